// One line with many devices. The bus composes the line connection (open, loss,
// reconnect), the scheduler (what goes next, with deadlines and fairness), the value
// store (values with their validity, statistics) and write transactions (pre-read, write
// once or safely repeated, read-back). It derives every timeout from the families'
// timing, keeps the quiet time after a lost answer, refuses writes in read-only mode and
// makes every value unknown the moment the line or the device is gone.
#pragma once

#include "bus/bussettings.h"
#include "bus/clock.h"
#include "bus/deviceidentities.h"
#include "bus/devicestatistics.h"
#include "bus/entrystate.h"
#include "bus/lineaddress.h"
#include "bus/lineconnection.h"
#include "bus/requestdesk.h"
#include "bus/scheduler.h"
#include "bus/shownviews.h"
#include "bus/transaction.h"
#include "bus/valuestore.h"
#include "bus/writeoutcome.h"
#include "protocol/readplanner.h"
#include "protocol/registermap.h"

#include <QDateTime>
#include <QHash>
#include <QObject>

#include <memory>
#include <optional>

namespace jumo {

class BitWrite;

struct TrafficRecord
{
    qint64 timeMs = 0;          // monotonic, the bus's clock
    quint8 slave = 0;
    QByteArray request;         // whole RTU frame
    QByteArray reply;           // whole RTU frame as received (reconstructed), empty if none
    double roundTripMs = 0;
    QString error;              // empty when the reply was good
};

class Bus : public DeviceSource
{
    Q_OBJECT

public:
    using Lane = Transaction::Lane;

    explicit Bus(QObject *parent = nullptr);
    // For tests: the clock and the transport are injected.
    Bus(Clock *clock, LineConnection::TransportFactory transport, QObject *parent = nullptr);
    ~Bus() override;

    void setSettings(const BusSettings &settings);
    const BusSettings &settings() const { return m_settings; }
    // The kind of line the settings' address names (serial, Modbus TCP, RTU over TCP).
    LineAddress::Kind lineKind() const { return m_lineKind; }
    bool isReadOnly() const { return m_settings.readOnly; }
    void setReadOnly(bool readOnly) { m_settings.readOnly = readOnly; }

    // Opens the port; returns false with the reason in lastError() if it cannot.
    bool open();
    void close();
    LineState state() const override { return m_line.state(); }
    QString lastError() const { return m_line.lastError(); }

    // Checks every device with the identify probes of these families (all known ones)
    // before its values count and writes reach it; empty (the default): no checks.
    void setIdentityCheck(const QList<std::shared_ptr<const RegisterMap>> &families);
    const DeviceIdentities &identities() const { return m_identities; }

    DeviceId addDevice(std::shared_ptr<const RegisterMap> map, quint8 address);
    void removeDevice(DeviceId id);
    QList<DeviceId> devices() const override { return m_scheduler.devices(); }
    std::shared_ptr<const RegisterMap> deviceMap(DeviceId id) const override;
    quint8 deviceAddress(DeviceId id) const override;
    // "ipc300@1", the name of a device in logs and messages.
    QString deviceName(DeviceId id) const override;

    // Which entries a poll cycle reads (empty: every readable entry) and how often a
    // cycle starts (0: as fast as the line allows).
    void setPollEntries(DeviceId id, const QStringList &ids);
    // Which entries a poll cycle reads (empty: every readable entry).
    QStringList pollEntries(DeviceId id) const;
    void setPollInterval(DeviceId id, int ms);
    // Cycles run continuously while polling is on; with it off, requestCycle() runs one.
    void setPolling(bool on);
    bool isPolling() const { return m_scheduler.isPolling(); }
    void requestCycle(DeviceId id);

    const EntryState *entryState(DeviceId id, const QString &entryId) const override;
    // Views say here what they show: those entries are read sooner meanwhile
    // (shownClass()).
    ShownEntries *shownEntries() const override { return m_shown.get(); }
    // The class an entry of the device is read in now (its map's, or higher while shown).
    PollClass pollClass(DeviceId id, const QString &entryId) const;
    const DeviceStatistics *statistics(DeviceId id) const;
    bool isOnline(DeviceId id) const;
    DeviceCondition condition(DeviceId id) const override;
    // While a device is offline: the time between its probes (doubles up to 30 s).
    int backoffMs(DeviceId id) const;
    // The read requests of one poll cycle.
    const ReadPlan *plan(DeviceId id) const;

    // Queues a write of a value given as text (the map's type and range checks apply).
    // Returns a ticket; writeFinished(ticket, ...) always follows, delivered queued, also
    // for refusals.
    int write(DeviceId id, const QString &entryId, const QString &value, bool verify = true,
              Lane lane = Lane::Operator);
    // Changes some bits of a bit field (bit id -> on) and keeps the others as the device
    // reports them, read just before the write; verified by read-back where the device
    // reports the bits.
    int writeBits(DeviceId id, const QString &entryId, const QHash<QString, bool> &bits, Lane lane = Lane::Operator);
    // Writes to address 0: every device of that family applies it without answering;
    // each known device of the family is then read back to see that it took. Sent once.
    int writeBroadcast(const QString &family, const QString &entryId, const QString &value);
    // Rewrites a RAM setpoint every intervalMs (EEPROM entries are refused: they wear).
    // Returns an error text, empty on success. An empty value stops the hold.
    QString setHold(DeviceId id, const QString &entryId, const QString &value, int intervalMs = 2000);

