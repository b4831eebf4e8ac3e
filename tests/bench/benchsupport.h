// What the benchmark programs share: waiting on the event loop, and a process's CPU time
// and memory from /proc.
#pragma once

#include <QByteArray>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QList>
#include <QTimer>

#include <cstdio>
#include <functional>
#include <unistd.h>

namespace jumo::bench {

// Figures of an unoptimised build (.ci/build's Check type, made for the tests) are not the
// product's: said on stderr before anything is measured.
inline void warnIfUnoptimised()
{
#ifndef __OPTIMIZE__
    std::fputs("warning: this benchmark was built without optimisation (build type Check?); for figures, build "
               "RelWithDebInfo or Release\n",
               stderr);
#endif
}

// Runs the event loop for this long.
inline void spin(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

// Runs the event loop until the condition holds (true) or the time is up (false).
inline bool waitUntil(const std::function<bool()> &condition, int timeoutMs)
{
    QElapsedTimer timer;
    timer.start();
    while (!condition()) {
        if (timer.elapsed() > timeoutMs)
            return false;
        spin(5);
    }
    return true;
}

// User and system CPU seconds of a process (0: this one); -1 when it is gone.
inline double cpuSeconds(qint64 pid = 0)
{
    QFile stat(pid > 0 ? QStringLiteral("/proc/%1/stat").arg(pid) : QStringLiteral("/proc/self/stat"));
    if (!stat.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray line = stat.readAll();
    // Fields after the name: the state is index 0, utime 11, stime 12.
    const QList<QByteArray> fields = line.mid(line.lastIndexOf(')') + 2).split(' ');
    return (fields.value(11).toDouble() + fields.value(12).toDouble()) / double(sysconf(_SC_CLK_TCK));
}

// A memory field of /proc/PID/status in KiB ("VmRSS", "VmHWM"; pid 0: this process);
// -1 when it is gone.
inline double statusKiB(const QByteArray &field, qint64 pid = 0)
{
    QFile status(pid > 0 ? QStringLiteral("/proc/%1/status").arg(pid) : QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith(field + ':'))
            return line.mid(field.size() + 1).trimmed().split(' ').first().toDouble();
    }
    return -1;
}

} // namespace jumo::bench
