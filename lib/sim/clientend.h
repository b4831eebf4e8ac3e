// The master's end of a simulated line (the pty a client opens), watched for the settings
// the client opened it with, so the simulated devices answer only at their own, as the
// manuals say real ones do (no response on a baud rate or format mismatch).
//
// A pseudo-terminal keeps the baud rate, the stop bits and odd parity of a client's
// settings, but Linux clears PARENB on every pty: even parity and none look the same, so a
// simulated device set to 8E1 answers a client at 8N1 too, and one at 8N1 a client at 8E1.
//
// The end is opened before the client opens it (QSerialPort takes it exclusively) and kept
// open, never read from: the client's settings are the tty's, shared by every open file.
#pragma once

#include "protocol/lineformat.h"

#include <QString>

#include <optional>

namespace jumo {

class ClientEnd
{
public:
    ClientEnd() = default;
    ~ClientEnd();
    ClientEnd(const ClientEnd &) = delete;
    ClientEnd &operator=(const ClientEnd &) = delete;

    // False with the reason when the end cannot be opened (it is then not watched).
    bool open(const QString &path, QString *error = nullptr);
    void close();
    bool isOpen() const { return m_fd >= 0; }

    // Whether a device set to this format would understand what the client sends now;
    // nullopt where the client's settings cannot be read (not watched, the end is gone).
    std::optional<bool> understands(const LineFormat &device) const;

private:
    int m_fd = -1;
};

} // namespace jumo
