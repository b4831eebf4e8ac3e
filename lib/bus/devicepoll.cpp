#include "bus/devicepoll.h"

#include "bus/linetiming.h"

#include <QMap>

#include <algorithm>

namespace jumo {

namespace {

constexpr int illegalDataAddress = 2;
constexpr int deviceBusy = 6;

ReadBlock blockOf(QList<const RegisterEntry *> entries, const ReadBlock &like)
{
    ReadBlock b;
    b.start = entries.first()->address;
    int last = b.start;
    for (const RegisterEntry *e : entries)
        last = std::max<int>(last, e->lastAddress());
    b.count = quint16(last - b.start + 1);
    b.entries = std::move(entries);
    b.pollClass = like.pollClass;
    b.shown = like.shown;
    return b;
}

bool better(const PollChoice &candidate, const PollChoice &best)
{
    return candidate.tier < best.tier || (candidate.tier == best.tier && candidate.overdueMs > best.overdueMs);
}

} // namespace

DevicePoll::DevicePoll(std::shared_ptr<const RegisterMap> map, quint8 address, qint64 now)
{
    m_info.map = std::move(map);
    m_info.address = address;
    m_cycleStartMs = now;
    m_nextProbeMs = now;
    replan();
}

void DevicePoll::replan()
{
    QList<const RegisterEntry *> wanted;
    QStringList missing;
    if (m_pollIds.isEmpty()) {
        for (const RegisterEntry &e : m_info.map->entries()) {
            if (e.isReadable() && e.alias.isEmpty() && !m_unavailable.contains(e.id))
                wanted << &e;
        }
    } else {
        for (const QString &id : std::as_const(m_pollIds)) {
            if (const RegisterEntry *e = m_info.map->entry(id); e && !m_unavailable.contains(id))
                wanted << e;
            else if (!e)
                missing << id;
        }
    }
    // A selection is what the user asked to see every cycle: one class. Whole maps are
    // read by what each entry is. Each class is planned apart (an alarm word never waits
    // in a block of settings), and so are the live values a view shows.
    m_classOf.clear();
    QMap<QPair<int, bool>, QList<const RegisterEntry *>> groups;
    for (const RegisterEntry *e : std::as_const(wanted)) {
        PollClass c = m_pollIds.isEmpty() ? e->pollClass : PollClass::Live;
        const bool shown = m_shown.contains(e->id);
        if (shown)
            c = shownClass(c);
        if (e->isReadable())
            m_classOf.insert(e->id, c);
        groups[qMakePair(classIndex(c), shown && c == PollClass::Live)] << e;
    }
    const int maxGap = m_format ? LineTiming::bridgeableGapWords(*m_format, m_info.map->protocol) : -1;
    ReadPlan plan;
    for (auto it = groups.cbegin(); it != groups.cend(); ++it) {
        ReadPlan part = ReadPlanner::plan(*m_info.map, it.value(), maxGap);
        for (ReadBlock &b : part.blocks) {
            b.pollClass = PollClass(it.key().first);
            b.shown = it.key().second;
        }
        plan.blocks += part.blocks;
        plan.errors += part.errors;
    }
    for (const QString &id : std::as_const(missing))
        plan.errors.prepend(ReadPlanner::tr("'%1' is not an entry of %2").arg(id, m_info.map->family));
    m_info.plan = std::move(plan);
    m_attempts = QList<int>(m_info.plan.blocks.size(), 0);
    m_inFlight = -1;
}

void DevicePoll::forgetUnavailable()
{
    if (m_unavailable.isEmpty())
        return;
    m_unavailable.clear();
    replan();
}

void DevicePoll::setPollEntries(const QStringList &ids)
{
    m_pollIds = ids;
    replan();
}

void DevicePoll::setShown(const QSet<QString> &entryIds)
{
    if (entryIds == m_shown)
        return;
    m_shown = entryIds;
    replan();
}

void DevicePoll::setLineFormat(const std::optional<LineFormat> &format)
{
    m_format = format;
    replan();
}

int DevicePoll::targetMs(PollClass pollClass) const
{
    switch (pollClass) {
    case PollClass::Alarm:
        return std::max(alarmTargetMs, m_info.intervalMs);
    case PollClass::Live:
        return m_info.intervalMs;
    case PollClass::Setting:
        break;
    }
    return std::max(settingTargetMs, m_info.intervalMs);
}

qint64 DevicePoll::allowanceMs(PollClass pollClass) const
{
    qint64 expected = std::max<qint64>(targetMs(pollClass), m_info.classAgeMs[classIndex(pollClass)]);
    if (pollClass == PollClass::Live)
        expected = std::max(expected, qint64(m_info.lastCycleMs));
    return std::max<qint64>(2 * expected, 2000) + 1000;
}

QSet<QString> DevicePoll::shownLive() const
{
    QSet<QString> ids;
    for (const ReadBlock &b : m_info.plan.blocks) {
        if (b.shown) {
            for (const RegisterEntry *e : b.entries)
                ids.insert(e->id);
        }
    }
    return ids;
}

qint64 DevicePoll::shownAllowanceMs() const
{
    const qint64 expected = std::max<qint64>(m_info.intervalMs > 0 ? m_info.intervalMs : shownTargetMs, m_info.shownAgeMs);
    return std::max<qint64>(2 * expected, 2000) + 1000;
}

qint64 DevicePoll::doneMs(const ReadBlock &block) const
{
    qint64 done = std::numeric_limits<qint64>::max();
    for (const RegisterEntry *e : block.entries)
        done = std::min(done, m_doneMs.value(e->id, neverMs));
    return block.entries.isEmpty() ? neverMs : done;
}

bool DevicePoll::forced(const ReadBlock &block) const
{
    const qint64 done = doneMs(block);
    return done < m_forcedMs[classIndex(block.pollClass)] || (m_requestedMs >= 0 && done < m_requestedMs);
}

bool DevicePoll::requestCycle(qint64 now)
{
    if (m_info.plan.blocks.isEmpty())
        return false;
    // From now: a block read before this request, in a cycle still under way, is read again.
    m_requestedMs = now;
    if (m_readsThisCycle == 0)
        m_cycleStartMs = now;
    return true;
}

void DevicePoll::refreshSettings(qint64 now)
{
    m_forcedMs[classIndex(PollClass::Setting)] = now;
}

int DevicePoll::probeBlock() const
{
    // The shortest read: a probe of a device that does not answer costs its timeout.
    int chosen = 0;
    for (int i = 1; i < m_info.plan.blocks.size(); ++i) {
        if (m_info.plan.blocks.at(i).count < m_info.plan.blocks.at(chosen).count)
            chosen = i;
    }
    return chosen;
}

PollChoice DevicePoll::choose(qint64 now, bool polling, PollChoice::Tier from) const
{
    PollChoice best;
    if (m_info.plan.blocks.isEmpty())
        return best;
    if (!m_info.online) {
        if (now >= m_nextProbeMs && from <= PollChoice::Due)
            best = PollChoice{probeBlock(), PollChoice::Due, now - m_nextProbeMs};
        return best;
    }
    // After a lost answer the device waits as long as that request took: one that
    // stopped answering gets at most half of the line, whatever its blocks' deadlines.
    if (now < m_pausedUntilMs)
        return best;
    const auto ownTier = [this](const ReadBlock &b) {
        // Live values are read whenever nothing else is due, unless the device has an
        // interval: then they are due at it, like any deadline.
        return b.pollClass == PollClass::Alarm                                ? PollChoice::AlarmDue
                : b.pollClass == PollClass::Live && m_info.intervalMs <= 0 ? PollChoice::Filler
                                                                           : PollChoice::Due;
    };
    // A block whose answer was lost is asked again before anything else of the device, so
    // a device that stopped answering is offline after its retries, not once each of its
    // blocks has timed out (a minute for a dTRON at 19200). It takes the place of the
    // device's most urgent block: a retry of a live block never holds the alarm words up
    // behind a tier a full line does not serve.
    const int retry = int(std::find_if(m_attempts.cbegin(), m_attempts.cend(), [](int a) { return a > 0; })
                          - m_attempts.cbegin());
    const int ceiling = targetMs(PollClass::Setting);
    const qint64 deadline = ceiling + (settingDeadlineMs - settingTargetMs);
    for (int i = 0; i < m_info.plan.blocks.size(); ++i) {
        const ReadBlock &b = m_info.plan.blocks.at(i);
        const qint64 done = doneMs(b);
        const qint64 age = now - done;
        const int target = targetMs(b.pollClass);
        const bool filler = ownTier(b) == PollChoice::Filler;
        PollChoice here{i, PollChoice::None, 0};
        if (forced(b)) {
            const qint64 askedMs = std::max(m_forcedMs[classIndex(b.pollClass)], m_requestedMs);
            here.tier = b.pollClass == PollClass::Alarm ? PollChoice::AlarmDue : PollChoice::Due;
            // Asked for at once (after a write, a reconnect, an identity check): ahead of
            // whatever is merely late in its tier, such as the shown values of a full line.
            here.overdueMs = settingDeadlineMs + std::max<qint64>(0, now - askedMs);
        } else if (!polling) {
            continue;
        } else if (b.pollClass == PollClass::Alarm) {
            if (age < target)
                continue;
            here.tier = PollChoice::AlarmDue;
            here.overdueMs = age - target;
        } else if (age >= ceiling) {
            // Due, ranked by the time left to its deadline (below: the same for each kind),
            // so every entry is read within the minute.
            here.tier = PollChoice::Due;
            here.overdueMs = age - deadline;
        } else if (b.shown && filler && age >= shownTargetMs) {
            here.tier = PollChoice::Due;
            here.overdueMs = age - shownDeadlineMs;
        } else if (!filler && age >= target) {
            here.tier = PollChoice::Due;
            here.overdueMs = age - (b.pollClass == PollClass::Setting ? deadline : target);
        } else if (filler) {
            // Live values: as often as the rest allows, the oldest first (those a view
            // shows count as twice as old).
            here.tier = PollChoice::Filler;
            here.overdueMs = (b.shown ? 2 : 1) * (age - target);
        } else if (b.pollClass == PollClass::Setting && age >= std::max(settingEarlyMs, m_info.intervalMs)) {
            // A setting may be read early where the line has time, so the settings of a
            // line read together at its start do not stay due together every minute.
            here.tier = PollChoice::Filler;
            here.overdueMs = age - settingEarlyMs;
        } else {
            continue;
        }
        if (here.tier >= from && better(here, best))
            best = here;
    }
    if (retry < m_attempts.size()) {
        if (best.block >= 0) {
            best.block = retry;
            return best;
        }
        const PollChoice own{retry, ownTier(m_info.plan.blocks.at(retry)), now - m_pausedUntilMs};
        return own.tier >= from ? own : best;
    }
    return best;
}

qint64 DevicePoll::dueMs(bool polling) const
{
    if (m_info.plan.blocks.isEmpty())
        return -1;
    if (!m_info.online)
        return m_nextProbeMs;
    const auto later = [this](qint64 due) { return std::max(due, m_pausedUntilMs); };
    qint64 earliest = -1;
    const int ceiling = targetMs(PollClass::Setting);
    for (int i = 0; i < m_info.plan.blocks.size(); ++i) {
        const ReadBlock &b = m_info.plan.blocks.at(i);
        if (m_attempts.at(i) > 0 || forced(b))
            return later(0);
        if (!polling)
            continue;
        const qint64 done = doneMs(b);
        const qint64 due = done + (b.pollClass == PollClass::Setting ? ceiling : std::min(targetMs(b.pollClass), ceiling));
        earliest = earliest < 0 ? std::max<qint64>(0, due) : std::min(earliest, std::max<qint64>(0, due));
    }
    return earliest < 0 ? earliest : later(earliest);
}

ModbusRequest DevicePoll::start(int block, qint64 now)
{
    m_inFlight = block;
    m_inFlightSinceMs = now;
    const ReadBlock &b = m_info.plan.blocks.at(block);
    return ModbusRequest::read(m_info.address, b.start, b.count);
}

void DevicePoll::restart(qint64 now)
{
    m_doneMs.clear();
    m_attempts.fill(0);
    m_inFlight = -1;
    m_pausedUntilMs = 0;
    m_nextProbeMs = now;
    m_consecutiveFailures = 0;
    m_cycleStartMs = now;
    m_readsThisCycle = 0;
    ++m_cycle;
}

PollOutcome DevicePoll::finished(int block, const ModbusResult &result, int maxRetries, qint64 now, bool polling)
{
    PollOutcome out;
    if (block < 0 || block >= m_info.plan.blocks.size() || m_inFlight != block)
        return out;   // the plan changed while the block was under way
    m_inFlight = -1;
    const ReadBlock b = m_info.plan.blocks.at(block);
    out.entries = b.entries;

    // A gateway's 0x0A/0x0B is no answer of the device's: counted as a timeout, shown
    // with its code.
    switch (result.isGatewayException() ? ModbusResult::Status::Timeout : result.status) {
    case ModbusResult::Status::Ok:
        m_attempts[block] = 0;
        out.store = true;
        markSuccess(out);
        markRead(b, now, true);
        break;
    case ModbusResult::Status::Exception:
        if (result.exceptionCode == illegalDataAddress) {
            markSuccess(out);
            isolate(block, out);
            if (!out.retry)
                checkCycle(now, out, polling);
            return out;
        }
        // It answered: it is there; the block is refused (a busy device is asked again).
        if (result.exceptionCode == deviceBusy && m_info.map->exceptions.contains(deviceBusy)
            && ++m_attempts[block] <= maxRetries) {
                        out.retry = true;
            return out;
        }
        m_attempts[block] = 0;
        markSuccess(out);
        out.failure = ReadError::Exception;
        out.exceptionCode = result.exceptionCode;
        markRead(b, now, false);
        break;
    case ModbusResult::Status::LineDown:
        // The bus invalidates everything; the block is read when the line is back.
        m_attempts[block] = 0;
        return out;
    default:
        // The request took its timeout and takes as long again in quiet: the others get
        // as long again after that.
        m_pausedUntilMs = now + 3 * (now - m_inFlightSinceMs);
        if (m_info.online && ++m_attempts[block] <= maxRetries) {
                        out.retry = true;   // still due: read again
            return out;
        }
        m_attempts[block] = 0;
        out.failure = result.isGatewayException()                     ? ReadError::Exception
                : result.status == ModbusResult::Status::BadReply ? ReadError::Mismatch
                                                                  : ReadError::Timeout;
        out.exceptionCode = result.isGatewayException() ? result.exceptionCode : 0;
        markFailure(out);
        if (!m_info.online) {
            // Each probe that finds nobody ends a cycle: whoever prints cycles says so.
            finishCycle(now, out);
            m_nextProbeMs = now + m_info.backoffMs;
            return out;
        }
        markRead(b, now, false);
        break;
    }
    checkCycle(now, out, polling);
    return out;
}

void DevicePoll::markRead(const ReadBlock &block, qint64 now, bool good)
{
    const int c = classIndex(block.pollClass);
    for (const RegisterEntry *e : block.entries) {
        const qint64 previous = m_doneMs.value(e->id, neverMs);
        if (good && previous != neverMs) {
            m_cycleClassAgeMs[c] = std::max(m_cycleClassAgeMs[c], now - previous);
            if (block.shown)
                m_cycleShownAgeMs = std::max(m_cycleShownAgeMs, now - previous);
        }
        m_doneMs.insert(e->id, now);
        m_cycleOf.insert(e->id, m_cycle);
    }
    ++m_readsThisCycle;
}

void DevicePoll::checkCycle(qint64 now, PollOutcome &outcome, bool polling)
{
    // A cycle is over when everything of the device is fresh: every block read since it
    // began (live values), or still within its class's target age (alarms, settings).
    if (m_readsThisCycle == 0)
        return;
    for (const ReadBlock &b : std::as_const(m_info.plan.blocks)) {
        const qint64 done = doneMs(b);
        if (forced(b))
            return;
        if (readThisCycle(b))
            continue;
        if (!polling || b.pollClass == PollClass::Live || now - done >= targetMs(b.pollClass))
            return;
    }
    finishCycle(now, outcome);
}

void DevicePoll::isolate(int block, PollOutcome &out)
{
    // A smaller model lacks an address of the block: halve it until the one entry is
    // found; the rest is read, that entry leaves the plan for the session.
    const ReadBlock whole = m_info.plan.blocks.at(block);
    out.entries.clear();
    if (whole.entries.size() > 1) {
        m_attempts[block] = 0;
        const qsizetype half = whole.entries.size() / 2;
        m_info.plan.blocks[block] = blockOf(whole.entries.mid(0, half), whole);
        m_info.plan.blocks.insert(block + 1, blockOf(whole.entries.mid(half), whole));
        m_attempts.insert(block + 1, 0);
        out.retry = true;
        return;
    }
    // One entry left: asked once more, so a single garbled answer never hides it.
    if (++m_attempts[block] <= 1) {
        out.retry = true;
        return;
    }
    m_unavailable.insert(whole.entries.first()->id);
    m_classOf.remove(whole.entries.first()->id);
    ++m_readsThisCycle;   // settled: it counts as read for the cycle
    out.unavailable = whole.entries;
    m_info.plan.blocks.removeAt(block);
    m_attempts.removeAt(block);
}

void DevicePoll::finishCycle(qint64 now, PollOutcome &outcome)
{
    const double cycleMs = double(now - m_cycleStartMs);
    m_info.lastCycleMs = cycleMs;
    outcome.cycleMs = cycleMs;
    for (int c = 0; c < pollClassCount; ++c) {
        if (m_cycleClassAgeMs[c] > 0)
            m_info.classAgeMs[c] = m_cycleClassAgeMs[c];
    }
    m_cycleClassAgeMs = {};
    if (m_cycleShownAgeMs > 0)
        m_info.shownAgeMs = m_cycleShownAgeMs;
    m_cycleShownAgeMs = 0;
    m_cycleStartMs = now;
    m_readsThisCycle = 0;
    ++m_cycle;   // the block that ended this cycle counts for it, not for the next
    m_requestedMs = -1;
}

bool DevicePoll::readThisCycle(const ReadBlock &block) const
{
    // By cycle, not by time: a read answered within the millisecond its cycle began (a
    // gateway on the same host) is in it.
    return std::all_of(block.entries.cbegin(), block.entries.cend(),
                       [this](const RegisterEntry *e) { return m_cycleOf.value(e->id, -1) == m_cycle; });
}

void DevicePoll::markFailure(PollOutcome &outcome)
{
    ++m_consecutiveFailures;
    if (m_info.online && m_consecutiveFailures >= failuresBeforeOffline) {
        m_info.online = false;
        m_info.backoffMs = firstBackoffMs;
        outcome.online = false;
    } else if (!m_info.online) {
        m_info.backoffMs = std::min(maximumBackoffMs, m_info.backoffMs * 2);
    }
}

void DevicePoll::markSuccess(PollOutcome &outcome)
{
    m_consecutiveFailures = 0;
    if (!m_info.online) {
        m_info.online = true;
        m_info.backoffMs = 0;
        outcome.online = true;
        // Back: everything is read at once, as after a reconnect.
        m_doneMs.clear();
    }
}

} // namespace jumo
