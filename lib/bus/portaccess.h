// Why a serial port cannot be opened, in words a user can act on: the adapter is not
// there, the device's group and the command to join it, or the process holding it.
// inspect() asks the system (stat, access, /proc); the wording depends on the fields
// alone, so any case can be composed and tested without the system.
#pragma once

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace jumo {

struct PortHolder
{
    qint64 pid = 0;
    QString command;   // /proc/PID/comm
};

struct PortAccess
{
    Q_DECLARE_TR_FUNCTIONS(jumo::PortAccess)

public:
    enum class Problem { None, Missing, Permission, Busy };

    QString port;     // as the user names it (a by-id link, say)
    QString device;   // what it leads to now
    Problem problem = Problem::None;
    // Permission: the device's owner, group and mode, and whether joining the group
    // helps (it grants read and write) or is done but this login predates it.
    QString owner;
    QString group;
    uint mode = 0;
    bool groupMayOpen = true;
    bool joinedAfterLogin = false;
    QList<PortHolder> holders;   // Busy: the processes that have the device open, if known

    // What the port's state is now; any process but this one counts as a holder.
    static PortAccess inspect(const QString &port, const QString &procFolder = QStringLiteral("/proc"));
    // The processes (but this one) with the device open, as far as /proc shows them:
    // all of them for root, one's own processes otherwise.
    static QList<PortHolder> holdersOf(const QString &device, const QString &procFolder = QStringLiteral("/proc"));
    // The problem an errno of open(), stat() or access() names (None when it names none of them).
    static Problem problemFromErrno(int errorNumber);

    // The reason and what to do, to follow "cannot open PORT: "; empty for None.
    QString message() const;
    // ok, missing, permission or busy (jumoctl ports --json).
    QString problemName() const;
};

} // namespace jumo
