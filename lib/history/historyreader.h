// Reads a history on the calling thread, over a read-only connection of its own: the
// recorded series, a trend's steps of one entry (raw or one-minute rows, as the span
// needs), and every record of a range at the finest resolution kept (exports, jumoctl).
// Stores answer trends through it on a thread of their own; jumoctl and tests use it
// directly.
#pragma once

#include "history/historydatabase.h"
#include "history/historytypes.h"

#include <QCoreApplication>
#include <QHash>

#include <functional>
#include <optional>

namespace jumo {

// A sample as it was kept: raw, or a one-minute row where the raw ones are thinned out.
struct HistoryRecord
{
    QString entry;
    HistoryPoint point;
    bool minute = false;
};

class HistoryReader
{
    Q_DECLARE_TR_FUNCTIONS(jumo::HistoryReader)

public:
    explicit HistoryReader(const HistoryLocation &location,
                           HistoryDatabase::ReadAccess access = HistoryDatabase::ReadAccess::BesideWriter);

    bool open(QString *error);
    bool isOpen() const { return m_db.isOpen(); }
    const HistoryLocation &location() const { return m_db.location(); }
    // Why the last open or read failed.
    HistoryDatabase::Fault fault() const { return m_db.fault(); }

    // The series of one station (empty: of every station), by station, line, device, entry.
    std::optional<QList<HistorySeriesInfo>> series(const QString &station, QString *error);
    // The steps of one entry over [fromMs, toMs), at most about 3 * maxPoints of them:
    // raw samples when the span has room for a point per minute or more and raw samples
    // are still kept from fromMs, else the one-minute rows (and raw ones after the last
    // rolled-up minute). An entry never recorded gives no points and no error.
    HistoryTrace samples(const HistoryKey &key, const QString &entry, qint64 fromMs, qint64 toMs, int maxPoints);
    HistoryTrace samples(const HistoryQuery &query);
    // Every record of the entry in [fromMs, toMs), in time order, to sink (which returns
    // false to stop). False with the reason when the reading failed.
    bool records(const HistoryKey &key, const QString &entry, qint64 fromMs, qint64 toMs,
                 const std::function<bool(const HistoryRecord &)> &sink, QString *error);

private:
    struct StationFacts
    {
        qint64 rawFromMs = 0;     // raw samples are kept from here
        qint64 rolledMs = 0;      // one-minute rows exist up to here
        qint64 maxHoldMs = 0;
    };
    std::optional<qint64> seriesId(const HistoryKey &key, const QString &entry, QString *error);
    std::optional<StationFacts> stationFacts(const QString &station, QString *error);
    bool readRange(bool minute, qint64 id, qint64 fromMs, qint64 toMs,
                   const std::function<void(const HistoryPoint &)> &sink, QString *error);
    std::optional<HistoryPoint> lastBefore(bool minute, qint64 id, qint64 timeMs, QString *error);

    HistoryDatabase m_db;
    QHash<QString, qint64> m_ids;
};

} // namespace jumo
