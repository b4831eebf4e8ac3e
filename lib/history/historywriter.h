// The worker that writes a station's history, on the store's writer thread: batches of
// samples in one transaction each, the marks of a crash found at the start, the
// one-minute rows and the thinning in the background, and on a failed write (a full
// disk, a server gone) a stop with the reason, then attempts until it can write again.
// Made and driven by SqlHistoryStore; every member function runs on the writer thread.
#pragma once

#include "history/historydatabase.h"
#include "history/historytypes.h"
#include "history/minuterollup.h"

#include <QHash>
#include <QObject>

class QTimer;

namespace jumo {

class HistoryWriter : public QObject
{
    Q_OBJECT

public:
    HistoryWriter(const HistoryLocation &location, const QString &station, const HistorySettings &settings);
    ~HistoryWriter() override;

    // Opens the store, ends what a crash left open as "not_recorded", starts maintenance.
    void start();
    void addSeries(int handle, const HistorySeriesInfo &info);
    void write(const QList<HistorySample> &samples);
    // The one-minute rows up to two minutes ago, and the thinning when it is due.
    void maintain();
    // Ends every series that is not in a gap as "not_recorded", closes, ends the thread.
    void finish();

signals:
    void failed(const QString &message);
    void resumed(const QString &message);
    void written(int samples);
    void maintained(qint64 rolledMs);

private:
    struct Last
    {
        qint64 timeMs = 0;
        SampleState state = SampleState::NotRecorded;
    };

    bool writeBatch(const QList<HistorySample> &samples, QString *error);
    bool resolveIds(const QList<HistorySample> &samples, QList<int> *created, QString *error);
    bool insertRaw(const QList<HistorySample> &samples, QString *error);
    // "not_recorded" for every series of the station whose last sample has a value.
    bool markCrash(QString *error);
    // "not_recorded" at the time given (or just after its last sample) for every series
    // this writer wrote that is not in a gap.
    bool markStop(qint64 timeMs, QString *error);
    bool rollUp(bool *more, QString *error);
    bool thin(QString *error);
    void fail(const QString &reason, qint64 sinceMs);
    void retry();
    qint64 rolledMs(QString *error);

    HistoryDatabase m_db;
    QString m_station;
    HistorySettings m_settings;
    MinuteRollup m_rollup;
    QHash<int, HistorySeriesInfo> m_infos;
    QHash<int, qint64> m_ids;
    QHash<int, Last> m_last;
    bool m_failed = false;
    qint64 m_failedSinceMs = 0;
    qint64 m_lost = 0;
    qint64 m_thinnedMs = 0;
    QTimer *m_maintenance = nullptr;
    QTimer *m_retry = nullptr;
};

} // namespace jumo
