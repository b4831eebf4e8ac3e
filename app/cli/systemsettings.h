// What an administrator fixes for every user of the tools in the system-wide
// configuration (jumo/jumo-hmi.conf in the system's configuration folders, read by the
// HMI and jumoctl alike); a command-line option cannot lift it.
#pragma once

#include <QString>

namespace jumo::SystemSettings {

// Read-only mode (control room): nothing is ever written to the devices.
bool readOnly();
// The file these settings come from, for messages.
QString fileName();

} // namespace jumo::SystemSettings
