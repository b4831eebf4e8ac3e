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

private:
    struct Pending
    {
        QString device;
        QString entry;
        QString value;
        QString previous;
    };

    EventLog *m_log;
    QHash<int, Pending> m_pending;
};

} // namespace jumo
