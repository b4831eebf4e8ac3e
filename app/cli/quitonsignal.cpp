#include "quitonsignal.h"

#include <QCoreApplication>
#include <QSocketNotifier>

#include <csignal>
#include <sys/socket.h>
#include <unistd.h>

namespace jumo {

namespace {

int signalPipe[2] = {-1, -1};

void onSignal(int signal)
{
    // Only async-signal-safe work here: wake the event loop through the socket.
    const char byte = char(signal);
    [[maybe_unused]] const ssize_t written = ::write(signalPipe[0], &byte, 1);
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

void quitOnTerminationSignals()
{
    onTerminationSignals([](int) { QCoreApplication::quit(); });
}

} // namespace jumo
