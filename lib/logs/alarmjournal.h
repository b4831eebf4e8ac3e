// The alarm journal: every alarm, warning and status bit of every polled device that
// sets or clears, and every loss and return of communication with a device, with time
// and device, in an EventLog that survives restarts.
#pragma once

#include "bus/devicesource.h"
#include "logs/eventlog.h"

#include <QHash>

namespace jumo {

class AlarmJournal : public QObject
{
    Q_OBJECT

public:
    AlarmJournal(const DeviceSource *devices, EventLog *log, QObject *parent = nullptr);

    static QStringList columns();
    // Put before each device's name ("line2/" makes "line2/ipc300@1") where several lines
    // of one station share the journal; empty (the default): "ipc300@1".
    void setDevicePrefix(const QString &prefix) { m_prefix = prefix; }

private:
    void onEntriesUpdated(DeviceId device, const QStringList &ids);
    void onConditionChanged(DeviceId device, const DeviceCondition &condition);

    const DeviceSource *m_devices;
    EventLog *m_log;
    QString m_prefix;
    QHash<QString, quint32> m_last;   // "device id/entry" -> raw value last seen
    QHash<DeviceId, DeviceCondition::State> m_condition;
};

} // namespace jumo
