#include "bus/mirroredline.h"

#include <atomic>
#include <chrono>
#include <limits>

namespace jumo {

MirroredLine::MirroredLine(const QString &name, QObject *parent) : DeviceSource(parent), m_name(name)
{
}

DeviceId MirroredLine::addDevice(std::shared_ptr<const RegisterMap> map, quint8 address)
{
    if (!map)
        return -1;
    if (const DeviceId known = device(map->family, address); known >= 0)
        return known;
    // Ids are unique in the process, as the Bus's are; the Bus counts from 1 upwards, a
    // mirror from the top down, so the two can never meet.
    static std::atomic<DeviceId> nextId{std::numeric_limits<DeviceId>::max()};
    const DeviceId id = nextId--;
    Device d;
    d.map = std::move(map);
    d.address = address;
    for (const RegisterEntry &e : d.map->entries()) {
        if (e.isReadable())
            d.entries.insert(e.id, EntryState{});
    }
    d.condition.state = DeviceCondition::State::Disconnected;
    d.condition.since = QDateTime::currentDateTime();
    m_devices.insert(id, std::move(d));
    m_order.append(id);
    return id;
}

void MirroredLine::removeDevice(DeviceId id)
{
    m_devices.remove(id);
    m_order.removeAll(id);
}

DeviceId MirroredLine::device(const QString &family, quint8 address) const
{
    for (auto it = m_devices.cbegin(); it != m_devices.cend(); ++it) {
        if (it->address == address && it->map->family == family)
            return it.key();
    }
    return -1;
}

void MirroredLine::setEntries(DeviceId id, const QHash<QString, EntryState> &states)
{
    auto device = m_devices.find(id);
    if (device == m_devices.end())
        return;
    QStringList changed;
    for (auto it = states.cbegin(); it != states.cend(); ++it) {
        auto entry = device->entries.find(it.key());
        if (entry == device->entries.end())
            continue;
        *entry = it.value();
        changed.append(it.key());
    }
    if (!changed.isEmpty())
        emit entriesUpdated(id, changed);
}

void MirroredLine::setCondition(DeviceId id, const DeviceCondition &condition)
{
    auto device = m_devices.find(id);
    if (device == m_devices.end())
        return;
    if (device->condition.state == condition.state && device->condition.detail == condition.detail)
        return;
    device->condition = condition;
    emit conditionChanged(id, condition);
}

void MirroredLine::setReadTime(DeviceId id, qint64 goodMs)
{
    auto device = m_devices.find(id);
    if (device == m_devices.end())
        return;
    for (EntryState &entry : device->entries) {
        if (entry.validity == Validity::Current && entry.goodMs < goodMs)
            entry.goodMs = goodMs;
    }
}

void MirroredLine::setState(LineState state, const QString &reason)
{
    // A new reason for the same state is news too ("not online yet" becomes the station's
    // own word for the loss).
    if (state == m_state && reason == m_stateReason)
        return;
    m_state = state;
    m_stateReason = reason;
    emit stateChanged(state);
}

qint64 MirroredLine::clockMs() const
{
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
            .count();
}

std::shared_ptr<const RegisterMap> MirroredLine::deviceMap(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? nullptr : it->map;
}

quint8 MirroredLine::deviceAddress(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? 0 : it->address;
}

QString MirroredLine::deviceName(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? QString() : QStringLiteral("%1@%2").arg(it->map->family).arg(it->address);
}

const EntryState *MirroredLine::entryState(DeviceId id, const QString &entryId) const
{
    const auto it = m_devices.constFind(id);
    if (it == m_devices.cend())
        return nullptr;
    const auto entry = it->entries.constFind(entryId);
    return entry == it->entries.cend() ? nullptr : &*entry;
}

DeviceCondition MirroredLine::condition(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? DeviceCondition{} : it->condition;
}

} // namespace jumo