    // Reads a raw block outside any poll plan (scan probes) in the job lane, repeated
    // once when unanswered: probeFinished follows.
    int probe(quint8 slave, quint16 address, quint16 count, const ProtocolInfo &timing);
    // The same once, at the short timeout of a quick scan (quickProbeTimeoutMs) and with no
    // quiet time after a lost answer: never to an address asked again within the full
    // timeout. A late answer shows as a stray reply (strayReplies()).
    int quickProbe(quint8 slave, quint16 address, quint16 count, const ProtocolInfo &timing);
    // Replies heard that fitted no request (a bad CRC, another address's answer, a reply of
    // the wrong size, bytes that made no frame) since the bus was made, on any request: a
    // scan hears late answers so.
    quint64 strayReplies() const { return m_strayReplies; }
    // Reads these entries of a device now, in the job lane (a backup, a report): the
    // values go to the store as polls do; entriesRead follows with those that failed.
    int readEntries(DeviceId id, const QStringList &entryIds);

    // Drops what of this ticket has not gone out yet (a job cancelled): its reads end as
    // failed, its writes as not sent; the request under way finishes.
    void cancel(int ticket);

    int requestTimeoutMs(const ProtocolInfo &protocol, int requestBytes, int replyBytes) const;
    // A quick probe's: the device given quickAnswerMs, never above requestTimeoutMs.
    int quickProbeTimeoutMs(const ProtocolInfo &protocol, int requestBytes, int replyBytes) const;
    double interFrameDelayMs() const;
    // The monotonic clock of EntryState times and TrafficRecord times.
    qint64 clockMs() const override { return m_clock->nowMs(); }
    Clock *clock() const { return m_clock; }

signals:
    void lineError(const QString &message);
    void pollCycleFinished(jumo::DeviceId id, double cycleMs);
    void onlineChanged(jumo::DeviceId id, bool online);
    void writeFinished(int ticket, const jumo::WriteOutcome &outcome);
    // Every write asked for, before any check: the device ("family@0" for a broadcast),
    // with the value it replaces where one is known.
    void writeRequested(int ticket, const QString &device, const QString &entryId, const QString &value,
                        const QString &previous);
    // Probe result: words on success; else timedOut or the exception code.
    void probeFinished(int ticket, const QList<quint16> &words, bool timedOut, int exceptionCode);
    void entriesRead(int ticket, const QStringList &failedIds);
    void traffic(const jumo::TrafficRecord &record);
    // A hold (setHold) ended without being asked to: the device is no longer confirmed
    // to be of its family (it was gone and answers again), so nothing more is written.
    void holdStopped(jumo::DeviceId id, const QString &entryId, const QString &reason);

private:
    friend class RequestDesk;

    struct InFlight
    {
        Scheduler::Turn turn;
        qint64 sentMs = 0;
    };

    void init();
    void onStateChanged(LineState state);
    void onLineLost(const QString &reason);
    void onResult(const ModbusResult &result);
    void loseInFlight(const QString &reason);
    void schedule(qint64 atMs);
    void dispatch();
    void sweep();
    void applyPoll(const Scheduler::Turn &turn, const ModbusResult &result, qint64 now);
    void refreshSettingsAfterWrite(const Scheduler::Turn &turn);
    void recordTraffic(const InFlight &flight, const ModbusResult &result, double roundTripMs);
    void setQuietAfter(const InFlight &flight, const ModbusResult &result, qint64 now);
    static bool isQuickProbe(const Scheduler::Turn &turn)
    {
        return turn.kind == Scheduler::Turn::Kind::Transaction && turn.transaction && turn.transaction->isQuickProbe();
    }
    void invalidateAll(ReadError reason);
    void abortQueued(const QString &reason);
    void setOnline(DeviceId id, bool online);
    void onIdentityChanged(DeviceId id);
    void emitCondition(DeviceId id);
    void updateAllowance(DeviceId id);
    void finishLater(int ticket, const WriteOutcome &outcome);
    void refuseLater(int ticket, WriteOutcome::Result result, const QString &message);
    int nextTicket() { return m_nextTicket++; }
    qint64 now() const { return m_clock->nowMs(); }

    std::unique_ptr<Clock> m_ownClock;
    Clock *m_clock;
    BusSettings m_settings;
    LineAddress::Kind m_lineKind = LineAddress::Kind::Serial;
    quint64 m_strayReplies = 0;
    LineConnection m_line;
    Scheduler m_scheduler;
    ValueStore m_store;
    RequestDesk m_requests{*this};
    std::unique_ptr<ShownViews> m_shown;
    QHash<DeviceId, QDateTime> m_offlineSince;
    QDateTime m_lineSince;
    std::optional<InFlight> m_inFlight;
    QList<DeviceId> m_forgetAfterFlight;   // removed while their request was under way
    int m_nextTicket = 1;
    qint64 m_wakeAtMs = -1;                // the earliest dispatch already asked for
    bool m_sweeping = false;
    DeviceIdentities m_identities{*this};   // last: its checks use the bus while it goes
};

} // namespace jumo
