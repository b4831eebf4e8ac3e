// One RS-485 line with many devices, over QModbusRtuSerialClient. It schedules every
// request itself (one in flight, writes before polls, devices round-robin), derives
// timeouts from the families' timing, retries after a quiet gap, takes dead devices
// offline with back-off, refuses writes in read-only mode and survives a lost port.
#pragma once

#include "bus/bussettings.h"
#include "bus/devicestatistics.h"
#include "bus/entrystate.h"
#include "protocol/readplanner.h"
#include "protocol/registermap.h"
#include "bus/writeoutcome.h"

#include <QElapsedTimer>
#include <QHash>
#include <QMap>
#include <QModbusDevice>
#include <QObject>
#include <QPointer>
#include <QQueue>
#include <QTimer>

#include <memory>
#include <optional>

class QModbusReply;
class QModbusRtuSerialClient;

namespace jumo {

using DeviceId = int;

enum class LineState { Disconnected, Connected, Lost };

struct TrafficRecord
{
    qint64 timeMs = 0;          // monotonic, since the bus was created
    quint8 slave = 0;
    QByteArray request;         // whole RTU frame
    QByteArray reply;           // whole RTU frame as received (reconstructed), empty if none
    double roundTripMs = 0;
    QString error;              // empty when the reply was good
};

class Bus : public QObject
{
    Q_OBJECT

public:
    explicit Bus(QObject *parent = nullptr);
    ~Bus() override;

    void setSettings(const BusSettings &settings);
    const BusSettings &settings() const { return m_settings; }
    bool isReadOnly() const { return m_settings.readOnly; }
    void setReadOnly(bool readOnly) { m_settings.readOnly = readOnly; }

    // Opens the port; returns false with the reason in lastError() if it cannot.
    bool open();
    void close();
    LineState state() const { return m_state; }
    QString lastError() const { return m_lastError; }

    DeviceId addDevice(std::shared_ptr<const RegisterMap> map, quint8 address);
    void removeDevice(DeviceId id);
    QList<DeviceId> devices() const { return m_devices.keys(); }
    std::shared_ptr<const RegisterMap> deviceMap(DeviceId id) const;
    quint8 deviceAddress(DeviceId id) const;

    // Which entries a poll cycle reads (empty: every readable entry) and how often a
    // cycle starts (0: as fast as the line allows).
    void setPollEntries(DeviceId id, const QStringList &ids);
    void setPollInterval(DeviceId id, int ms);
    // Cycles run continuously while polling is on; with it off, requestCycle() runs one.
    void setPolling(bool on);
    bool isPolling() const { return m_polling; }
    void requestCycle(DeviceId id);

    const EntryState *entryState(DeviceId id, const QString &entryId) const;
    const DeviceStatistics *statistics(DeviceId id) const;
    bool isOnline(DeviceId id) const;
    // While a device is offline: the time between its probes (doubles up to 30 s).
    int backoffMs(DeviceId id) const { return m_devices.value(id).backoffMs; }
    // The read requests of one poll cycle.
    const ReadPlan *plan(DeviceId id) const;

    // Queues a write of a value given as text (the map's type and range checks apply).
    // Returns a ticket; writeFinished(ticket, ...) always follows, also for refusals.
    int write(DeviceId id, const QString &entryId, const QString &value, bool verify = true);
    // Writes to address 0: every device of that family applies it without answering;
    // each known device of the family is then read back to see that it took.
    int writeBroadcast(const QString &family, const QString &entryId, const QString &value);
    // Rewrites a RAM setpoint every intervalMs (EEPROM entries are refused: they wear).
    // Returns an error text, empty on success. An empty value stops the hold.
    QString setHold(DeviceId id, const QString &entryId, const QString &value, int intervalMs = 2000);

    // Reads a raw block outside any poll plan (scan probes): identifyFinished follows.
    int probe(quint8 slave, quint16 address, quint16 count, const ProtocolInfo &timing);

