#include "protocol/mbapframe.h"

#include "protocol/rtuframe.h"

namespace jumo::MbapFrame {

namespace {

quint16 wordAt(QByteArrayView bytes, qsizetype at)
{
    return quint16(quint8(bytes[at]) << 8 | quint8(bytes[at + 1]));
}

} // namespace

QByteArray build(quint16 transaction, quint8 unit, QByteArrayView pdu)
{
    QByteArray frame;
    frame.reserve(headerBytes + pdu.size());
    const quint16 length = quint16(pdu.size() + 1);
    frame.append(char(transaction >> 8)).append(char(transaction & 0xFF));
    frame.append('\0').append('\0');   // protocol id: Modbus
    frame.append(char(length >> 8)).append(char(length & 0xFF));
    frame.append(char(unit));
    frame.append(pdu.data(), pdu.size());
    return frame;
}

Taken take(QByteArrayView stream)
{
    Taken taken;
    if (stream.size() < headerBytes)
        return taken;
    taken.header.transaction = wordAt(stream, 0);
    taken.header.protocol = wordAt(stream, 2);
    taken.header.length = wordAt(stream, 4);
    taken.header.unit = quint8(stream[6]);
    if (taken.header.protocol != 0 || taken.header.length < minLength || taken.header.length > maxLength) {
        taken.kind = Taken::Kind::Unframable;
        return taken;
    }
    const qsizetype size = 6 + taken.header.length;
    if (stream.size() < size)
        return taken;
    taken.kind = Taken::Kind::Frame;
    taken.pdu = stream.sliced(headerBytes, size - headerBytes).toByteArray();
    taken.size = size;
    return taken;
}

bool isConsistentResponse(QByteArrayView pdu)
{
    // The RTU rule for a frame's length from its first bytes, applied to unit id + PDU
    // (an RTU frame is the same with a CRC of 2 bytes behind): only its first three
    // bytes are read.
    if (pdu.isEmpty())
        return false;
    const char head[3] = {0, pdu[0], pdu.size() > 1 ? pdu[1] : char(0)};
    const std::optional<int> length = RtuFrame::expectedLength(
            QByteArrayView(head, std::min<qsizetype>(3, pdu.size() + 1)), RtuFrame::Direction::Response);
    return length && *length == pdu.size() + 3;
}

} // namespace jumo::MbapFrame
