#include "protocol/rtuframe.h"

#include <QString>

namespace jumo::RtuFrame {

quint16 crc16(QByteArrayView bytes)
{
    quint16 crc = 0xFFFF;
    for (char c : bytes) {
        crc ^= quint8(c);
        for (int i = 0; i < 8; ++i)
            crc = (crc & 1) ? quint16((crc >> 1) ^ 0xA001) : quint16(crc >> 1);
    }
    return crc;
}

QByteArray build(quint8 slave, QByteArrayView pdu)
{
    QByteArray frame;
    frame.reserve(pdu.size() + 3);
    frame.append(char(slave));
    frame.append(pdu.data(), pdu.size());
    const quint16 crc = crc16(frame);
    frame.append(char(crc & 0xFF));
    frame.append(char(crc >> 8));
    return frame;
}

bool hasValidCrc(QByteArrayView frame)
{
    if (frame.size() < 4)
        return false;
    const quint16 crc = crc16(frame.first(frame.size() - 2));
    return quint8(frame[frame.size() - 2]) == (crc & 0xFF) && quint8(frame[frame.size() - 1]) == (crc >> 8);
}

std::optional<int> expectedLength(QByteArrayView head, Direction direction)
{
    if (head.size() < 2)
        return std::nullopt;
    const quint8 function = quint8(head[1]);
    if (function & 0x80)
        return 5;   // address, function | 0x80, exception code, CRC
    switch (function) {
    case 0x03:
    case 0x04:
        if (direction == Direction::Request)
            return 8;
        if (head.size() < 3)
            return std::nullopt;
        return 5 + quint8(head[2]);
    case 0x06:
        return 8;
    case 0x10:
        if (direction == Direction::Response)
            return 8;
        if (head.size() < 7)
            return std::nullopt;
        return 9 + quint8(head[6]);
    default:
        return -1;
    }
}

QByteArray toHex(QByteArrayView bytes)
{
    return QByteArray(bytes.data(), bytes.size()).toHex(' ').toUpper();
}

std::optional<QByteArray> fromHex(QString text)
{
    text.remove(QLatin1Char(' '));
    if (text.size() % 2 != 0)
        return std::nullopt;
    for (QChar c : std::as_const(text)) {
        if (!c.isDigit() && !QStringLiteral("abcdefABCDEF").contains(c))
            return std::nullopt;
    }
    return QByteArray::fromHex(text.toLatin1());
}

} // namespace jumo::RtuFrame
