#include "bus/devicepoll.h"

#include <algorithm>

namespace jumo {

namespace {

constexpr int illegalDataAddress = 2;
constexpr int deviceBusy = 6;

ReadBlock blockOf(QList<const RegisterEntry *> entries)
{
    ReadBlock b;
    b.start = entries.first()->address;
    int last = b.start;
    for (const RegisterEntry *e : entries)
        last = std::max<int>(last, e->lastAddress());
    b.count = quint16(last - b.start + 1);
    b.entries = std::move(entries);
    return b;
}

} // namespace

DevicePoll::DevicePoll(std::shared_ptr<const RegisterMap> map, quint8 address, qint64 now)
{
    m_info.map = std::move(map);
    m_info.address = address;
    m_nextDueMs = now;
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
    m_info.plan = ReadPlanner::plan(*m_info.map, wanted);
    for (const QString &id : std::as_const(missing))
        m_info.plan.errors.prepend(ReadPlanner::tr("'%1' is not an entry of %2").arg(id, m_info.map->family));
    m_blockIndex = -1;
    m_blockAttempts = 0;
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

bool DevicePoll::requestCycle(qint64 now)
{
    if (m_info.plan.blocks.isEmpty())
        return false;
    m_cycleRequested = true;
    if (m_info.online)
        m_nextDueMs = std::min(m_nextDueMs, now);
    return true;
}

bool DevicePoll::ready(qint64 now, bool polling) const
{
    if (m_info.plan.blocks.isEmpty())
        return false;
    if (m_blockIndex >= 0)
        return true;   // a cycle is running: its next block
    if (!m_info.online)
        return now >= m_nextDueMs;   // a probe at the end of the back-off
    return (polling || m_cycleRequested) && now >= m_nextDueMs;
}

qint64 DevicePoll::dueMs(bool polling) const
{
    if (m_info.plan.blocks.isEmpty())
        return -1;
    if (m_blockIndex >= 0)
        return 0;
    if (!m_info.online || polling || m_cycleRequested)
        return m_nextDueMs;
    return -1;
}

std::pair<int, ModbusRequest> DevicePoll::nextBlock(qint64 now)
{
    if (m_blockIndex < 0) {
        m_blockIndex = 0;
        m_cycleStartMs = now;
    }
    const ReadBlock &block = m_info.plan.blocks.at(m_blockIndex);
    return {m_blockIndex, ModbusRequest::read(m_info.address, block.start, block.count)};
}

void DevicePoll::restart(qint64 now)
{
    m_blockIndex = -1;
    m_blockAttempts = 0;
    m_nextDueMs = now;
    m_consecutiveFailures = 0;
}

PollOutcome DevicePoll::finished(int block, const ModbusResult &result, int maxRetries, qint64 now)
{
    PollOutcome out;
    if (block < 0 || block >= m_info.plan.blocks.size() || m_blockIndex != block)
        return out;   // the plan changed while the block was under way
    out.entries = m_info.plan.blocks.at(block).entries;

    // A gateway's 0x0A/0x0B is no answer of the device's: counted as a timeout, shown
    // with its code.
    switch (result.isGatewayException() ? ModbusResult::Status::Timeout : result.status) {
    case ModbusResult::Status::Ok:
        m_blockAttempts = 0;
        out.store = true;
        markSuccess(out);
        break;
    case ModbusResult::Status::Exception:
        if (result.exceptionCode == illegalDataAddress) {
            markSuccess(out);
            isolate(block, out, now);
            return out;
        }
        // It answered: it is there; the block is refused (a busy device is asked again).
        if (result.exceptionCode == deviceBusy && m_info.map->exceptions.contains(deviceBusy)
            && ++m_blockAttempts <= maxRetries) {
            out.retry = true;
            return out;
        }
        m_blockAttempts = 0;
        markSuccess(out);
        out.failure = ReadError::Exception;
        out.exceptionCode = result.exceptionCode;
        break;
    case ModbusResult::Status::LineDown:
        // The bus invalidates everything; the cycle starts again when the line is back.
        m_blockIndex = -1;
        m_blockAttempts = 0;
        return out;
    default:
        if (m_info.online && ++m_blockAttempts <= maxRetries) {
            out.retry = true;   // the device's next turn repeats the block
            return out;
        }
        m_blockAttempts = 0;
        out.failure = result.isGatewayException()                     ? ReadError::Exception
                : result.status == ModbusResult::Status::BadReply ? ReadError::Mismatch
                                                                  : ReadError::Timeout;
        out.exceptionCode = result.isGatewayException() ? result.exceptionCode : 0;
        markFailure(out);
        if (!m_info.online) {
            if (m_blockIndex >= 0)
                finishCycle(now, out);
            m_nextDueMs = now + m_info.backoffMs;
            return out;
        }
        break;
    }
    if (++m_blockIndex >= m_info.plan.blocks.size())
        finishCycle(now, out);
    return out;
}

void DevicePoll::isolate(int block, PollOutcome &out, qint64 now)
{
    // A smaller model lacks an address of the block: halve it until the one entry is
    // found; the rest is read, that entry leaves the plan for the session.
    const ReadBlock whole = m_info.plan.blocks.at(block);
    out.entries.clear();
    if (whole.entries.size() > 1) {
        m_blockAttempts = 0;
        const qsizetype half = whole.entries.size() / 2;
        m_info.plan.blocks[block] = blockOf(whole.entries.mid(0, half));
        m_info.plan.blocks.insert(block + 1, blockOf(whole.entries.mid(half)));
        out.retry = true;
        return;
    }
    // One entry left: asked once more, so a single garbled answer never hides it.
    if (++m_blockAttempts <= 1) {
        out.retry = true;
        return;
    }
    m_blockAttempts = 0;
    m_unavailable.insert(whole.entries.first()->id);
    out.unavailable = whole.entries;
    m_info.plan.blocks.removeAt(block);
    if (m_blockIndex >= m_info.plan.blocks.size())
        finishCycle(now, out);
}

void DevicePoll::finishCycle(qint64 now, PollOutcome &outcome)
{
    const double cycleMs = double(now - m_cycleStartMs);
    m_blockIndex = -1;
    m_cycleRequested = false;
    m_info.lastCycleMs = cycleMs;
    outcome.cycleMs = cycleMs;
    if (m_info.online)
        m_nextDueMs = std::max(m_cycleStartMs + m_info.intervalMs, now);
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
    }
}

} // namespace jumo
