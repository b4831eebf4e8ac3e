#include "bus/scheduler.h"

#include <algorithm>

namespace jumo {

namespace {

constexpr int illegalDataAddress = 2;

} // namespace

int Scheduler::keepaliveMs(const RegisterMap &map)
{
    return map.protocol.busErrorTimeoutMs ? *map.protocol.busErrorTimeoutMs / 2 : 0;
}

void Scheduler::addDevice(DeviceId id, std::shared_ptr<const RegisterMap> map, quint8 address, qint64 now)
{
    Device &d = m_devices[id];
    d.map = std::move(map);
    d.address = address;
    d.nextDueMs = now;
    replan(d);
}

void Scheduler::removeDevice(DeviceId id)
{
    m_devices.remove(id);
}

const Scheduler::DeviceInfo *Scheduler::device(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? nullptr : &*it;
}

void Scheduler::replan(Device &d)
{
    QList<const RegisterEntry *> wanted;
    QStringList missing;
    if (d.pollIds.isEmpty()) {
        for (const RegisterEntry &e : d.map->entries()) {
            if (e.isReadable() && e.alias.isEmpty() && !d.unavailable.contains(e.id))
                wanted << &e;
        }
    } else {
        for (const QString &id : std::as_const(d.pollIds)) {
            if (const RegisterEntry *e = d.map->entry(id); e && !d.unavailable.contains(id))
                wanted << e;
            else if (!e)
                missing << id;
        }
    }
    d.plan = ReadPlanner::plan(*d.map, wanted);
    for (const QString &id : std::as_const(missing))
        d.plan.errors.prepend(ReadPlanner::tr("'%1' is not an entry of %2").arg(id, d.map->family));
    d.blockIndex = -1;
    d.blockAttempts = 0;
}

void Scheduler::setPollEntries(DeviceId id, const QStringList &ids)
{
    if (const auto it = m_devices.find(id); it != m_devices.end()) {
        it->pollIds = ids;
        replan(*it);
    }
}

QStringList Scheduler::pollEntries(DeviceId id) const
{
    return m_devices.value(id).pollIds;
}

void Scheduler::setPollInterval(DeviceId id, int ms)
{
    if (const auto it = m_devices.find(id); it != m_devices.end())
        it->intervalMs = std::max(0, ms);
}

bool Scheduler::requestCycle(DeviceId id, qint64 now)
{
    const auto it = m_devices.find(id);
    if (it == m_devices.end() || it->plan.blocks.isEmpty())
        return false;
    it->cycleRequested = true;
    if (it->online)
        it->nextDueMs = std::min(it->nextDueMs, now);
    return true;
}

QList<const RegisterEntry *> Scheduler::blockEntries(DeviceId id, int block) const
{
    const auto it = m_devices.constFind(id);
    if (it == m_devices.cend() || block < 0 || block >= it->plan.blocks.size())
        return {};
    return it->plan.blocks.at(block).entries;
}

void Scheduler::setHold(DeviceId id, const QString &entryId, const QList<quint16> &words, int intervalMs)
{
    if (const auto it = m_devices.find(id); it != m_devices.end())
        it->holds.insert(entryId, Hold{words, std::max(200, intervalMs), -1});
}

void Scheduler::clearHold(DeviceId id, const QString &entryId)
{
    if (const auto it = m_devices.find(id); it != m_devices.end())
        it->holds.remove(entryId);
}

void Scheduler::enqueue(std::unique_ptr<Transaction> transaction)
{
    (transaction->lane() == Transaction::Lane::Operator ? m_operator : m_jobs).push_back(std::move(transaction));
}

std::vector<std::unique_ptr<Transaction>> Scheduler::takeQueued(const Transaction *inFlight)
{
    std::vector<std::unique_ptr<Transaction>> out;
    for (auto *lane : {&m_operator, &m_jobs}) {
        for (auto it = lane->begin(); it != lane->end();) {
            if (it->get() == inFlight) {
                ++it;
                continue;
            }
            out.push_back(std::move(*it));
            it = lane->erase(it);
        }
    }
    if (m_holding != inFlight)
        m_holding = nullptr;
    return out;
}

std::vector<std::unique_ptr<Transaction>> Scheduler::takeTicket(int ticket, const Transaction *inFlight)
{
    std::vector<std::unique_ptr<Transaction>> out;
    for (auto *lane : {&m_operator, &m_jobs}) {
        for (auto it = lane->begin(); it != lane->end();) {
            if (it->get() == inFlight || (*it)->ticket() != ticket) {
                ++it;
                continue;
            }
            if (m_holding == it->get())
                m_holding = nullptr;
            out.push_back(std::move(*it));
            it = lane->erase(it);
        }
    }
    return out;
}

void Scheduler::forgetDevice(DeviceId id, const Transaction *inFlight)
{
    for (auto *lane : {&m_operator, &m_jobs}) {
        for (const auto &t : *lane) {
            if (t.get() != inFlight)
                t->forgetDevice(id);
        }
        prune(*lane);
    }
}

void Scheduler::prune(std::deque<std::unique_ptr<Transaction>> &lane)
{
    for (auto it = lane.begin(); it != lane.end();) {
        if ((*it)->isFinished()) {
            if (m_holding == it->get())
                m_holding = nullptr;
            it = lane.erase(it);
        } else {
            ++it;
        }
    }
}

void Scheduler::transactionFinished(Transaction *transaction)
{
    m_holding = transaction && !transaction->isFinished() && transaction->holdsLine() ? transaction : nullptr;
    prune(m_operator);
    prune(m_jobs);
}

void Scheduler::sent(const ModbusRequest &request, qint64 now)
{
    if (request.isBroadcast()) {
        // A broadcast is a telegram for every device.
        for (Device &d : m_devices)
            m_lastAddressedMs.insert(d.address, now);
        return;
    }
    m_lastAddressedMs.insert(request.slave, now);
}

void Scheduler::restart(qint64 now)
{
    for (Device &d : m_devices) {
        d.blockIndex = -1;
        d.blockAttempts = 0;
        d.nextDueMs = now;
        d.consecutiveFailures = 0;
    }
    m_lastAddressedMs.clear();
    m_quietUntilMs = 0;
}

bool Scheduler::pollReady(const Device &d, qint64 now) const
{
    if (d.plan.blocks.isEmpty())
        return false;
    if (d.blockIndex >= 0)
        return true;   // a cycle is running: its next block
    if (!d.online)
        return now >= d.nextDueMs;   // a probe at the end of the back-off
    return (m_polling || d.cycleRequested) && now >= d.nextDueMs;
}

qint64 Scheduler::pollDueMs(const Device &d) const
{
    if (d.plan.blocks.isEmpty())
        return -1;
    if (d.blockIndex >= 0)
        return 0;
    if (!d.online || m_polling || d.cycleRequested)
        return d.nextDueMs;
    return -1;
}

Scheduler::Turn Scheduler::devicePollTurn(DeviceId id, Device &d, qint64 now)
{
    if (d.blockIndex < 0) {
        d.blockIndex = 0;
        d.cycleStartMs = now;
    }
    const ReadBlock &block = d.plan.blocks.at(d.blockIndex);
    Turn turn;
    turn.kind = Turn::Kind::Poll;
    turn.device = id;
    turn.block = d.blockIndex;
    turn.request = ModbusRequest::read(d.address, block.start, block.count);
    turn.timing = d.map->protocol;
    return turn;
}

std::optional<Scheduler::Turn> Scheduler::pollTurn(qint64 now)
{
    if (m_devices.isEmpty())
        return std::nullopt;
    // Round-robin by request: each device in turn gets one block, so a long cycle of one
    // device never holds up the others.
    QList<DeviceId> order = m_devices.keys();
    const auto split = std::upper_bound(order.begin(), order.end(), m_roundRobin);
    std::rotate(order.begin(), split, order.end());
    for (DeviceId id : std::as_const(order)) {
        Device &d = m_devices[id];
        if (!pollReady(d, now))
            continue;
        m_roundRobin = id;
        return devicePollTurn(id, d, now);
    }
    return std::nullopt;
}

std::optional<Scheduler::Turn> Scheduler::keepaliveTurn(qint64 now)
{
    // A device becomes urgent a second before its keepalive interval is over: time for
    // the request under way and a quiet gap. The one waiting longest goes first.
    DeviceId chosen = -1;
    qint64 oldest = 0;
    for (auto it = m_devices.begin(); it != m_devices.end(); ++it) {
        const int keepalive = keepaliveMs(*it->map);
        if (keepalive <= 0 || !it->online)
            continue;
        const qint64 last = m_lastAddressedMs.value(it->address, -1);
        if (last >= 0 && now - last < keepalive - keepaliveMarginMs)
            continue;
        if (chosen < 0 || last < oldest) {
            chosen = it.key();
            oldest = last;
        }
    }
    if (chosen < 0)
        return std::nullopt;
    Device &d = m_devices[chosen];
    // Its next poll block when one is due: no extra request. Otherwise (a long poll
    // interval, polling off) the smallest read of anything readable keeps it talking.
    if (pollReady(d, now))
        return devicePollTurn(chosen, d, now);
    for (const RegisterEntry &e : d.map->entries()) {
        if (e.isReadable() && e.alias.isEmpty() && !d.unavailable.contains(e.id)) {
            Turn turn;
            turn.kind = Turn::Kind::Keepalive;
            turn.device = chosen;
            turn.request = ModbusRequest::read(d.address, e.address, quint16(e.wordCount()));
            turn.timing = d.map->protocol;
            return turn;
        }
    }
    return std::nullopt;
}

std::optional<Scheduler::Turn> Scheduler::holdTurn(qint64 now)
{
    for (auto it = m_devices.begin(); it != m_devices.end(); ++it) {
        for (auto h = it->holds.begin(); h != it->holds.end(); ++h) {
            if (h->lastSentMs >= 0 && now - h->lastSentMs < h->intervalMs)
                continue;
            const RegisterEntry *entry = it->map->entry(h.key());
            if (!entry)
                continue;
            h->lastSentMs = now;
            Turn turn;
            turn.kind = Turn::Kind::Hold;
            turn.device = it.key();
            turn.holdEntry = h.key();
            turn.request = ModbusRequest::write(it->address, entry->address, h->words);
            turn.timing = it->map->protocol;
            return turn;
        }
    }
    return std::nullopt;
}

std::optional<Scheduler::Turn> Scheduler::transactionTurn(std::deque<std::unique_ptr<Transaction>> &lane)
{
    prune(lane);
    for (const auto &t : lane) {
        if (const std::optional<ModbusRequest> request = t->nextRequest()) {
            Turn turn;
            turn.kind = Turn::Kind::Transaction;
            turn.transaction = t.get();
            turn.device = t->device();
            turn.request = *request;
            turn.timing = t->timing();
            return turn;
        }
    }
    return std::nullopt;
}

Scheduler::Turn Scheduler::next(qint64 now)
{
    Turn idle;
    if (now < m_quietUntilMs) {
        idle.wakeAtMs = m_quietUntilMs;
        return idle;
    }
    if (m_holding && !m_holding->isFinished()) {
        if (const std::optional<ModbusRequest> request = m_holding->nextRequest()) {
            Turn turn;
            turn.kind = Turn::Kind::Transaction;
            turn.transaction = m_holding;
            turn.device = m_holding->device();
            turn.request = *request;
            turn.timing = m_holding->timing();
            return turn;
        }
    }
    m_holding = nullptr;
    if (std::optional<Turn> t = keepaliveTurn(now))
        return *t;
    if (std::optional<Turn> t = transactionTurn(m_operator))
        return *t;
    if (std::optional<Turn> t = holdTurn(now))
        return *t;

    // Jobs and polls take turns while both have work.
    std::optional<Turn> job = transactionTurn(m_jobs);
    if (job && (m_lastWasJob == false)) {
        m_lastWasJob = true;
        return *job;
    }
    if (std::optional<Turn> poll = pollTurn(now)) {
        m_lastWasJob = false;
        return *poll;
    }
    if (job) {
        m_lastWasJob = true;
        return *job;
    }

    // Nothing to do now: when will there be?
    qint64 wake = -1;
    auto consider = [&wake](qint64 due) {
        if (due >= 0)
            wake = wake < 0 ? due : std::min(wake, due);
    };
    for (const Device &d : std::as_const(m_devices)) {
        consider(pollDueMs(d));
        for (const Hold &h : d.holds)
            consider(h.lastSentMs + h.intervalMs);
        const int keepalive = keepaliveMs(*d.map);
        if (keepalive > 0 && d.online)
            consider(m_lastAddressedMs.value(d.address, now) + keepalive - keepaliveMarginMs);
    }
    idle.wakeAtMs = wake < 0 ? -1 : std::max(wake, now + 1);
    return idle;
}

Scheduler::PollOutcome Scheduler::pollFinished(const Turn &turn, const ModbusResult &result, int maxRetries, qint64 now)
{
    PollOutcome out;
    const auto it = m_devices.find(turn.device);
    if (it == m_devices.end())
        return out;
    Device &d = *it;
    if (turn.kind == Turn::Kind::Keepalive) {
        // Only to keep the device talking; a poll or a probe tells whether it is there.
        return out;
    }
    if (turn.block < 0 || turn.block >= d.plan.blocks.size() || d.blockIndex != turn.block)
        return out;   // the plan changed while the block was under way
    const ReadBlock block = d.plan.blocks.at(turn.block);
    out.entries = block.entries;

    if (result.status == ModbusResult::Status::Ok) {
        d.blockAttempts = 0;
        out.store = true;
        markSuccess(d, out);
    } else if (result.status == ModbusResult::Status::Exception && result.exceptionCode == illegalDataAddress) {
        // A smaller model lacks an address of the block: halve it until the one entry is
        // found; the rest is read, that entry leaves the plan for the session.
        markSuccess(d, out);
        if (block.entries.size() > 1) {
            d.blockAttempts = 0;
            const qsizetype half = block.entries.size() / 2;
            auto makeBlock = [](QList<const RegisterEntry *> entries) {
                ReadBlock b;
                b.start = entries.first()->address;
                int last = b.start;
                for (const RegisterEntry *e : entries)
                    last = std::max<int>(last, e->lastAddress());
                b.count = quint16(last - b.start + 1);
                b.entries = std::move(entries);
                return b;
            };
            d.plan.blocks[turn.block] = makeBlock(block.entries.mid(0, half));
            d.plan.blocks.insert(turn.block + 1, makeBlock(block.entries.mid(half)));
            out.entries.clear();
            out.retry = true;
            return out;
        }
        // One entry left: asked once more, so a single garbled answer never hides it.
        if (++d.blockAttempts <= 1) {
            out.entries.clear();
            out.retry = true;
            return out;
        }
        d.blockAttempts = 0;
        d.unavailable.insert(block.entries.first()->id);
        out.unavailable = block.entries;
        out.entries.clear();
        d.plan.blocks.removeAt(turn.block);
        if (d.blockIndex >= d.plan.blocks.size())
            finishCycle(d, now, out);
        return out;
    } else if (result.status == ModbusResult::Status::Exception) {
        // It answered: it is there; the block is refused.
        const bool busy = result.exceptionCode == 6 && d.map->exceptions.contains(6);
        if (busy && ++d.blockAttempts <= maxRetries) {
            out.retry = true;
            return out;
        }
        d.blockAttempts = 0;
        markSuccess(d, out);
        out.failure = ReadError::Exception;
        out.exceptionCode = result.exceptionCode;
    } else if (result.status == ModbusResult::Status::LineDown) {
        // The bus invalidates everything; the cycle starts again when the line is back.
        d.blockIndex = -1;
        d.blockAttempts = 0;
        return out;
    } else {
        if (d.online && ++d.blockAttempts <= maxRetries) {
            out.retry = true;   // the device's next turn repeats the block
            return out;
        }
        d.blockAttempts = 0;
        out.failure = result.status == ModbusResult::Status::BadReply ? ReadError::Mismatch : ReadError::Timeout;
        markFailure(d, out);
        if (!d.online) {
            if (d.blockIndex >= 0)
                finishCycle(d, now, out);
            d.nextDueMs = now + d.backoffMs;
            return out;
        }
    }
    if (++d.blockIndex >= d.plan.blocks.size())
        finishCycle(d, now, out);
    return out;
}

void Scheduler::finishCycle(Device &d, qint64 now, PollOutcome &outcome)
{
    const double cycleMs = double(now - d.cycleStartMs);
    d.blockIndex = -1;
    d.cycleRequested = false;
    d.lastCycleMs = cycleMs;
    outcome.cycleMs = cycleMs;
    if (d.online)
        d.nextDueMs = std::max(d.cycleStartMs + d.intervalMs, now);
}

void Scheduler::markFailure(Device &d, PollOutcome &outcome)
{
    ++d.consecutiveFailures;
    if (d.online && d.consecutiveFailures >= failuresBeforeOffline) {
        d.online = false;
        d.backoffMs = firstBackoffMs;
        outcome.online = false;
    } else if (!d.online) {
        d.backoffMs = std::min(maximumBackoffMs, d.backoffMs * 2);
    }
}

void Scheduler::markSuccess(Device &d, PollOutcome &outcome)
{
    d.consecutiveFailures = 0;
    if (!d.online) {
        d.online = true;
        d.backoffMs = 0;
        outcome.online = true;
    }
}

} // namespace jumo
