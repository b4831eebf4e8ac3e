#include "history/tracebuilder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace jumo {

namespace {

constexpr qint64 minuteMs = 60000;

struct Flat
{
    HistoryPoint point;
    // Up to here the point's minimum, maximum and mean describe it; after, its value holds.
    qint64 spanEndMs = 0;
    bool raw = true;
};

bool sameNumber(double a, double b)
{
    return a == b || (std::isnan(a) && std::isnan(b));
}

bool sameState(const HistoryPoint &a, const HistoryPoint &b)
{
    return a.state == b.state && sameNumber(a.value, b.value) && a.text == b.text;
}

HistoryPoint notRecorded(qint64 timeMs)
{
    HistoryPoint p;
    p.timeMs = timeMs;
    p.state = SampleState::NotRecorded;
    return p;
}

double lesser(double a, double b)
{
    return std::isnan(a) ? b : std::isnan(b) ? a : std::min(a, b);
}

double greater(double a, double b)
{
    return std::isnan(a) ? b : std::isnan(b) ? a : std::max(a, b);
}

class Buckets
{
public:
    Buckets(const QList<Flat> &flat, qint64 endMs) : m_flat(flat), m_endMs(endMs) { }

    // The points of flat[first, last), all inside one bucket that ends at bucketEndMs.
    void add(qsizetype first, qsizetype last, qint64 bucketEndMs, QList<HistoryPoint> &out) const
    {
        if (last - first == 1) {
            out.append(m_flat[first].point);
            return;
        }
        QList<std::pair<qsizetype, qsizetype>> runs;
        for (qsizetype k = first; k < last; ++k) {
            if (runs.isEmpty() || valued(runs.last().first) != valued(k))
                runs.append({k, k + 1});
            else
                runs.last().second = k + 1;
        }
        if (runs.size() == 1) {
            out.append(join(first, last, valued(first), bucketEndMs));
            return;
        }
        const HistoryPoint withValue = join(first, last, true, bucketEndMs);
        const HistoryPoint without = join(first, last, false, bucketEndMs);
        const bool valueFirst = withValue.timeMs < without.timeMs;
        out.append(valueFirst ? withValue : without);
        out.append(valueFirst ? without : withValue);
        // What holds after the bucket is how it ends.
        const auto [endRunFirst, endRunLast] = runs.last();
        if (valued(endRunFirst) == valueFirst)
            out.append(join(endRunFirst, endRunLast, valueFirst, bucketEndMs));
    }

private:
    bool valued(qsizetype k) const { return hasValue(m_flat[k].point.state); }
    qint64 nextMs(qsizetype k) const { return k + 1 < m_flat.size() ? m_flat[k + 1].point.timeMs : m_endMs; }

    // The points of [first, last) with (or without) a value as one point.
    HistoryPoint join(qsizetype first, qsizetype last, bool withValue, qint64 bucketEndMs) const
    {
        HistoryPoint joined;
        bool any = false;
        bool stale = false;
        double sum = 0;
        double total = 0;
        for (qsizetype k = first; k < last; ++k) {
            const HistoryPoint &p = m_flat[k].point;
            if (valued(k) != withValue)
                continue;
            if (!any)
                joined.timeMs = p.timeMs;
            any = true;
            stale = stale || p.state == SampleState::Stale;
            joined.state = p.state;
            joined.value = p.value;
            joined.text = p.text;
            if (!withValue)
                continue;
            joined.minimum = lesser(joined.minimum, p.minimum);
            joined.maximum = greater(joined.maximum, p.maximum);
            const qint64 start = p.timeMs;
            const qint64 stop = std::max(start, std::min(nextMs(k), bucketEndMs));
            const qint64 spanEnd = std::clamp(m_flat[k].spanEndMs, start, stop);
            if (!std::isnan(p.mean)) {
                sum += p.mean * double(spanEnd - start);
                total += double(spanEnd - start);
            }
            if (!std::isnan(p.value)) {
                sum += p.value * double(stop - spanEnd);
                total += double(stop - spanEnd);
            }
        }
        if (withValue) {
            joined.state = stale ? SampleState::Stale : SampleState::Ok;
            joined.mean = total > 0 ? sum / total : joined.value;
        }
        return joined;
    }

    const QList<Flat> &m_flat;
    qint64 m_endMs;
};

} // namespace

QList<HistoryPoint> TraceBuilder::build(const QList<Step> &steps, qint64 fromMs, qint64 endMs, qint64 maxHoldMs,
                                        int maxPoints, qint64 *bucketMs)
{
    if (bucketMs)
        *bucketMs = 0;
    QList<Flat> flat;
    auto push = [&](const HistoryPoint &p, qint64 spanEndMs, bool raw) {
        if (p.timeMs >= endMs)
            return;
        if (!flat.isEmpty()) {
            Flat &last = flat.last();
            if (p.timeMs <= last.point.timeMs) {
                last = Flat{p, spanEndMs, raw};
                return;
            }
            // A raw sample that repeats the one before: the step goes on.
            if (raw && last.raw && sameState(last.point, p))
                return;
        }
        flat.append(Flat{p, spanEndMs, raw});
    };
    for (qsizetype i = 0; i < steps.size(); ++i) {
        const Step &s = steps[i];
        const qint64 nextMs = i + 1 < steps.size() ? steps[i + 1].point.timeMs : endMs;
        if (nextMs <= fromMs && i + 1 < steps.size())
            continue;   // a later step is what held at fromMs
        // A raw value is repeated every heartbeat; held far longer, nobody recorded it.
        qint64 capMs = std::numeric_limits<qint64>::max();
        if (s.raw && !isGap(s.point.state) && nextMs - s.point.timeMs > maxHoldMs)
            capMs = s.point.timeMs + maxHoldMs;
        HistoryPoint p = s.point;
        qint64 spanEndMs = s.raw ? p.timeMs : p.timeMs - (((p.timeMs % minuteMs) + minuteMs) % minuteMs) + minuteMs;
        if (p.timeMs < fromMs) {
            p.timeMs = fromMs;
            p.minimum = p.maximum = p.mean = p.value;
            spanEndMs = fromMs;
        }
        if (capMs <= p.timeMs) {
            push(notRecorded(p.timeMs), p.timeMs, true);
            continue;
        }
        push(p, spanEndMs, s.raw);
        if (capMs < nextMs)
            push(notRecorded(capMs), capMs, true);
    }

    QList<HistoryPoint> out;
    if (flat.size() <= std::max(1, maxPoints)) {
        out.reserve(flat.size());
        for (const Flat &f : std::as_const(flat))
            out.append(f.point);
        return out;
    }
    const qint64 span = std::max<qint64>(1, endMs - fromMs);
    const qint64 width = std::max<qint64>(1, (span + maxPoints - 1) / maxPoints);
    if (bucketMs)
        *bucketMs = width;
    const Buckets buckets(flat, endMs);
    for (qsizetype i = 0; i < flat.size();) {
        const qint64 bucketEndMs = fromMs + ((flat[i].point.timeMs - fromMs) / width + 1) * width;
        qsizetype j = i;
        while (j < flat.size() && flat[j].point.timeMs < bucketEndMs)
            ++j;
        buckets.add(i, j, bucketEndMs, out);
        i = j;
    }
    return out;
}

} // namespace jumo
