// One device's polls: what they read (a read plan per poll class), which block is most
// overdue and how urgent that is, the repeat of a failed block, the split of a block
// answered with exception 02 until the one address the device lacks is isolated, online
// or offline with back-off, and when a cycle is over. The scheduler decides whose turn it
// is; this says what that turn reads and how badly it is needed.
#pragma once

#include "bus/entrystate.h"
#include "bus/modbusrequest.h"
#include "protocol/lineformat.h"
#include "protocol/readplanner.h"

#include <QHash>
#include <QSet>

#include <array>
#include <limits>
#include <memory>
#include <optional>

namespace jumo {

constexpr int pollClassCount = 3;
constexpr int classIndex(PollClass pollClass) { return int(pollClass); }

struct DeviceInfo
{
    std::shared_ptr<const RegisterMap> map;
    quint8 address = 0;
    ReadPlan plan;   // every block tagged with its class
    int intervalMs = 0;
    bool online = true;
    int backoffMs = 0;
    double lastCycleMs = 0;
    // Per class: the longest time between two reads of one of its blocks in the last
    // cycle (0: none read twice yet). What the values' allowance is made of.
    std::array<qint64, pollClassCount> classAgeMs{};
    qint64 shownAgeMs = 0;   // the same for the live values a view shows
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

// How badly a device needs its next read: the scheduler takes the lowest tier first, and
// within a tier the block most overdue.
struct PollChoice
{
    enum Tier {
        AlarmDue,   // an alarm block at its target age
        Due,        // a setting or live values a view shows at their target age, any
                    // block at the ceiling, a probe, a cycle asked for, settings after a
                    // write: the most overdue first, so none of them starves another
        Filler,     // live values: as often as the rest allows (shown ones first)
        None
    };
    int block = -1;
    Tier tier = None;
    qint64 overdueMs = 0;
};

class DevicePoll
{
public:
    static constexpr int failuresBeforeOffline = 2;   // blocks failed after all their retries
    static constexpr int firstBackoffMs = 1000;
    static constexpr int maximumBackoffMs = 30000;
    // Target ages: an alarm block is read again after 1.2 s (an alarm held for 2 s is seen
    // within 1.5 s at the 99th percentile, and 31 devices' alarm words, some 38 % of a
    // 38400 line, leave room for their faceplates), a setting from 50 s, ranked by the time left to 55 s (so
    // within the minute on a full line, whose time goes to the shown values until then),
    // live values whenever nothing else is. Past the ceiling (the setting target) every
    // block is due, ranked the same way.
    static constexpr int alarmTargetMs = 1200;
    static constexpr int settingTargetMs = 50000;
    static constexpr int settingDeadlineMs = 55000;
    // Settings may be read from this age on where the line has time (with the live values).
    static constexpr int settingEarlyMs = 20000;
    // Live values a view shows (a faceplate, an open page): due from shownTargetMs, ranked
    // by the time left to shownDeadlineMs, so on a full line they go ahead of a setting that
    // still has seconds and after the alarm words, which are read every round.
    static constexpr int shownTargetMs = 2500;
    static constexpr int shownDeadlineMs = 3000;

    DevicePoll() = default;
    DevicePoll(std::shared_ptr<const RegisterMap> map, quint8 address, qint64 now);

    const DeviceInfo &info() const { return m_info; }
    const RegisterMap &map() const { return *m_info.map; }
    quint8 address() const { return m_info.address; }
    bool isOnline() const { return m_info.online; }
    bool isAvailable(const QString &entryId) const { return !m_unavailable.contains(entryId); }

