#include "bus/valuestore.h"

#include <algorithm>

namespace jumo {

void ValueStore::addDevice(DeviceId id, std::shared_ptr<const RegisterMap> map)
{
    Device &d = m_devices[id];
    d.map = std::move(map);
}

void ValueStore::removeDevice(DeviceId id)
{
    m_devices.remove(id);
}

const EntryState *ValueStore::state(DeviceId id, const QString &entryId) const
{
    const auto d = m_devices.constFind(id);
    if (d == m_devices.cend())
        return nullptr;
    const auto v = d->values.constFind(entryId);
    return v == d->values.cend() ? nullptr : &*v;
}

const DeviceStatistics *ValueStore::statistics(DeviceId id) const
{
    const auto d = m_devices.constFind(id);
    return d == m_devices.cend() ? nullptr : &d->stats;
}

DeviceStatistics *ValueStore::statistics(DeviceId id)
{
    const auto d = m_devices.find(id);
    return d == m_devices.end() ? nullptr : &d->stats;
}

void ValueStore::setAllowance(DeviceId id, qint64 ms)
{
    if (const auto d = m_devices.find(id); d != m_devices.end())
        d->allowanceMs.fill(std::max<qint64>(1, ms));
}

void ValueStore::setAllowance(DeviceId id, PollClass pollClass, qint64 ms)
{
    if (const auto d = m_devices.find(id); d != m_devices.end())
        d->allowanceMs[size_t(pollClass)] = std::max<qint64>(1, ms);
}

void ValueStore::setClasses(DeviceId id, const QHash<QString, PollClass> &classes)
{
    if (const auto d = m_devices.find(id); d != m_devices.end())
        d->classes = classes;
}

void ValueStore::setShownLive(DeviceId id, const QSet<QString> &entryIds, qint64 ms)
{
    if (const auto d = m_devices.find(id); d != m_devices.end()) {
        d->shownLive = entryIds;
        d->shownAllowanceMs = ms;
    }
}

qint64 ValueStore::allowance(DeviceId id, PollClass pollClass) const
{
    const auto d = m_devices.constFind(id);
    return d == m_devices.cend() ? 0 : d->allowanceMs[size_t(pollClass)];
}

qint64 ValueStore::allowance(DeviceId id, const QString &entryId) const
{
    const auto d = m_devices.constFind(id);
    return d == m_devices.cend() ? 0 : d->allowanceOf(entryId);
}

QStringList ValueStore::store(DeviceId id, const QList<const RegisterEntry *> &entries, quint16 start,
                              const QList<quint16> &words, qint64 now)
{
    QStringList updated;
    const auto d = m_devices.find(id);
    if (d == m_devices.end())
        return updated;
    for (const RegisterEntry *e : entries) {
        const int offset = e->address - start;
        if (offset < 0 || offset + e->wordCount() > words.size())
            continue;   // not inside the block: never decode a neighbour's words
        EntryState &s = d->values[e->id];
        s.words = words.mid(offset, e->wordCount());
        s.value = ValueCodec::decode(*e, *d->map, s.words);
        s.validity = Validity::Current;
        s.error = ReadError::None;
        s.exceptionCode = 0;
        s.updatedMs = now;
        s.goodMs = now;
        d->readAllowanceMs.insert(e->id, d->classAllowanceOf(e->id));
        updated << e->id;
    }
    return updated;
}

QStringList ValueStore::fail(DeviceId id, const QList<const RegisterEntry *> &entries, ReadError error,
                             int exceptionCode, qint64 now)
{
    QStringList updated;
    const auto d = m_devices.find(id);
    if (d == m_devices.end())
        return updated;
    for (const RegisterEntry *e : entries) {
        EntryState &s = d->values[e->id];
        s.validity = Validity::Unknown;
        s.error = error;
        s.exceptionCode = exceptionCode;
        s.updatedMs = now;
        updated << e->id;
    }
    return updated;
}

QStringList ValueStore::invalidate(DeviceId id, ReadError reason, qint64 now)
{
    QStringList updated;
    const auto d = m_devices.find(id);
    if (d == m_devices.end())
        return updated;
    // Entries not read yet (a setting waits its minute) are unknown for this reason too.
    for (auto it = d->classes.cbegin(); it != d->classes.cend(); ++it) {
        if (!d->values.contains(it.key()))
            d->values.insert(it.key(), EntryState{});
    }
    for (auto it = d->values.begin(); it != d->values.end(); ++it) {
        // An entry the device does not have stays so; everything else is unknown now.
        if (it->error == ReadError::NotAvailable || (it->validity == Validity::Unknown && it->error == reason))
            continue;
        it->validity = Validity::Unknown;
        it->error = reason;
        it->exceptionCode = 0;
        it->updatedMs = now;
        updated << it.key();
    }
    return updated;
}

QStringList ValueStore::sweep(DeviceId id, qint64 now)
{
    QStringList updated;
    const auto d = m_devices.find(id);
    if (d == m_devices.end())
        return updated;
    for (auto it = d->values.begin(); it != d->values.end(); ++it) {
        if (it->validity == Validity::Current && now - it->goodMs > d->allowanceOf(it.key())) {
            it->validity = Validity::Stale;
            it->updatedMs = now;
            updated << it.key();
        }
    }
    return updated;
}

qint64 ValueStore::nextStaleMs(DeviceId id) const
{
    const auto d = m_devices.constFind(id);
    if (d == m_devices.cend())
        return -1;
    qint64 next = -1;
    for (auto it = d->values.cbegin(); it != d->values.cend(); ++it) {
        const EntryState &s = *it;
        if (s.validity != Validity::Current)
            continue;
        const qint64 due = s.goodMs + d->allowanceOf(it.key()) + 1;
        next = next < 0 ? due : std::min(next, due);
    }
    return next;
}

void ValueStore::count(DeviceId device, const ModbusResult &result, double roundTripMs)
{
    DeviceStatistics *s = statistics(device);
    if (!s)
        return;
    s->crcErrors += result.crcErrors;
    s->mismatches += result.mismatches;
    switch (result.status) {
    case ModbusResult::Status::Ok:
        s->addRoundTrip(roundTripMs);
        break;
    case ModbusResult::Status::Exception:
        ++s->exceptions[result.exceptionCode];
        s->addRoundTrip(roundTripMs);
        break;
    case ModbusResult::Status::Timeout:
        ++s->timeouts;
        break;
    case ModbusResult::Status::BadReply:
        ++s->mismatches;
        break;
    case ModbusResult::Status::LineDown:
        break;
    }
}

} // namespace jumo
