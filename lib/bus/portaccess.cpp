#include "bus/portaccess.h"

#include "bus/serialportlist.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <grp.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

namespace jumo {

namespace {

QString groupName(gid_t gid)
{
    const group *g = ::getgrgid(gid);
    return g ? QString::fromLocal8Bit(g->gr_name) : QString::number(gid);
}

QString userName(uid_t uid)
{
    const passwd *p = ::getpwuid(uid);
    return p ? QString::fromLocal8Bit(p->pw_name) : QString::number(uid);
}

bool sessionHasGroup(gid_t gid)
{
    if (::getegid() == gid)
        return true;
    const int count = ::getgroups(0, nullptr);
    QList<gid_t> groups(std::max(count, 0));
    if (count > 0 && ::getgroups(count, groups.data()) == count)
        return groups.contains(gid);
    return false;
}

// The group database lists the user (usermod -aG done), whatever this login has.
bool userListedInGroup(gid_t gid)
{
    const group *g = ::getgrgid(gid);
    const passwd *p = ::getpwuid(::getuid());
    if (!g || !p)
        return false;
    if (p->pw_gid == gid)
        return true;
    for (char **member = g->gr_mem; member && *member; ++member) {
        if (qstrcmp(*member, p->pw_name) == 0)
            return true;
    }
    return false;
}

} // namespace

PortAccess::Problem PortAccess::problemFromErrno(int errorNumber)
{
    switch (errorNumber) {
    case ENOENT:
    case ENODEV:
    case ENXIO:
    case ENOTDIR:
        return Problem::Missing;
    case EACCES:
    case EPERM:
        return Problem::Permission;
    case EBUSY:
        return Problem::Busy;
    default:
        return Problem::None;
    }
}

PortAccess PortAccess::inspect(const QString &port, const QString &procFolder)
{
    PortAccess access;
    access.port = port;
    access.device = SerialPortList::currentDevice(port);
    const QByteArray path = QFile::encodeName(port);
    struct stat st {};
    if (::stat(path.constData(), &st) != 0) {
        access.problem = problemFromErrno(errno);   // EACCES: a folder on the way is closed
        return access;
    }
    access.owner = userName(st.st_uid);
    access.group = groupName(st.st_gid);
    access.mode = st.st_mode & 07777;
    if (::access(path.constData(), R_OK | W_OK) != 0) {
        access.problem = problemFromErrno(errno);
        access.groupMayOpen = (st.st_mode & (S_IRGRP | S_IWGRP)) == (S_IRGRP | S_IWGRP) && st.st_gid != 0;
        access.joinedAfterLogin = userListedInGroup(st.st_gid) && !sessionHasGroup(st.st_gid);
        return access;
    }
    access.holders = holdersOf(access.device, procFolder);
    if (!access.holders.isEmpty())
        access.problem = Problem::Busy;
    return access;
}

QList<PortHolder> PortAccess::holdersOf(const QString &device, const QString &procFolder)
{
    QList<PortHolder> holders;
    const QString self = QString::number(QCoreApplication::applicationPid());
    const QDir proc(procFolder);
    for (const QString &pid : proc.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        bool numeric = false;
        const qint64 number = pid.toLongLong(&numeric);
        if (!numeric || pid == self)
            continue;
        const QDir fds(proc.filePath(pid + QStringLiteral("/fd")));
        const QStringList entries = fds.entryList(QDir::System | QDir::Files | QDir::NoDotAndDotDot);
        const bool holds = std::any_of(entries.cbegin(), entries.cend(), [&](const QString &fd) {
            return QFile::symLinkTarget(fds.filePath(fd)) == device;
        });
        if (!holds)
            continue;
        QFile comm(proc.filePath(pid + QStringLiteral("/comm")));
        QString command;
        if (comm.open(QIODevice::ReadOnly))
            command = QString::fromLocal8Bit(comm.readAll()).trimmed();
        holders << PortHolder{number, command};
    }
    std::sort(holders.begin(), holders.end(), [](const PortHolder &a, const PortHolder &b) { return a.pid < b.pid; });
    return holders;
}

QString PortAccess::message() const
{
    const QString deviceName = device.isEmpty() ? port : device;
    switch (problem) {
    case Problem::None:
        return {};
    case Problem::Missing:
        return tr("there is no such port: is the adapter plugged in? 'jumoctl ports' lists the serial ports.");
    case Problem::Permission:
        if (group.isEmpty())
            return tr("no permission to reach %1.").arg(deviceName);
        if (!groupMayOpen)
            return tr("no permission: %1 (owner %2, group %3, mode %4) is not open to a group. Ask the administrator "
                      "to give it to the group dialout (a udev rule).")
                    .arg(deviceName, owner, group, QString::number(mode, 8).rightJustified(4, QLatin1Char('0')));
        if (joinedAfterLogin)
            return tr("no permission: %1 belongs to the group '%2'; you are in it, but this login started before you "
                      "joined: log out and in again.")
                    .arg(deviceName, group);
        return tr("no permission: %1 belongs to the group '%2'. Join it with 'sudo usermod -aG %2 $USER', then log "
                  "out and in again.")
                .arg(deviceName, group);
    case Problem::Busy: {
        if (holders.isEmpty())
            return tr("%1 is in use by another program (the system does not tell which).").arg(deviceName);
        QStringList names;
        for (const PortHolder &holder : holders)
            names << tr("%1 (PID %2)").arg(holder.command.isEmpty() ? tr("a process") : holder.command).arg(holder.pid);
        return tr("%1 is in use by %2: close it there first.").arg(deviceName, names.join(QStringLiteral(", ")));
    }
    }
    return {};
}

QString PortAccess::problemName() const
{
    switch (problem) {
    case Problem::None:
        return QStringLiteral("ok");
    case Problem::Missing:
        return QStringLiteral("missing");
    case Problem::Permission:
        return QStringLiteral("permission");
    case Problem::Busy:
        return QStringLiteral("busy");
    }
    return {};
}

} // namespace jumo