    // Which entries are read (empty: every readable entry, each in its map class). A
    // selection is read whole every cycle, as one live class.
    void setPollEntries(const QStringList &ids);
    QStringList pollEntries() const { return m_pollIds; }
    // Entries a view shows: read sooner while shown (shownClass(), shownTargetMs).
    void setShown(const QSet<QString> &entryIds);
    // The line's baud rate and format: plans weigh the wire time of gaps against requests.
    void setLineFormat(const std::optional<LineFormat> &format);
    // Entries isolated by exception 02 are polled again (another device may be there now).
    void forgetUnavailable();
    // No block read more often than this (0: each class's own target).
    void setInterval(int ms) { m_info.intervalMs = std::max(0, ms); }
    // The class an entry is read in now.
    PollClass classOf(const QString &entryId) const { return m_classOf.value(entryId, PollClass::Live); }
    const QHash<QString, PollClass> &classes() const { return m_classOf; }
    int targetMs(PollClass pollClass) const;
    // How long a value of the class stays current: about twice the age its blocks are
    // read at (their target, or what the line gave them lately), plus a second.
    qint64 allowanceMs(PollClass pollClass) const;
    // The live values a view shows (read at shownTargetMs) and how long they stay current:
    // as long as their own reads allow, not as long as the other live values'.
    QSet<QString> shownLive() const;
    qint64 shownAllowanceMs() const;

    // One cycle soon, every block, polling on or off; false when there is nothing to read.
    bool requestCycle(qint64 now);
    // The settings are read at once (a write may have changed more than its own word).
    void refreshSettings(qint64 now);

    // The block to read now and how urgent it is (block -1: none); only blocks of this
    // tier or a lower one (less urgent) when given.
    PollChoice choose(qint64 now, bool polling, PollChoice::Tier from = PollChoice::AlarmDue) const;
    bool ready(qint64 now, bool polling) const { return choose(now, polling).block >= 0; }
    // When a block will be due (-1: not until told).
    qint64 dueMs(bool polling) const;
    // The request that reads a block, which is from now on under way.
    ModbusRequest start(int block, qint64 now);
    // What the answer to that block means.
    PollOutcome finished(int block, const ModbusResult &result, int maxRetries, qint64 now, bool polling);
    // Whatever was under way is void and everything is read at once: the line was (re)opened.
    void restart(qint64 now);

private:
    static constexpr qint64 neverMs = std::numeric_limits<qint64>::min() / 4;

    void replan();
    qint64 doneMs(const ReadBlock &block) const;
    bool forced(const ReadBlock &block) const;
    void isolate(int block, PollOutcome &outcome);
    void markRead(const ReadBlock &block, qint64 now, bool good);
    void checkCycle(qint64 now, PollOutcome &outcome, bool polling);
    void finishCycle(qint64 now, PollOutcome &outcome);
    bool readThisCycle(const ReadBlock &block) const;
    void markFailure(PollOutcome &outcome);
    void markSuccess(PollOutcome &outcome);
    int probeBlock() const;

    DeviceInfo m_info;
    QStringList m_pollIds;
    QSet<QString> m_shown;
    std::optional<LineFormat> m_format;
    QSet<QString> m_unavailable;          // entries this model does not have
    QHash<QString, PollClass> m_classOf;  // the class each planned entry is read in
    QHash<QString, qint64> m_doneMs;      // entry -> last read (answered or failed for good)
    QList<int> m_attempts;                // per block: failed attempts of the read under way
    qint64 m_pausedUntilMs = 0;           // after a lost answer: nothing of the device before
    int m_inFlight = -1;
    qint64 m_inFlightSinceMs = 0;
    // Blocks of a class last read before this time are read at once.
    std::array<qint64, pollClassCount> m_forcedMs{neverMs, neverMs, neverMs};
    qint64 m_requestedMs = -1;            // a whole cycle asked for at this time
    qint64 m_cycleStartMs = 0;
    int m_cycle = 0;                      // the cycle under way
    QHash<QString, int> m_cycleOf;        // entry -> the cycle it was last read in
    int m_readsThisCycle = 0;
    std::array<qint64, pollClassCount> m_cycleClassAgeMs{};
    qint64 m_cycleShownAgeMs = 0;
    qint64 m_nextProbeMs = 0;             // offline: the next probe
    int m_consecutiveFailures = 0;
};

} // namespace jumo
