// A line seen from elsewhere: its devices, values and states are what a station published,
// handed in by calls. A DeviceSource like the Bus, so the same models and views show it,
// but with no port, no requests and no write path.
#pragma once

#include "bus/devicesource.h"

#include <QElapsedTimer>
#include <QHash>

namespace jumo {

class MirroredLine final : public DeviceSource
{
    Q_OBJECT

public:
    explicit MirroredLine(const QString &name, QObject *parent = nullptr);

    QString name() const { return m_name; }

    // A device the station reports; returns the known id when it is there already.
    DeviceId addDevice(std::shared_ptr<const RegisterMap> map, quint8 address);
    void removeDevice(DeviceId id);
    // The device of this family at this address, or -1.
    DeviceId device(const QString &family, quint8 address) const;

    // Entries as published, times already on this line's clock (clockMs()). Unknown ids
    // are ignored. One entriesUpdated for the whole set.
    void setEntries(DeviceId id, const QHash<QString, EntryState> &states);
    void setCondition(DeviceId id, const DeviceCondition &condition);
    // The station read the device's current values again at goodMs (this line's clock),
    // unchanged: their age starts again. No signal: nothing but an age changed.
    void setReadTime(DeviceId id, qint64 goodMs);
    // The line's state as the station reports it (or Lost while the station is silent),
    // with the reason in words.
    void setState(LineState state, const QString &reason = {});
    QString stateReason() const { return m_stateReason; }

    QList<DeviceId> devices() const override { return m_order; }
    std::shared_ptr<const RegisterMap> deviceMap(DeviceId id) const override;
    quint8 deviceAddress(DeviceId id) const override;
    QString deviceName(DeviceId id) const override;
    const EntryState *entryState(DeviceId id, const QString &entryId) const override;
    DeviceCondition condition(DeviceId id) const override;
    LineState state() const override { return m_state; }
    // The machine's monotonic clock, as the RemoteStation's: times handed in need no shift.
    qint64 clockMs() const override;

private:
    struct Device
    {
        std::shared_ptr<const RegisterMap> map;
        quint8 address = 0;
        QHash<QString, EntryState> entries;
        DeviceCondition condition;
    };

    QString m_name;
    QHash<DeviceId, Device> m_devices;
    QList<DeviceId> m_order;
    LineState m_state = LineState::Disconnected;
    QString m_stateReason;
};

} // namespace jumo
