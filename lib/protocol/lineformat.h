// Baud rate and character format of a serial line, and the wire time they imply.
#pragma once

#include <QSerialPort>
#include <QString>

#include <optional>

namespace jumo {

struct LineFormat
{
    int baudRate = 19200;
    QSerialPort::Parity parity = QSerialPort::NoParity;
    QSerialPort::StopBits stopBits = QSerialPort::OneStop;

    // Baud 4800/9600/19200/38400 and "8N1", "8E1", "8O1", "8N2"; nullopt otherwise.
    static std::optional<LineFormat> parse(int baudRate, const QString &format);
    QString formatName() const;
    // Start bit, 8 data bits, parity, stop bits.
    int bitsPerCharacter() const;
    // Time on the wire for n bytes, in milliseconds.
    double wireTimeMs(int bytes) const { return 1000.0 * bytes * bitsPerCharacter() / baudRate; }
    // The 3.5-character silence that ends an RTU frame, in milliseconds.
    double frameGapMs() const { return wireTimeMs(1) * 3.5; }

    friend bool operator==(const LineFormat &, const LineFormat &) = default;
};

} // namespace jumo
