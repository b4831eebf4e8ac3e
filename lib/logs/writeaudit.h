// The write audit log: every write asked for on a bus, with the value it replaces, the
// value asked for and what became of it (read-only refusals included), in an EventLog.
#pragma once

#include "bus/bus.h"
#include "logs/eventlog.h"

#include <QHash>

namespace jumo {

class WriteAudit : public QObject
{
    Q_OBJECT

public:
    WriteAudit(Bus *bus, EventLog *log, QObject *parent = nullptr);

    static QStringList columns();
    // Put before each device's name ("line2/" makes "line2/ipc300@1") where several lines
    // of one station share the log; empty (the default): "ipc300@1".
    void setDevicePrefix(const QString &prefix) { m_prefix = prefix; }

private:
    struct Pending
    {
        QString device;
        QString entry;
        QString value;
        QString previous;
    };

    EventLog *m_log;
    QString m_prefix;
    QHash<int, Pending> m_pending;
};

} // namespace jumo
