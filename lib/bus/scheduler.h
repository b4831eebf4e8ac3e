// Decides what goes on the line next, and when. The rules, in order:
//  1. a transaction that holds the line (the write after its read-modify-write read)
//     goes at once;
//  2. a device with a bus-error timeout (IPC 300, TYA 200) that has not been addressed for
//     almost its keepalive interval (half the bus-error timeout) gets a request before
//     anything else, so it never falls silent for longer than that whatever else runs;
//  3. operator work goes next;
//  4. RAM setpoint holds, when due;
//  5. job work (scan, backup, restore, report) and polls alternate while both wait,
//     and polls go on until they have had as much line time as the jobs (a silent
//     address costs a scan its timeout); either runs alone when the other has nothing;
// and nothing goes before the quiet time the bus sets after a lost answer, a turnaround
// or a broadcast. Polls go by deadlines, not turns: every block has its class's target
// age, and the most overdue block of the most urgent tier goes first (alarm words at
// their age, then settings, probes and anything at the ceiling, then live values as
// often as the rest allows); devices that are equally overdue take turns. What each
// device reads is its DevicePoll's business (plans, repeats, exception 02, back-off).
// Pure logic: no timers, no transport, the time is given.
#pragma once

#include "bus/devicepoll.h"
#include "bus/transaction.h"

#include <QHash>
#include <QMap>
#include <QSet>

#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace jumo {

class Scheduler
{
public:
    struct Turn
    {
        enum class Kind { Idle, Poll, Keepalive, Transaction, Hold };
        Kind kind = Kind::Idle;
        DeviceId device = -1;
        int block = -1;                           // Poll: index into the device's plan
        jumo::Transaction *transaction = nullptr;  // Transaction: owned by the scheduler
        QString holdEntry;                        // Hold
        ModbusRequest request;                    // the timeout is the bus's to set
        ProtocolInfo timing;
        qint64 wakeAtMs = -1;                     // Idle: when to ask again, -1 = when told
    };

    using PollOutcome = jumo::PollOutcome;
    using DeviceInfo = jumo::DeviceInfo;

    // How long before its keepalive interval ends a device's request becomes urgent.
    static constexpr int keepaliveMarginMs = 1000;
    // Alarm words read in a row while a setting or a probe waits: the rest keep a fifth of
    // the line even where the alarm words alone would fill it.
    static constexpr int alarmTurnsInARow = 4;

    void addDevice(DeviceId id, std::shared_ptr<const RegisterMap> map, quint8 address, qint64 now);
    void removeDevice(DeviceId id);
    bool contains(DeviceId id) const { return m_devices.contains(id); }
    const DeviceInfo *device(DeviceId id) const;
    QList<DeviceId> devices() const { return m_devices.keys(); }

    // Which entries a poll cycle reads (empty: every readable entry).
    void setPollEntries(DeviceId id, const QStringList &ids);
    // The entries views show of the device: each is read sooner meanwhile.
    void setShown(DeviceId id, const QSet<QString> &entryIds);
    // The line's format, for plans that weigh wire time (none: fewest requests).
    void setLineFormat(const std::optional<LineFormat> &format);
    // The class each polled entry of the device is read in now.
    QHash<QString, PollClass> entryClasses(DeviceId id) const;
    // How long a value of the class stays current (see DevicePoll::allowanceMs).
    qint64 allowanceMs(DeviceId id, PollClass pollClass) const;
    QSet<QString> shownLive(DeviceId id) const;
    qint64 shownAllowanceMs(DeviceId id) const;
    // The device's settings are read at once (after a write to it).
    void refreshSettings(DeviceId id, qint64 now);
    void forgetUnavailable(DeviceId id);
    QStringList pollEntries(DeviceId id) const;
    // How often a cycle starts (0: as fast as the line allows).
    void setPollInterval(DeviceId id, int ms);
    void setPolling(bool on) { m_polling = on; }
    bool isPolling() const { return m_polling; }
    // One cycle of the device soon, polling on or off; false when there is nothing to read.
    bool requestCycle(DeviceId id, qint64 now);
    // The entries of a block of the device's plan.
    QList<const RegisterEntry *> blockEntries(DeviceId id, int block) const;

    void setHold(DeviceId id, const QString &entryId, const QList<quint16> &words, int intervalMs);
    void clearHold(DeviceId id, const QString &entryId);

    void enqueue(std::unique_ptr<Transaction> transaction);
    // Every transaction not under way, out of the queues (the line went down or closed).
    std::vector<std::unique_ptr<Transaction>> takeQueued(const Transaction *inFlight);
    // The transactions of this ticket not under way, out of the queues (a cancel).
    std::vector<std::unique_ptr<Transaction>> takeTicket(int ticket, const Transaction *inFlight);
    // Transactions waiting, both lanes.
    int queuedTransactions() const { return int(m_operator.size() + m_jobs.size()); }
    void forgetDevice(DeviceId id, const Transaction *inFlight);

    // The next turn at this time.
    Turn next(qint64 now);
    void setQuietUntil(qint64 ms) { m_quietUntilMs = std::max(m_quietUntilMs, ms); }
    qint64 quietUntil() const { return m_quietUntilMs; }
    // A request went out (every request to an address counts as its keepalive).
    void sent(const ModbusRequest &request, qint64 now);
    // A turn is over: the line time it took, its quiet time after included.
    void charge(const Turn &turn, qint64 lineMs);
    // Whatever a cycle was doing is void: the line was (re)opened.
    void restart(qint64 now);

    PollOutcome pollFinished(const Turn &turn, const ModbusResult &result, int maxRetries, qint64 now);
    // A transaction's turn is over; finished ones leave the queues.
    void transactionFinished(Transaction *transaction);

    // The keepalive a device needs (0: none): half its bus-error timeout.
    static int keepaliveMs(const RegisterMap &map);

private:
    struct Hold
    {
        QList<quint16> words;
        int intervalMs = 2000;
        qint64 lastSentMs = -1;
    };

    struct Device
    {
        DevicePoll poll;
        QMap<QString, Hold> holds;
    };

    std::optional<Turn> pollTurn(qint64 now);
    std::optional<std::pair<DeviceId, PollChoice>> bestPoll(qint64 now, PollChoice::Tier from);
    std::optional<Turn> keepaliveTurn(qint64 now);
    std::optional<Turn> holdTurn(qint64 now);
    std::optional<Turn> transactionTurn(std::deque<std::unique_ptr<Transaction>> &lane);
    Turn devicePollTurn(DeviceId id, Device &device, int block, qint64 now);
    void prune(std::deque<std::unique_ptr<Transaction>> &lane);

    QMap<DeviceId, Device> m_devices;
    std::deque<std::unique_ptr<Transaction>> m_operator;
    std::deque<std::unique_ptr<Transaction>> m_jobs;
    Transaction *m_holding = nullptr;          // must go next
    bool m_polling = true;
    bool m_lastWasJob = false;
    qint64 m_jobLineMs = 0;                    // line time of jobs and polls while both wait
    qint64 m_pollLineMs = 0;
    DeviceId m_roundRobin = 0;                 // the device after which the next poll search starts
    int m_alarmStreak = 0;                     // alarm turns since anything else
    qint64 m_quietUntilMs = 0;
    QHash<quint8, qint64> m_lastAddressedMs;   // slave -> last request
    std::optional<LineFormat> m_format;
};

} // namespace jumo
