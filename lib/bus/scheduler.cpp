#include "bus/scheduler.h"

#include <algorithm>

namespace jumo {

int Scheduler::keepaliveMs(const RegisterMap &map)
{
    return map.protocol.busErrorTimeoutMs ? *map.protocol.busErrorTimeoutMs / 2 : 0;
}

void Scheduler::addDevice(DeviceId id, std::shared_ptr<const RegisterMap> map, quint8 address, qint64 now)
{
    m_devices[id].poll = DevicePoll(std::move(map), address, now);
    if (m_format)
        m_devices[id].poll.setLineFormat(m_format);
}

void Scheduler::removeDevice(DeviceId id)
{
    m_devices.remove(id);
}

const Scheduler::DeviceInfo *Scheduler::device(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? nullptr : &it->poll.info();
}

void Scheduler::setPollEntries(DeviceId id, const QStringList &ids)
{
    if (const auto it = m_devices.find(id); it != m_devices.end())
        it->poll.setPollEntries(ids);
}

void Scheduler::setShown(DeviceId id, const QSet<QString> &entryIds)
{
    if (const auto it = m_devices.find(id); it != m_devices.end())
        it->poll.setShown(entryIds);
}

void Scheduler::setLineFormat(const std::optional<LineFormat> &format)
{
    m_format = format;
    for (Device &d : m_devices)
        d.poll.setLineFormat(format);
}

QHash<QString, PollClass> Scheduler::entryClasses(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? QHash<QString, PollClass>() : it->poll.classes();
}

QSet<QString> Scheduler::shownLive(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? QSet<QString>() : it->poll.shownLive();
}

qint64 Scheduler::shownAllowanceMs(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? 0 : it->poll.shownAllowanceMs();
}

qint64 Scheduler::allowanceMs(DeviceId id, PollClass pollClass) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? 0 : it->poll.allowanceMs(pollClass);
}

void Scheduler::refreshSettings(DeviceId id, qint64 now)
{
    if (const auto it = m_devices.find(id); it != m_devices.end())
        it->poll.refreshSettings(now);
}

void Scheduler::forgetUnavailable(DeviceId id)
{
    if (const auto it = m_devices.find(id); it != m_devices.end())
        it->poll.forgetUnavailable();
}

QStringList Scheduler::pollEntries(DeviceId id) const
{
    return m_devices.value(id).poll.pollEntries();
}

void Scheduler::setPollInterval(DeviceId id, int ms)
{
    if (const auto it = m_devices.find(id); it != m_devices.end())
        it->poll.setInterval(ms);
}

bool Scheduler::requestCycle(DeviceId id, qint64 now)
{
    const auto it = m_devices.find(id);
    return it != m_devices.end() && it->poll.requestCycle(now);
}

QList<const RegisterEntry *> Scheduler::blockEntries(DeviceId id, int block) const
{
    const auto it = m_devices.constFind(id);
    if (it == m_devices.cend() || block < 0 || block >= it->poll.info().plan.blocks.size())
        return {};
    return it->poll.info().plan.blocks.at(block).entries;
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
            m_lastAddressedMs.insert(d.poll.address(), now);
        return;
    }
    m_lastAddressedMs.insert(request.slave, now);
}

void Scheduler::charge(const Turn &turn, qint64 lineMs)
{
    if (turn.kind == Turn::Kind::Poll || turn.kind == Turn::Kind::Keepalive)
        m_pollLineMs += lineMs;
    else if (turn.kind == Turn::Kind::Transaction && turn.transaction->lane() == Transaction::Lane::Job)
        m_jobLineMs += lineMs;
}

void Scheduler::restart(qint64 now)
{
    for (Device &d : m_devices)
        d.poll.restart(now);
    m_lastAddressedMs.clear();
    m_quietUntilMs = 0;
}

Scheduler::Turn Scheduler::devicePollTurn(DeviceId id, Device &d, int block, qint64 now)
{
    Turn turn;
    turn.kind = Turn::Kind::Poll;
    turn.device = id;
    turn.block = block;
    turn.request = d.poll.start(block, now);
    turn.timing = d.poll.map().protocol;
    return turn;
}

std::optional<std::pair<DeviceId, PollChoice>> Scheduler::bestPoll(qint64 now, PollChoice::Tier from)
{
    // The most urgent tier first, within it the most overdue block. Devices equally
    // overdue take turns: the search starts after the device served last.
    QList<DeviceId> order = m_devices.keys();
    const auto split = std::upper_bound(order.begin(), order.end(), m_roundRobin);
    std::rotate(order.begin(), split, order.end());
    std::optional<std::pair<DeviceId, PollChoice>> best;
    for (DeviceId id : std::as_const(order)) {
        const PollChoice c = m_devices[id].poll.choose(now, m_polling, from);
        if (c.block < 0)
            continue;
        if (!best || c.tier < best->second.tier
            || (c.tier == best->second.tier && c.overdueMs > best->second.overdueMs))
            best = std::make_pair(id, c);
    }
    return best;
}

