#include "history/minuterollup.h"

#include <QSet>

#include <algorithm>
#include <cmath>

namespace jumo {

namespace {

constexpr qint64 minuteMs = 60000;

qint64 minuteOf(qint64 t)
{
    return t - (((t % minuteMs) + minuteMs) % minuteMs);
}

bool sameNumber(double a, double b)
{
    return a == b || (std::isnan(a) && std::isnan(b));
}

} // namespace

QList<MinuteRollup::Row> MinuteRollup::roll(const QList<Sample> &samples, qint64 toMs)
{
    m_pending = m_held;
    QList<Row> rows;
    QSet<qint64> seen;
    for (qsizetype i = 0; i < samples.size();) {
        qsizetype j = i;
        while (j < samples.size() && samples[j].series == samples[i].series)
            ++j;
        rollSeries(samples[i].series, samples.constData() + i, samples.constData() + j, toMs, rows);
        seen.insert(samples[i].series);
        i = j;
    }
    // Series that said nothing in this pass: perhaps nobody records them any more.
    const QList<qint64> quiet = m_pending.keys();
    for (qint64 series : quiet) {
        if (!seen.contains(series))
            rollSeries(series, nullptr, nullptr, toMs, rows);
    }
    return rows;
}

void MinuteRollup::accept()
{
    m_held = std::move(m_pending);
    m_pending.clear();
}

void MinuteRollup::rollSeries(qint64 series, const Sample *first, const Sample *end, qint64 toMs, QList<Row> &rows)
{
    const auto found = m_pending.constFind(series);
    bool known = found != m_pending.cend();
    Held held = known ? *found : Held{};
    Run run;

    auto cap = [&](qint64 untilMs) {
        if (!known || isGap(held.state) || untilMs - held.timeMs <= m_maxHoldMs)
            return;
        const qint64 capMs = held.timeMs + m_maxHoldMs;
        if (run.open)
            closeRun(run, std::min(capMs, run.minute + minuteMs), series, rows);
        Row gap;
        gap.series = series;
        gap.point.timeMs = capMs;
        gap.point.state = SampleState::NotRecorded;
        rows.append(gap);
        held = Held{capMs, SampleState::NotRecorded, qQNaN(), QString()};
    };
    auto extend = [&run](const Sample &s) {
        if (!std::isnan(run.last))
            run.weighted += run.last * double(s.timeMs - run.lastMs);
        run.lastMs = s.timeMs;
        run.last = s.value;
        if (!std::isnan(s.value)) {
            run.minimum = std::isnan(run.minimum) ? s.value : std::min(run.minimum, s.value);
            run.maximum = std::isnan(run.maximum) ? s.value : std::max(run.maximum, s.value);
        }
        run.text = s.text;
    };

    for (const Sample *s = first; s != end; ++s) {
        if (run.open && minuteOf(s->timeMs) != run.minute)
            closeRun(run, run.minute + minuteMs, series, rows);
        cap(s->timeMs);
        if (known && held.state == s->state && sameNumber(held.value, s->value) && held.text == s->text) {
            // The same again: it only says the value still held then.
            held.timeMs = s->timeMs;
            if (run.open)
                extend(*s);
            continue;
        }
        if (run.open && run.state != s->state)
            closeRun(run, s->timeMs, series, rows);
        if (run.open) {
            extend(*s);
        } else {
            run = Run{};
            run.open = true;
            run.startMs = s->timeMs;
            run.minute = minuteOf(s->timeMs);
            run.state = s->state;
            run.lastMs = s->timeMs;
            run.last = s->value;
            run.minimum = s->value;
            run.maximum = s->value;
            run.text = s->text;
        }
        held = Held{s->timeMs, s->state, s->value, s->text};
        known = true;
    }
    cap(toMs);
    if (run.open)
        closeRun(run, std::min(run.minute + minuteMs, toMs), series, rows);
    if (known)
        m_pending.insert(series, held);
}

void MinuteRollup::closeRun(Run &run, qint64 endMs, qint64 series, QList<Row> &rows)
{
    const qint64 endTime = std::max(endMs, run.lastMs);
    if (!std::isnan(run.last))
        run.weighted += run.last * double(endTime - run.lastMs);
    Row row;
    row.series = series;
    row.point.timeMs = run.startMs;
    row.point.state = run.state;
    row.point.value = run.last;
    row.point.minimum = run.minimum;
    row.point.maximum = run.maximum;
    const qint64 duration = endTime - run.startMs;
    row.point.mean = std::isnan(run.minimum) ? qQNaN() : duration > 0 ? run.weighted / double(duration) : run.last;
    row.point.text = run.text;
    rows.append(row);
    run.open = false;
}

} // namespace jumo
