// Modbus TCP framing: the MBAP header (transaction id, protocol id, length, unit id) in
// front of a PDU, and taking one frame off the front of a byte stream. A stream that
// cannot be framed any more (a header no Modbus TCP peer sends) is said as such: what
// follows it on that connection can no longer be told apart.
#pragma once

#include <QByteArray>
#include <QByteArrayView>

#include <optional>

namespace jumo {

namespace MbapFrame {

constexpr int headerBytes = 7;
// The length field counts the unit id and the PDU: a PDU is 1..253 bytes.
constexpr int minLength = 2;
constexpr int maxLength = 254;

struct Header
{
    quint16 transaction = 0;
    quint16 protocol = 0;
    quint16 length = 0;   // unit id and PDU
    quint8 unit = 0;
};

QByteArray build(quint16 transaction, quint8 unit, QByteArrayView pdu);

// What the front of a stream holds.
struct Taken
{
    enum class Kind {
        Incomplete,   // more must arrive (nothing taken)
        Frame,        // a whole frame: header and pdu, `size` bytes taken
        Unframable,   // a header with a protocol id other than 0 or an impossible length
    };
    Kind kind = Kind::Incomplete;
    Header header;
    QByteArray pdu;
    qsizetype size = 0;
};
Taken take(QByteArrayView stream);

// True when the PDU's own fields (an exception's one code byte, a read reply's byte
// count, a write reply's address and count) say it has exactly the size it has: a
// length field that disagrees with them means the frame boundary is not where the
// header puts it. Only the functions this project speaks are known; others: false.
bool isConsistentResponse(QByteArrayView pdu);

} // namespace MbapFrame

} // namespace jumo
