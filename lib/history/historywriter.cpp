#include "history/historywriter.h"

#include <QDateTime>
#include <QSqlError>
#include <QSqlQuery>
#include <QThread>
#include <QTimer>
#include <QVariant>

#include <algorithm>
#include <cmath>

namespace jumo {

namespace {

constexpr qint64 minuteMs = 60000;
// Rows per INSERT: well inside SQLite's and PostgreSQL's limits of bound values.
constexpr int rowsPerStatement = 200;
// Minutes rolled up in one transaction, so a long backlog never holds the writer for long.
constexpr qint64 minutesPerPass = 60;
constexpr qint64 thinIntervalMs = 3600 * 1000;

qint64 now()
{
    return QDateTime::currentMSecsSinceEpoch();
}

QVariant nullable(double value)
{
    return std::isnan(value) ? QVariant(QMetaType::fromType<double>()) : QVariant(value);
}

QVariant nullableText(const QString &text)
{
    return text.isNull() ? QVariant(QMetaType::fromType<QString>()) : QVariant(text);
}

// An empty text, never NULL: a null QString binds as NULL, which the NOT NULL columns refuse.
QString notNull(const QString &text)
{
    return text.isNull() ? QStringLiteral("") : text;
}

QString metaName(const char *what, const QString &station)
{
    return QLatin1String(what) + QLatin1Char(':') + station;
}

} // namespace

HistoryWriter::HistoryWriter(const HistoryLocation &location, const QString &station, const HistorySettings &settings)
    : m_db(location), m_station(station), m_settings(settings), m_rollup(settings.maxHoldMs())
{
}

HistoryWriter::~HistoryWriter() = default;

void HistoryWriter::start()
{
    m_maintenance = new QTimer(this);
    m_maintenance->setInterval(m_settings.maintenanceIntervalMs);
    connect(m_maintenance, &QTimer::timeout, this, &HistoryWriter::maintain);
    m_retry = new QTimer(this);
    m_retry->setSingleShot(true);
    m_retry->setInterval(m_settings.retryIntervalMs);
    connect(m_retry, &QTimer::timeout, this, &HistoryWriter::retry);

    QString error;
    if (!m_db.open(true, &error) || !markCrash(&error)
        || !m_db.setMeta(metaName("heartbeat", m_station), QString::number(m_settings.heartbeatMs), &error)) {
        m_db.close();   // the retry opens it again and marks the crash first
        fail(error, now());
        return;
    }
    m_maintenance->start();
}

void HistoryWriter::addSeries(int handle, const HistorySeriesInfo &info)
{
    m_infos.insert(handle, info);
}

void HistoryWriter::write(const QList<HistorySample> &samples)
{
    if (samples.isEmpty())
        return;
    if (m_failed) {
        m_lost += samples.size();
        return;
    }
    QString error;
    if (!writeBatch(samples, &error)) {
        m_lost += samples.size();
        fail(error, samples.first().timeMs);
        return;
    }
    emit written(int(samples.size()));
}

bool HistoryWriter::writeBatch(const QList<HistorySample> &samples, QString *error)
{
    QSqlDatabase &db = m_db.database();
    if (!db.transaction()) {
        *error = m_db.failure(tr("write"), db.lastError());
        return false;
    }
    QList<int> created;
    if (!resolveIds(samples, &created, error) || !insertRaw(samples, error) || !db.commit()) {
        if (error->isEmpty())
            *error = m_db.failure(tr("write"), db.lastError());
        db.rollback();
        // Ids handed out in the failed transaction do not exist.
        for (int handle : std::as_const(created))
            m_ids.remove(handle);
        return false;
    }
    for (const HistorySample &s : samples)
        m_last.insert(s.series, Last{s.timeMs, s.state});
    return true;
}

bool HistoryWriter::resolveIds(const QList<HistorySample> &samples, QList<int> *created, QString *error)
{
    for (const HistorySample &s : samples) {
        if (m_ids.contains(s.series))
            continue;
        const auto info = m_infos.constFind(s.series);
        if (info == m_infos.cend())
            continue;   // never named: dropped by insertRaw
        QSqlQuery insert = m_db.query();
        insert.prepare(QStringLiteral("INSERT INTO history_series (station, line, device, entry, is_number, unit) "
                                      "VALUES (?, ?, ?, ?, ?, ?) ON CONFLICT (station, line, device, entry) "
                                      "DO UPDATE SET is_number = excluded.is_number, unit = excluded.unit"));
        insert.addBindValue(notNull(info->key.station));
        insert.addBindValue(notNull(info->key.line));
        insert.addBindValue(notNull(info->key.device));
        insert.addBindValue(notNull(info->entry));
        insert.addBindValue(info->numeric ? 1 : 0);
        insert.addBindValue(notNull(info->unit));
        QSqlQuery select = m_db.query();
        select.prepare(QStringLiteral("SELECT id FROM history_series WHERE station = ? AND line = ? AND device = ? "
                                      "AND entry = ?"));
        select.addBindValue(notNull(info->key.station));
        select.addBindValue(notNull(info->key.line));
        select.addBindValue(notNull(info->key.device));
        select.addBindValue(notNull(info->entry));
        if (!insert.exec() || !select.exec() || !select.next()) {
            *error = m_db.failure(tr("write"), insert.lastError().isValid() ? insert.lastError() : select.lastError());
            return false;
        }
        m_ids.insert(s.series, select.value(0).toLongLong());
        created->append(s.series);
    }
    return true;
}

bool HistoryWriter::insertRaw(const QList<HistorySample> &samples, QString *error)
{
    QList<const HistorySample *> rows;
    rows.reserve(samples.size());
    for (const HistorySample &s : samples) {
        if (m_ids.contains(s.series))
            rows.append(&s);
    }
    QString fullSql;
    for (qsizetype first = 0; first < rows.size(); first += rowsPerStatement) {
        const int count = int(std::min<qsizetype>(rowsPerStatement, rows.size() - first));
        QSqlQuery q = m_db.query();
        if (count == rowsPerStatement) {
            if (fullSql.isEmpty())
                fullSql = HistoryDatabase::upsertRaw(rowsPerStatement);
            q.prepare(fullSql);
        } else {
            q.prepare(HistoryDatabase::upsertRaw(count));
        }
        for (int k = 0; k < count; ++k) {
            const HistorySample &s = *rows[first + k];
            q.addBindValue(m_ids.value(s.series));
            q.addBindValue(s.timeMs);
            q.addBindValue(int(s.state));
            q.addBindValue(nullable(s.value));
            q.addBindValue(nullableText(s.text));
        }
        if (!q.exec()) {
            *error = m_db.failure(tr("write"), q.lastError());
            return false;
        }
    }
    return true;
}

bool HistoryWriter::markCrash(QString *error)
{
    // The last sample of every series of this station; where it has a value, the recorder
    // ended without saying so: nobody recorded from a heartbeat after it (or from now).
    QSqlQuery q = m_db.query();
    q.prepare(QStringLiteral("SELECT r.series, r.t, r.state FROM history_raw r JOIN "
                             "(SELECT series, MAX(t) AS t FROM history_raw WHERE series IN "
                             "(SELECT id FROM history_series WHERE station = ?) GROUP BY series) l "
                             "ON r.series = l.series AND r.t = l.t"));
    q.addBindValue(m_station);
    if (!q.exec()) {
        *error = m_db.failure(tr("read"), q.lastError());
        return false;
    }
    const qint64 at = now();
    QList<std::pair<qint64, qint64>> open;
    while (q.next()) {
        const auto state = sampleStateFromNumber(q.value(2).toInt());
        if (state && !isGap(*state))
            open.append({q.value(0).toLongLong(), q.value(1).toLongLong()});
    }
    if (open.isEmpty())
        return true;
    QSqlDatabase &db = m_db.database();
    db.transaction();
    for (const auto &[series, lastMs] : std::as_const(open)) {
        QSqlQuery mark = m_db.query();
        mark.prepare(HistoryDatabase::upsertRaw(1));
        mark.addBindValue(series);
        mark.addBindValue(std::max(lastMs + 1, std::min(at, lastMs + m_settings.heartbeatMs)));
        mark.addBindValue(int(SampleState::NotRecorded));
        mark.addBindValue(QVariant(QMetaType::fromType<double>()));
        mark.addBindValue(QVariant(QMetaType::fromType<QString>()));
        if (!mark.exec()) {
            *error = m_db.failure(tr("write"), mark.lastError());
            db.rollback();
            return false;
        }
    }
    if (!db.commit()) {
        *error = m_db.failure(tr("write"), db.lastError());
        db.rollback();
        return false;
    }
    return true;
}

bool HistoryWriter::markStop(qint64 timeMs, QString *error)
{
    QList<HistorySample> marks;
    for (auto it = m_last.cbegin(); it != m_last.cend(); ++it) {
        if (isGap(it->state))
            continue;
        HistorySample s;
        s.series = it.key();
        s.timeMs = std::max(timeMs, it->timeMs + 1);
        s.state = SampleState::NotRecorded;
        marks.append(s);
    }
    return marks.isEmpty() || writeBatch(marks, error);
}

void HistoryWriter::maintain()
{
    if (m_failed || !m_db.isOpen())
        return;
    QString error;
    bool more = true;
    while (more) {
        if (!rollUp(&more, &error)) {
            fail(error, now());
            return;
        }
    }
    if (now() - m_thinnedMs >= thinIntervalMs) {
        if (!thin(&error)) {
            fail(error, now());
            return;
        }
        m_thinnedMs = now();
    }
    QString ignored;
    emit maintained(rolledMs(&ignored));
}

qint64 HistoryWriter::rolledMs(QString *error)
{
    const std::optional<QString> rolled = m_db.meta(metaName("rolled", m_station), error);
    return rolled && !rolled->isEmpty() ? rolled->toLongLong() : -1;
}

bool HistoryWriter::rollUp(bool *more, QString *error)
{
    *more = false;
    const qint64 untilMs = (now() - 2 * minuteMs) / minuteMs * minuteMs;
    qint64 fromMs = rolledMs(error);
    if (!error->isEmpty())
        return false;
    if (fromMs < 0) {
        // The first pass: from the first minute anything was recorded.
        QSqlQuery first = m_db.query();
        first.prepare(QStringLiteral("SELECT MIN(t) FROM history_raw WHERE series IN "
                                     "(SELECT id FROM history_series WHERE station = ?)"));
        first.addBindValue(m_station);
        if (!first.exec() || !first.next()) {
            *error = m_db.failure(tr("read"), first.lastError());
            return false;
        }
        if (first.value(0).isNull())
            return true;
        fromMs = first.value(0).toLongLong() / minuteMs * minuteMs;
    }
    if (fromMs >= untilMs)
        return true;
    const qint64 toMs = std::min(untilMs, fromMs + minutesPerPass * minuteMs);
    *more = toMs < untilMs;

    QSqlQuery q = m_db.query();
    q.prepare(QStringLiteral("SELECT series, t, state, value, text_value FROM history_raw WHERE series IN "
                             "(SELECT id FROM history_series WHERE station = ?) AND t >= ? AND t < ? "
                             "ORDER BY series, t"));
    q.addBindValue(m_station);
    q.addBindValue(fromMs);
    q.addBindValue(toMs);
    if (!q.exec()) {
        *error = m_db.failure(tr("read"), q.lastError());
        return false;
    }
    QList<MinuteRollup::Sample> samples;
    while (q.next()) {
        MinuteRollup::Sample s;
        s.series = q.value(0).toLongLong();
        s.timeMs = q.value(1).toLongLong();
        s.state = sampleStateFromNumber(q.value(2).toInt()).value_or(SampleState::NotRecorded);
        s.value = q.value(3).isNull() ? qQNaN() : q.value(3).toDouble();
        s.text = q.value(4).toString();
        samples.append(s);
    }
    const QList<MinuteRollup::Row> rows = m_rollup.roll(samples, toMs);

    QSqlDatabase &db = m_db.database();
    if (!db.transaction()) {
        *error = m_db.failure(tr("write"), db.lastError());
        return false;
    }
    bool ok = true;
    for (qsizetype first = 0; ok && first < rows.size(); first += rowsPerStatement) {
        const int count = int(std::min<qsizetype>(rowsPerStatement, rows.size() - first));
        QSqlQuery insert = m_db.query();
        insert.prepare(HistoryDatabase::upsertMinute(count));
        for (int k = 0; k < count; ++k) {
            const MinuteRollup::Row &row = rows[first + k];
            insert.addBindValue(row.series);
            insert.addBindValue(row.point.timeMs);
            insert.addBindValue(int(row.point.state));
            insert.addBindValue(nullable(row.point.value));
            insert.addBindValue(nullable(row.point.minimum));
            insert.addBindValue(nullable(row.point.maximum));
            insert.addBindValue(nullable(row.point.mean));
            insert.addBindValue(nullableText(row.point.text.isEmpty() ? QString() : row.point.text));
        }
        ok = insert.exec();
        if (!ok)
            *error = m_db.failure(tr("write"), insert.lastError());
    }
    ok = ok && m_db.setMeta(metaName("rolled", m_station), QString::number(toMs), error);
    if (ok && !db.commit()) {
        *error = m_db.failure(tr("write"), db.lastError());
        ok = false;
    }
    if (!ok) {
        db.rollback();
        return false;
    }
    m_rollup.accept();
    return true;
}

bool HistoryWriter::thin(QString *error)
{
    QString why;
    const qint64 rolled = rolledMs(&why);
    if (!why.isEmpty()) {
        *error = why;
        return false;
    }
    // Raw samples go only once their minutes are rolled up.
    const qint64 rawCut = std::min(now() - m_settings.rawRetentionMs, std::max<qint64>(0, rolled));
    const qint64 minuteCut = now() - m_settings.minuteRetentionMs;
    QSqlDatabase &db = m_db.database();
    if (!db.transaction()) {
        *error = m_db.failure(tr("write"), db.lastError());
        return false;
    }
    const QString ofStation = QStringLiteral(" AND series IN (SELECT id FROM history_series WHERE station = ?)");
    QSqlQuery raw = m_db.query();
    raw.prepare(QStringLiteral("DELETE FROM history_raw WHERE t < ?") + ofStation);
    raw.addBindValue(rawCut);
    raw.addBindValue(m_station);
    QSqlQuery minute = m_db.query();
    minute.prepare(QStringLiteral("DELETE FROM history_minute WHERE t < ?") + ofStation);
    minute.addBindValue(minuteCut);
    minute.addBindValue(m_station);
    bool ok = raw.exec();
    if (!ok)
        *error = m_db.failure(tr("write"), raw.lastError());
    ok = ok && minute.exec();
    if (!ok && error->isEmpty())
        *error = m_db.failure(tr("write"), minute.lastError());
    if (ok && rawCut > 0)
        ok = m_db.setMeta(metaName("raw_from", m_station), QString::number(rawCut), error);
    if (ok && !db.commit()) {
        *error = m_db.failure(tr("write"), db.lastError());
        ok = false;
    }
    if (!ok)
        db.rollback();
    return ok;
}

void HistoryWriter::fail(const QString &reason, qint64 sinceMs)
{
    if (!m_failed) {
        m_failed = true;
        m_failedSinceMs = sinceMs;
        emit failed(tr("History not recorded: %1").arg(reason));
    }
    if (m_maintenance)
        m_maintenance->stop();
    if (m_retry)
        m_retry->start();
}

void HistoryWriter::retry()
{
    QString error;
    if (!m_db.isOpen()) {
        if (!m_db.open(true, &error) || !markCrash(&error)) {
            m_retry->start();
            return;
        }
    }
    // What was not written is a time nobody recorded, from the first sample lost.
    if (!markStop(m_failedSinceMs, &error)) {
        m_retry->start();
        return;
    }
    m_failed = false;
    const qint64 lost = m_lost;
    m_lost = 0;
    m_maintenance->start();
    emit resumed(tr("History recorded again (%n sample(s) since the failure not recorded)", nullptr, int(lost)));
}

void HistoryWriter::finish()
{
    if (m_maintenance)
        m_maintenance->stop();
    if (m_retry)
        m_retry->stop();
    if (!m_failed && m_db.isOpen()) {
        QString error;
        if (!markStop(now(), &error))
            emit failed(tr("History not recorded: %1").arg(error));
    }
    m_db.close();
    QThread::currentThread()->quit();
}

} // namespace jumo
