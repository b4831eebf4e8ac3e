// Quits the application's event loop on SIGINT and SIGTERM, so destructors run and
// helper processes (socat) are stopped and their links removed.
#pragma once

namespace jumo {

void quitOnTerminationSignals();

} // namespace jumo
