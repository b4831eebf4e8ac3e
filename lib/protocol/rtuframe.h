// Modbus RTU framing: CRC16, building and checking frames, and the expected length of a
// frame from its first bytes (the way a receiver finds the end of a reply).
#pragma once

#include <QByteArray>
#include <QByteArrayView>

#include <optional>

namespace jumo {

namespace RtuFrame {

quint16 crc16(QByteArrayView bytes);

// Appends the CRC (low byte first) to address + PDU.
QByteArray build(quint8 slave, QByteArrayView pdu);
// True when the frame is at least 4 bytes and its last two bytes are its CRC.
bool hasValidCrc(QByteArrayView frame);

enum class Direction { Request, Response };
// Total frame length (address .. CRC) once enough bytes are known to tell it, else
// nullopt; -1 when the function code is not one this project speaks.
std::optional<int> expectedLength(QByteArrayView head, Direction direction);

QByteArray toHex(QByteArrayView bytes);   // "01 03 00 B1 00 02 94 2C"
std::optional<QByteArray> fromHex(QString text);   // accepts spaces, case-insensitive

} // namespace RtuFrame

} // namespace jumo
