// What an administrator fixes for every user of the tools in the system-wide
// configuration (jumo/jumo-hmi.conf in the system's configuration folders, read by the
// HMI and jumoctl alike); a command-line option cannot lift it. Read so that a slip
// fails closed: a readOnly key in another case counts, and a file that is there but
// cannot be read means read-only.
#pragma once

#include <QString>
#include <QStringList>

namespace jumo::SystemSettings {

// Read-only mode (control room): nothing is ever written to the devices. Set by any key
// that reads readOnly ignoring case and '_' or '-' (readonly, ReadOnly, read_only) with
// a value other than false, 0, no or off, or by a file that cannot be read.
bool readOnly();
// What is wrong with the file, one sentence each (unknown keys, a key taken as
// readOnly, a value that is no boolean, a file that cannot be read), for a warning.
QStringList warnings();
// The file these settings come from, for messages.
QString fileName();

} // namespace jumo::SystemSettings
