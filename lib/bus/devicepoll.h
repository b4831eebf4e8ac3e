// One device's poll cycles: what they read (its read plan), which block is next, when the
// next cycle is due, the repeat of a failed block, the split of a block answered with
// exception 02 until the one address the device lacks is isolated, and online or offline
// with back-off. The scheduler decides whose turn it is; this says what that turn reads.
#pragma once

#include "bus/entrystate.h"
#include "bus/modbusrequest.h"
#include "protocol/readplanner.h"

#include <QSet>

#include <memory>
#include <optional>

namespace jumo {

struct DeviceInfo
{
    std::shared_ptr<const RegisterMap> map;
    quint8 address = 0;
    ReadPlan plan;
    int intervalMs = 0;
    bool online = true;
    int backoffMs = 0;
    double lastCycleMs = 0;
};

// What became of a poll turn, for the bus to carry out.
struct PollOutcome
{
    QList<const RegisterEntry *> entries;     // the entries of the block
    bool store = false;                       // the words are good: store the entries
    bool retry = false;                       // the block is repeated; nothing to report yet
    std::optional<ReadError> failure;         // the entries failed for this reason
    int exceptionCode = 0;
    QList<const RegisterEntry *> unavailable; // isolated by exception 02: not on this device
    std::optional<bool> online;               // the device went on- or offline
    std::optional<double> cycleMs;            // a cycle of the device finished
};

class DevicePoll
{
public:
    static constexpr int failuresBeforeOffline = 2;   // blocks failed after all their retries
    static constexpr int firstBackoffMs = 1000;
    static constexpr int maximumBackoffMs = 30000;

    DevicePoll() = default;
    DevicePoll(std::shared_ptr<const RegisterMap> map, quint8 address, qint64 now);

    const DeviceInfo &info() const { return m_info; }
    const RegisterMap &map() const { return *m_info.map; }
    quint8 address() const { return m_info.address; }
    bool isOnline() const { return m_info.online; }
    bool isAvailable(const QString &entryId) const { return !m_unavailable.contains(entryId); }

    // Which entries a cycle reads (empty: every readable entry).
    void setPollEntries(const QStringList &ids);
    // Entries isolated by exception 02 are polled again (another device may be there now).
    void forgetUnavailable();
    QStringList pollEntries() const { return m_pollIds; }
    void setInterval(int ms) { m_info.intervalMs = std::max(0, ms); }
    // One cycle soon, polling on or off; false when there is nothing to read.
    bool requestCycle(qint64 now);

    // Whether a block is to be read now (polling: cycles start by themselves).
    bool ready(qint64 now, bool polling) const;
    // When one will be (0: now, -1: not until told).
    qint64 dueMs(bool polling) const;
    // The block to read now, starting a cycle when none runs: its index and request.
    std::pair<int, ModbusRequest> nextBlock(qint64 now);
    // What the answer to that block means.
    PollOutcome finished(int block, const ModbusResult &result, int maxRetries, qint64 now);
    // Whatever a cycle was doing is void: the line was (re)opened.
    void restart(qint64 now);

private:
    void replan();
    void isolate(int block, PollOutcome &outcome, qint64 now);
    void finishCycle(qint64 now, PollOutcome &outcome);
    void markFailure(PollOutcome &outcome);
    void markSuccess(PollOutcome &outcome);

    DeviceInfo m_info;
    QStringList m_pollIds;
    QSet<QString> m_unavailable;   // entries this model does not have
    int m_blockIndex = -1;         // -1: no cycle running
    int m_blockAttempts = 0;
    qint64 m_cycleStartMs = -1;
    qint64 m_nextDueMs = 0;
    bool m_cycleRequested = false;
    int m_consecutiveFailures = 0;
};

} // namespace jumo
