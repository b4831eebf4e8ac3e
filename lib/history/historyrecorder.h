// Records every value a line's devices give, from the first poll, into a station's
// history: on a change beyond the entry's precision or of its state, again every
// heartbeat while it stays, and the start and end of every gap. Fed by DeviceSource,
// so the HMI's own lines and the publisher's station record the same way.
#pragma once

#include "bus/devicesource.h"
#include "history/historystore.h"

#include <QHash>
#include <QPointer>
#include <QTimer>

#include <functional>
#include <memory>
#include <vector>

namespace jumo {

class HistoryRecorder : public QObject
{
    Q_OBJECT

public:
    explicit HistoryRecorder(HistoryStore *store, QObject *parent = nullptr);
    ~HistoryRecorder() override;

    // Records the devices of one line of the station, named line in the history's keys.
    // The source must outlive the recorder or be removed first.
    void addSource(const DeviceSource *source, const QString &line);
    void removeSource(const DeviceSource *source);

    // The time of the samples, ms since the epoch (tests give their own clock).
    void setClock(std::function<qint64()> wallClockMs) { m_clock = std::move(wallClockMs); }
    int samplesRecorded() const { return m_recorded; }

    // The sample an entry's state gives (series not set).
    static HistorySample sampleOf(const RegisterEntry &entry, const EntryState &state);
    // Whether b differs from a enough to be kept: another state or text, or a number
    // that differs at the entry's precision (floats) or at all (integers).
    static bool differs(const RegisterEntry &entry, const HistorySample &a, const HistorySample &b);

private:
    struct Recorded
    {
        int series = -1;
        HistorySample last;
        bool valid = false;
    };
    struct Line
    {
        QPointer<const DeviceSource> source;
        QString line;
        QList<QMetaObject::Connection> connections;
        QHash<DeviceId, QHash<QString, Recorded>> recorded;
    };

    void recordEntries(Line &line, DeviceId id, const QStringList &entryIds, bool force);
    void recordAll(bool force);
    void heartbeat();
    qint64 now() const;

    HistoryStore *m_store;
    std::vector<std::unique_ptr<Line>> m_lines;
    QTimer m_heartbeat;
    std::function<qint64()> m_clock;
    int m_recorded = 0;
};

} // namespace jumo
