// SIGINT, SIGTERM, SIGHUP and SIGPIPE (a closed output) on the event loop: by default
// they quit the application's event loop, so destructors run and helper processes
// (socat) are stopped and their links removed; a command line tool can take them
// instead and end with a summary. SIGXFSZ is ignored: a write past a file size limit
// fails and is reported like a full disk.
#pragma once

#include <QByteArray>
#include <QString>

#include <array>
#include <csignal>
#include <functional>

namespace jumo {

void quitOnTerminationSignals();
// The handler runs on the event loop with the signal number, once per signal.
void onTerminationSignals(const std::function<void(int signal)> &handler);

// The last termination signal that came (0: none), for a command that works to its end
// outside the event loop (jumoctl history): it stops before its next record.
int pendingTerminationSignal();

// What a command says when a signal stopped it: "interrupted: DONE", "terminated: DONE",
// "hangup: DONE", "output closed: DONE".
QString signalSummary(int signal, const QString &done);

// For the life of this object, around a call that blocks, cannot be interrupted and
// holds nothing to save (a database's connect, SQLite's wait for a lock): SIGINT,
// SIGTERM and SIGHUP end the program at once with 128 + the number, after the message
// for that signal on stderr. Only where onTerminationSignals() is in use.
class EndAtOnceOnSignals
{
public:
    explicit EndAtOnceOnSignals(const std::function<QString(int signal)> &message);
    ~EndAtOnceOnSignals();
    EndAtOnceOnSignals(const EndAtOnceOnSignals &) = delete;
    EndAtOnceOnSignals &operator=(const EndAtOnceOnSignals &) = delete;

private:
    bool m_active = false;
    std::array<struct sigaction, 3> m_previous = {};
};

} // namespace jumo
