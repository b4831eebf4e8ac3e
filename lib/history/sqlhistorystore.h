// A station's history in an SQL database (an SQLite file by default, or PostgreSQL):
// samples gathered on the caller's thread, written in batches by a HistoryWriter on a
// thread of its own, trends answered by a HistoryReader on another, so neither a slow
// disk nor a long query ever holds up the bus or a view.
#pragma once

#include "history/historylocation.h"
#include "history/historystore.h"

#include <QHash>
#include <QThread>
#include <QTimer>

namespace jumo {

class HistoryReader;
class HistoryWriter;

class SqlHistoryStore : public HistoryStore
{
    Q_OBJECT

public:
    SqlHistoryStore(const HistoryLocation &location, const QString &station, const HistorySettings &settings = {},
                    QObject *parent = nullptr);
    // Writes what is gathered, marks every series as no longer recorded, and waits for
    // the writer to finish.
    ~SqlHistoryStore() override;

    // Starts the writer thread (which opens or makes the store); a failure to open is
    // reported by recordingStopped, and the writer tries again.
    void start();
    const HistoryLocation &location() const { return m_location; }
    const HistorySettings &settings() const { return m_settings; }

    QString station() const override { return m_station; }
    int series(const HistorySeriesInfo &info) override;
    void record(const HistorySample &sample) override;
    bool isRecording() const override { return m_recording; }
    qint64 heartbeatMs() const override { return m_settings.heartbeatMs; }
    quint64 requestSamples(const HistoryQuery &query) override;

    // Hands what is gathered to the writer now (also done every batch interval).
    void flush();
    // Rolls up and thins now, not at the next maintenance interval (tests, benchmarks).
    void maintainNow();

signals:
    // A batch of this many samples is in the store.
    void written(int samples);
    // The one-minute rows reach up to rolledMs (-1: nothing recorded yet).
    void maintained(qint64 rolledMs);

private:
    void onFailed(const QString &message);
    void onResumed(const QString &message);

    HistoryLocation m_location;
    QString m_station;
    HistorySettings m_settings;
    QThread m_writerThread;
    QThread m_readerThread;
    HistoryWriter *m_writer = nullptr;
    QObject *m_readerContext = nullptr;
    std::shared_ptr<HistoryReader> m_reader;
    QTimer m_batchTimer;
    QHash<QString, int> m_handles;
    QHash<int, qint64> m_lastMs;
    QList<HistorySample> m_pending;
    bool m_recording = true;
    bool m_started = false;
    quint64 m_nextRequest = 1;
};

} // namespace jumo