    int requestTimeoutMs(const ProtocolInfo &protocol, int requestBytes, int replyBytes) const;
    double interFrameDelayMs() const;
    // The monotonic clock of EntryState times and TrafficRecord times.
    qint64 clockMs() const { return m_clock.elapsed(); }

signals:
    void stateChanged(jumo::LineState state);
    void lineError(const QString &message);
    // Values of these entries were updated (one signal per poll block).
    void entriesUpdated(jumo::DeviceId id, const QStringList &entryIds);
    void pollCycleFinished(jumo::DeviceId id, double cycleMs);
    void onlineChanged(jumo::DeviceId id, bool online);
    void writeFinished(int ticket, const jumo::WriteOutcome &outcome);
    // Every write asked for, before any check: device -1 for a broadcast (then the
    // family is in entryId's map), with the value it replaces where one is known.
    void writeRequested(int ticket, const QString &device, const QString &entryId, const QString &value,
                        const QString &previous);
    // Probe result: words on success; else timedOut or the exception code.
    void probeFinished(int ticket, const QList<quint16> &words, bool timedOut, int exceptionCode);
    void traffic(const jumo::TrafficRecord &record);

private:
    struct HoldState
    {
        QList<quint16> words;
        int intervalMs = 2000;
        qint64 lastSentMs = -1;
    };

    struct DeviceState
    {
        std::shared_ptr<const RegisterMap> map;
        quint8 address = 0;
        QStringList pollIds;
        ReadPlan plan;
        int intervalMs = 0;
        int blockIndex = -1;        // -1: no cycle running
        int blockAttempts = 0;      // failed attempts at the current block
        qint64 cycleStartMs = -1;
        qint64 nextDueMs = 0;
        bool cycleRequested = false;
        bool online = true;
        int consecutiveFailures = 0;
        int backoffMs = 0;
        QHash<QString, EntryState> values;
        DeviceStatistics stats;
        QHash<QString, HoldState> holds;
    };

    enum class JobKind { Poll, Write, ReadBack, Probe, Hold };

    struct Job
    {
        JobKind kind = JobKind::Poll;
        DeviceId device = -1;
        int ticket = -1;
        quint8 slave = 0;
        quint16 start = 0;
        quint16 count = 0;              // words to read, or written
        QList<quint16> words;           // to write
        std::shared_ptr<const RegisterMap> map;   // keeps entry alive
        const RegisterEntry *entry = nullptr;
        bool verify = true;
        bool broadcast = false;
        QString family;                 // broadcast read-backs
        QList<DeviceId> readBackDevices;
        ProtocolInfo timing;
        int attempts = 0;
    };

    void setState(LineState state);
    void onErrorOccurred(QModbusDevice::Error error);
    void tryReconnect();
    void failAllWrites(const QString &reason);
    void replan(DeviceState &device);
    void schedule(int delayMs = 0);
    void dispatch();
    bool pickPollJob(Job &job, qint64 now, qint64 &earliestDue);
    void send(Job job);
    void onReplyFinished(QModbusReply *reply, Job job, qint64 sentMs);
    // The entries a block delivers: the polled ones whose words lie inside it.
    QList<const RegisterEntry *> blockEntries(const DeviceState &d, const Job &job) const;
    void completePoll(const Job &job, const QList<quint16> &words);
    void failPoll(const Job &job, ReadError error, int exceptionCode);
    void finishCycle(DeviceId id, DeviceState &device, qint64 now);
    void markFailure(DeviceId id, DeviceState &device);
    void markSuccess(DeviceId id, DeviceState &device);
    void finishWrite(const Job &job, WriteOutcome outcome);
    void continueAfterWrite(const Job &job);
    void checkReadBack(const Job &job, const QList<quint16> &words);
    void queueImmediateOutcome(int ticket, WriteOutcome::Result result, const QString &message);
    // Checks and encodes a write; on a refusal the outcome is queued and nullopt returned.
    std::optional<Job> makeWriteJob(int ticket, const std::shared_ptr<const RegisterMap> &map,
                                    const QString &entryId, const QString &value);
    qint64 now() const { return m_clock.elapsed(); }

    BusSettings m_settings;
    QModbusRtuSerialClient *m_client = nullptr;
    LineState m_state = LineState::Disconnected;
    QString m_lastError;
    QMap<DeviceId, DeviceState> m_devices;
    DeviceId m_nextDeviceId = 1;
    int m_nextTicket = 1;
    QQueue<Job> m_writeQueue;       // writes and their read-backs, before any poll
    QQueue<Job> m_probeQueue;
    bool m_inFlight = false;
    bool m_polling = true;
    DeviceId m_roundRobin = 0;      // the device after which the next poll search starts
    QTimer m_dispatchTimer;
    QTimer m_reconnectTimer;
    QElapsedTimer m_clock;
    qint64 m_quietUntilMs = 0;      // no request before this (late-reply guard, turnaround)
};

} // namespace jumo
