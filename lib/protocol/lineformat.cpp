#include "protocol/lineformat.h"

namespace jumo {

std::optional<LineFormat> LineFormat::parse(int baudRate, const QString &format)
{
    if (baudRate != 4800 && baudRate != 9600 && baudRate != 19200 && baudRate != 38400)
        return std::nullopt;
    LineFormat f;
    f.baudRate = baudRate;
    const QString upper = format.toUpper();
    if (upper == QLatin1String("8N1")) {
        f.parity = QSerialPort::NoParity;
    } else if (upper == QLatin1String("8E1")) {
        f.parity = QSerialPort::EvenParity;
    } else if (upper == QLatin1String("8O1")) {
        f.parity = QSerialPort::OddParity;
    } else if (upper == QLatin1String("8N2")) {
        f.parity = QSerialPort::NoParity;
        f.stopBits = QSerialPort::TwoStop;
    } else {
        return std::nullopt;
    }
    return f;
}

QString LineFormat::formatName() const
{
    const QChar parityLetter = parity == QSerialPort::EvenParity ? QLatin1Char('E')
            : parity == QSerialPort::OddParity                   ? QLatin1Char('O')
                                                                 : QLatin1Char('N');
    return QStringLiteral("8%1%2").arg(parityLetter).arg(stopBits == QSerialPort::TwoStop ? 2 : 1);
}

int LineFormat::bitsPerCharacter() const
{
    return 1 + 8 + (parity == QSerialPort::NoParity ? 0 : 1) + (stopBits == QSerialPort::TwoStop ? 2 : 1);
}

} // namespace jumo