std::optional<Scheduler::Turn> Scheduler::pollTurn(qint64 now)
{
    if (m_devices.isEmpty())
        return std::nullopt;
    std::optional<std::pair<DeviceId, PollChoice>> chosen = bestPoll(now, PollChoice::AlarmDue);
    if (!chosen)
        return std::nullopt;
    if (chosen->second.tier == PollChoice::AlarmDue && m_alarmStreak >= alarmTurnsInARow) {
        // Whatever is most urgent after the alarm words: a setting or probe due, else
        // live values (those on screen first), so a full line of alarm words still
        // refreshes the screen.
        if (std::optional<std::pair<DeviceId, PollChoice>> due = bestPoll(now, PollChoice::Due);
            due && due->second.tier <= PollChoice::Filler)
            chosen = due;
    }
    m_alarmStreak = chosen->second.tier == PollChoice::AlarmDue ? m_alarmStreak + 1 : 0;
    m_roundRobin = chosen->first;
    return devicePollTurn(chosen->first, m_devices[chosen->first], chosen->second.block, now);
}

std::optional<Scheduler::Turn> Scheduler::keepaliveTurn(qint64 now)
{
    // A device becomes urgent a second before its keepalive interval is over: time for
    // the request under way and a quiet gap. The one waiting longest goes first.
    DeviceId chosen = -1;
    qint64 oldest = 0;
    for (auto it = m_devices.begin(); it != m_devices.end(); ++it) {
        const int keepalive = keepaliveMs(it->poll.map());
        if (keepalive <= 0 || !it->poll.isOnline())
            continue;
        const qint64 last = m_lastAddressedMs.value(it->poll.address(), -1);
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
    if (const PollChoice c = d.poll.choose(now, m_polling); c.block >= 0)
        return devicePollTurn(chosen, d, c.block, now);
    for (const RegisterEntry &e : d.poll.map().entries()) {
        if (e.isReadable() && e.alias.isEmpty() && d.poll.isAvailable(e.id)) {
            Turn turn;
            turn.kind = Turn::Kind::Keepalive;
            turn.device = chosen;
            turn.request = ModbusRequest::read(d.poll.address(), e.address, quint16(e.wordCount()));
            turn.timing = d.poll.map().protocol;
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
            const RegisterEntry *entry = it->poll.map().entry(h.key());
            if (!entry)
                continue;
            h->lastSentMs = now;
            Turn turn;
            turn.kind = Turn::Kind::Hold;
            turn.device = it.key();
            turn.holdEntry = h.key();
            turn.request = ModbusRequest::write(it->poll.address(), entry->address, h->words);
            turn.timing = it->poll.map().protocol;
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

    // Jobs and polls take turns while both have work, and the line time is shared: after
    // a long job turn (a timeout), polls go on until they have had as much.
    std::optional<Turn> job = transactionTurn(m_jobs);
    if (job && !m_lastWasJob && m_jobLineMs <= m_pollLineMs) {
        m_lastWasJob = true;
        return *job;
    }
    if (std::optional<Turn> poll = pollTurn(now)) {
        m_lastWasJob = false;
        if (!job)
            m_jobLineMs = m_pollLineMs = 0;
        return *poll;
    }
    m_jobLineMs = m_pollLineMs = 0;
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
        consider(d.poll.dueMs(m_polling));
        for (const Hold &h : d.holds)
            consider(h.lastSentMs + h.intervalMs);
        const int keepalive = keepaliveMs(d.poll.map());
        if (keepalive > 0 && d.poll.isOnline())
            consider(m_lastAddressedMs.value(d.poll.address(), now) + keepalive - keepaliveMarginMs);
    }
    idle.wakeAtMs = wake < 0 ? -1 : std::max(wake, now + 1);
    return idle;
}

Scheduler::PollOutcome Scheduler::pollFinished(const Turn &turn, const ModbusResult &result, int maxRetries, qint64 now)
{
    const auto it = m_devices.find(turn.device);
    // A keepalive only keeps the device talking; a poll or a probe tells whether it is there.
    if (it == m_devices.end() || turn.kind == Turn::Kind::Keepalive)
        return {};
    return it->poll.finished(turn.block, result, maxRetries, now, m_polling);
}

} // namespace jumo
