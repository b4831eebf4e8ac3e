// SIGINT, SIGTERM, SIGHUP and SIGPIPE (a closed output) on the event loop: by default
// they quit the application's event loop, so destructors run and helper processes
// (socat) are stopped and their links removed; a command line tool can take them
// instead and end with a summary. SIGXFSZ is ignored: a write past a file size limit
// fails and is reported like a full disk.
#pragma once

#include <functional>

namespace jumo {

void quitOnTerminationSignals();
// The handler runs on the event loop with the signal number, once per signal.
void onTerminationSignals(const std::function<void(int signal)> &handler);

} // namespace jumo
