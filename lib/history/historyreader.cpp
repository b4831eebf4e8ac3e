#include "history/historyreader.h"

#include "history/tracebuilder.h"

#include <QDateTime>
#include <QSqlError>
#include <QSqlQuery>
#include <QVariant>

#include <algorithm>

namespace jumo {

namespace {

double number(const QVariant &v)
{
    return v.isNull() ? qQNaN() : v.toDouble();
}

// The columns every range and look-back reads, in this order.
QString columns(bool minute)
{
    return minute ? QStringLiteral("t, state, value, text_value, minimum, maximum, mean")
                  : QStringLiteral("t, state, value, text_value");
}

// next() is false at the end and when a page could not be read (a damaged file, a
// server gone): only the error tells them apart.
bool failedReading(const QSqlQuery &q)
{
    return q.lastError().isValid();
}

HistoryPoint pointOf(const QSqlQuery &q, bool minute)
{
    HistoryPoint p;
    p.timeMs = q.value(0).toLongLong();
    p.state = sampleStateFromStored(q.value(1));
    p.value = number(q.value(2));
    p.text = q.value(3).toString();
    if (minute) {
        p.minimum = number(q.value(4));
        p.maximum = number(q.value(5));
        p.mean = number(q.value(6));
    } else {
        p.minimum = p.maximum = p.mean = p.value;
    }
    return p;
}

} // namespace

HistoryReader::HistoryReader(const HistoryLocation &location, HistoryDatabase::ReadAccess access)
    : m_db(location, access)
{
}

bool HistoryReader::open(QString *error)
{
    m_ids.clear();
    return m_db.open(false, error);
}

std::optional<QList<HistorySeriesInfo>> HistoryReader::series(const QString &station, QString *error)
{
    QSqlQuery q = m_db.query();
    const bool prepared = q.prepare(
            QStringLiteral("SELECT station, line, device, entry, is_number, unit FROM history_series %1"
                           "ORDER BY station, line, device, entry")
                    .arg(station.isEmpty() ? QString() : QStringLiteral("WHERE station = ? ")));
    if (!station.isEmpty())
        q.addBindValue(station);
    // A failed prepare says why; exec after it would only say "No query".
    if (!prepared || !q.exec()) {
        if (error)
            *error = m_db.failure(tr("read"), q.lastError());
        return std::nullopt;
    }
    QList<HistorySeriesInfo> out;
    while (q.next()) {
        HistorySeriesInfo info;
        info.key = {q.value(0).toString(), q.value(1).toString(), q.value(2).toString()};
        info.entry = q.value(3).toString();
        info.numeric = q.value(4).toInt() != 0;
        info.unit = q.value(5).toString();
        out.append(info);
    }
    if (failedReading(q)) {
        if (error)
            *error = m_db.failure(tr("read"), q.lastError());
        return std::nullopt;
    }
    return out;
}

std::optional<qint64> HistoryReader::seriesId(const HistoryKey &key, const QString &entry, QString *error)
{
    const QString name = key.name() + QLatin1Char('/') + entry;
    if (const auto known = m_ids.constFind(name); known != m_ids.cend())
        return *known;
    QSqlQuery q = m_db.query();
    const bool prepared = q.prepare(
            QStringLiteral("SELECT id FROM history_series WHERE station = ? AND line = ? AND device = ? AND entry = ?"));
    q.addBindValue(key.station);
    q.addBindValue(key.line);
    q.addBindValue(key.device);
    q.addBindValue(entry);
    if (!prepared || !q.exec()) {
        if (error)
            *error = m_db.failure(tr("read"), q.lastError());
        return std::nullopt;
    }
    if (!q.next()) {
        if (failedReading(q)) {
            if (error)
                *error = m_db.failure(tr("read"), q.lastError());
            return std::nullopt;
        }
        return qint64(-1);   // never recorded (not remembered: it may be soon)
    }
    const qint64 id = q.value(0).toLongLong();
    m_ids.insert(name, id);
    return id;
}

std::optional<HistoryReader::StationFacts> HistoryReader::stationFacts(const QString &station, QString *error)
{
    QSqlQuery q = m_db.query();
    const bool prepared = q.prepare(QStringLiteral("SELECT name, value FROM history_meta WHERE name IN (?, ?, ?)"));
    q.addBindValue(QStringLiteral("raw_from:") + station);
    q.addBindValue(QStringLiteral("rolled:") + station);
    q.addBindValue(QStringLiteral("heartbeat:") + station);
    if (!prepared || !q.exec()) {
        if (error)
            *error = m_db.failure(tr("read"), q.lastError());
        return std::nullopt;
    }
    StationFacts facts;
    HistorySettings settings;
    while (q.next()) {
        const QString name = q.value(0).toString();
        const qint64 value = q.value(1).toLongLong();
        if (name.startsWith(QLatin1String("raw_from:")))
            facts.rawFromMs = value;
        else if (name.startsWith(QLatin1String("rolled:")))
            facts.rolledMs = value;
        else if (value > 0)
            settings.heartbeatMs = value;
    }
    if (failedReading(q)) {
        if (error)
            *error = m_db.failure(tr("read"), q.lastError());
        return std::nullopt;
    }
    facts.maxHoldMs = settings.maxHoldMs();
    return facts;
}

bool HistoryReader::readRange(bool minute, qint64 id, qint64 fromMs, qint64 toMs,
                              const std::function<void(const HistoryPoint &)> &sink, QString *error)
{
    if (toMs <= fromMs)
        return true;
    QSqlQuery q = m_db.query();
    const bool prepared = q.prepare(
            QStringLiteral("SELECT %1 FROM %2 WHERE series = ? AND t >= ? AND t < ? ORDER BY t")
                    .arg(columns(minute), minute ? QStringLiteral("history_minute") : QStringLiteral("history_raw")));
    q.addBindValue(id);
    q.addBindValue(fromMs);
    q.addBindValue(toMs);
    if (!prepared || !q.exec()) {
        if (error)
            *error = m_db.failure(tr("read"), q.lastError());
        return false;
    }
    while (q.next())
        sink(pointOf(q, minute));
    if (failedReading(q)) {
        if (error)
            *error = m_db.failure(tr("read"), q.lastError());
        return false;
    }
    return true;
}

std::optional<HistoryPoint> HistoryReader::lastBefore(bool minute, qint64 id, qint64 timeMs, QString *error)
{
    QSqlQuery q = m_db.query();
    const bool prepared = q.prepare(
            QStringLiteral("SELECT %1 FROM %2 WHERE series = ? AND t < ? ORDER BY t DESC LIMIT 1")
                    .arg(columns(minute), minute ? QStringLiteral("history_minute") : QStringLiteral("history_raw")));
    q.addBindValue(id);
    q.addBindValue(timeMs);
    if (!prepared || !q.exec()) {
        if (error)
            *error = m_db.failure(tr("read"), q.lastError());
        return std::nullopt;
    }
    if (!q.next()) {
        if (failedReading(q)) {
            if (error)
                *error = m_db.failure(tr("read"), q.lastError());
            return std::nullopt;
        }
        HistoryPoint none;
        none.timeMs = -1;
        return none;
    }
    return pointOf(q, minute);
}

HistoryTrace HistoryReader::samples(const HistoryKey &key, const QString &entry, qint64 fromMs, qint64 toMs,
                                    int maxPoints)
{
    return samples(HistoryQuery{key, entry, fromMs, toMs, maxPoints});
}

HistoryTrace HistoryReader::samples(const HistoryQuery &query)
{
    HistoryTrace trace;
    trace.query = query;
    trace.query.maxPoints = std::clamp(query.maxPoints, 2, 100000);
    trace.endMs = std::max(query.fromMs, std::min(query.toMs, QDateTime::currentMSecsSinceEpoch()));
    if (!m_db.isOpen() && !open(&trace.error))
        return trace;
    const std::optional<qint64> id = seriesId(query.key, query.entry, &trace.error);
    if (!id || *id < 0 || query.toMs <= query.fromMs)
        return trace;
    const std::optional<StationFacts> facts = stationFacts(query.key.station, &trace.error);
    if (!facts)
        return trace;

    const qint64 span = query.toMs - query.fromMs;
    const bool raw = query.fromMs >= facts->rawFromMs && span <= qint64(trace.query.maxPoints) * 60000;
    trace.resolution = raw ? HistoryTrace::Resolution::Raw : HistoryTrace::Resolution::Minute;

    QList<TraceBuilder::Step> steps;
    // What held at the start: the later of the last raw sample and the last minute row
    // before it (raw samples of a long gap may be thinned out; its minute row is kept).
    const std::optional<HistoryPoint> heldRaw = lastBefore(false, *id, query.fromMs, &trace.error);
    const std::optional<HistoryPoint> heldMinute = heldRaw ? lastBefore(true, *id, query.fromMs, &trace.error)
                                                           : std::nullopt;
    if (!heldRaw || !heldMinute)
        return trace;
    if (heldRaw->timeMs >= 0 && heldRaw->timeMs >= heldMinute->timeMs)
        steps.append({*heldRaw, true});
    else if (heldMinute->timeMs >= 0)
        steps.append({*heldMinute, false});

    bool ok = true;
    if (raw) {
        ok = readRange(false, *id, query.fromMs, query.toMs, [&](const HistoryPoint &p) { steps.append({p, true}); },
                       &trace.error);
    } else {
        const qint64 split = std::clamp(facts->rolledMs, query.fromMs, query.toMs);
        ok = readRange(true, *id, query.fromMs, split, [&](const HistoryPoint &p) { steps.append({p, false}); },
                       &trace.error)
                && readRange(false, *id, split, query.toMs, [&](const HistoryPoint &p) { steps.append({p, true}); },
                             &trace.error);
    }
    if (!ok)
        return trace;
    trace.points = TraceBuilder::build(steps, query.fromMs, trace.endMs, facts->maxHoldMs, trace.query.maxPoints,
                                       &trace.bucketMs);
    return trace;
}

bool HistoryReader::records(const HistoryKey &key, const QString &entry, qint64 fromMs, qint64 toMs,
                            const std::function<bool(const HistoryRecord &)> &sink, QString *error)
{
    if (!m_db.isOpen() && !open(error))
        return false;
    const std::optional<qint64> id = seriesId(key, entry, error);
    if (!id)
        return false;
    if (*id < 0)
        return true;
    const std::optional<StationFacts> facts = stationFacts(key.station, error);
    if (!facts)
        return false;
    // Where raw samples are thinned out, the one-minute rows; raw ones from there on.
    const qint64 split = std::clamp(facts->rawFromMs, fromMs, std::max(fromMs, toMs));
    bool going = true;
    auto pass = [&](bool minute) {
        return [&, minute](const HistoryPoint &p) {
            if (going)
                going = sink(HistoryRecord{entry, p, minute});
        };
    };
    return readRange(true, *id, fromMs, split, pass(true), error)
            && (!going || readRange(false, *id, split, toMs, pass(false), error));
}

} // namespace jumo
