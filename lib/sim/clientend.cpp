#include "sim/clientend.h"

#include <QCoreApplication>
#include <QFile>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace jumo {

namespace {

speed_t speedOf(int baud)
{
    switch (baud) {
    case 1200:
        return B1200;
    case 2400:
        return B2400;
    case 4800:
        return B4800;
    case 9600:
        return B9600;
    case 19200:
        return B19200;
    case 38400:
        return B38400;
    case 57600:
        return B57600;
    case 115200:
        return B115200;
    default:
        return B0;
    }
}

} // namespace

ClientEnd::~ClientEnd()
{
    close();
}

bool ClientEnd::open(const QString &path, QString *error)
{
    close();
    m_fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (m_fd >= 0 && ::isatty(m_fd))
        return true;
    if (error)
        *error = m_fd >= 0 ? QCoreApplication::translate("jumo::ClientEnd", "not a terminal") : QString::fromLocal8Bit(std::strerror(errno));
    close();
    return false;
}

void ClientEnd::close()
{
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = -1;
}

std::optional<bool> ClientEnd::understands(const LineFormat &device) const
{
    termios client{};
    if (m_fd < 0 || ::tcgetattr(m_fd, &client) != 0)
        return std::nullopt;
    if (cfgetospeed(&client) != speedOf(device.baudRate))
        return false;
    if (bool(client.c_cflag & CSTOPB) != (device.stopBits == QSerialPort::TwoStop))
        return false;
    // PARODD survives on a pty, PARENB does not: odd parity is seen, even is taken for none.
    const bool clientOdd = client.c_cflag & PARODD;
    return clientOdd == (device.parity == QSerialPort::OddParity);
}

} // namespace jumo
