#include "quitonsignal.h"

#include <QCoreApplication>
#include <QSocketNotifier>

#include <csignal>
#include <sys/socket.h>
#include <unistd.h>

namespace jumo {

namespace {

int signalPipe[2] = {-1, -1};
volatile std::sig_atomic_t pendingSignal = 0;

void onSignal(int signal)
{
    // Only async-signal-safe work here: note it, and wake the event loop through the socket.
    pendingSignal = signal;
    const char byte = char(signal);
    [[maybe_unused]] const ssize_t written = ::write(signalPipe[0], &byte, 1);
}

constexpr std::array<int, 3> endingSignals{SIGINT, SIGTERM, SIGHUP};
// The messages EndAtOnceOnSignals writes, made before: nothing is formatted in a handler.
std::array<QByteArray, 3> endMessages;

void endAtOnce(int signal)
{
    for (size_t i = 0; i < endingSignals.size(); ++i) {
        if (endingSignals[i] == signal) {
            [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, endMessages[i].constData(),
                                                             size_t(endMessages[i].size()));
        }
    }
    ::_exit(128 + signal);
}

} // namespace

void onTerminationSignals(const std::function<void(int)> &handler)
{
    if (signalPipe[0] >= 0 || ::socketpair(AF_UNIX, SOCK_STREAM, 0, signalPipe) != 0)
        return;
    auto *notifier = new QSocketNotifier(signalPipe[1], QSocketNotifier::Read, QCoreApplication::instance());
    QObject::connect(notifier, &QSocketNotifier::activated, QCoreApplication::instance(), [handler] {
        char byte = 0;
        if (::read(signalPipe[1], &byte, 1) == 1)
            handler(int(byte));
    });
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;   // nothing blocks outside the event loop (prompts included)
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
    // A closed terminal and a closed output (| head) end the run as the others do, with
    // its records kept, instead of killing it halfway.
    ::sigaction(SIGHUP, &action, nullptr);
    ::sigaction(SIGPIPE, &action, nullptr);
    // Past a file size limit (ulimit -f) a write fails with EFBIG, which the logs and
    // files report, instead of the signal ending the program without a word.
    ::signal(SIGXFSZ, SIG_IGN);
}

int pendingTerminationSignal()
{
    return pendingSignal;
}

QString signalSummary(int signal, const QString &done)
{
    const char *const text = signal == SIGTERM ? QT_TRANSLATE_NOOP("jumo::Signals", "terminated: %1")
            : signal == SIGHUP                 ? QT_TRANSLATE_NOOP("jumo::Signals", "hangup: %1")
            : signal == SIGPIPE                ? QT_TRANSLATE_NOOP("jumo::Signals", "output closed: %1")
                                               : QT_TRANSLATE_NOOP("jumo::Signals", "interrupted: %1");
    return QCoreApplication::translate("jumo::Signals", text).arg(done);
}

EndAtOnceOnSignals::EndAtOnceOnSignals(const std::function<QString(int)> &message)
{
    if (signalPipe[0] < 0)
        return;   // not a program that takes termination signals (a test running a command)
    m_active = true;
    for (size_t i = 0; i < endingSignals.size(); ++i)
        endMessages[i] = message(endingSignals[i]).toUtf8() + '\n';
    struct sigaction action = {};
    action.sa_handler = endAtOnce;
    sigemptyset(&action.sa_mask);
    for (size_t i = 0; i < endingSignals.size(); ++i)
        ::sigaction(endingSignals[i], &action, &m_previous[i]);
    // One that came just before ends it as well.
    if (const int signal = pendingSignal; signal == SIGINT || signal == SIGTERM || signal == SIGHUP)
        endAtOnce(signal);
}

EndAtOnceOnSignals::~EndAtOnceOnSignals()
{
    if (!m_active)
        return;
    for (size_t i = 0; i < endingSignals.size(); ++i)
        ::sigaction(endingSignals[i], &m_previous[i], nullptr);
}

void quitOnTerminationSignals()
{
    onTerminationSignals([](int) { QCoreApplication::quit(); });
}

} // namespace jumo
