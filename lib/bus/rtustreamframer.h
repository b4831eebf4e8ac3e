// RTU over TCP without the socket: finds the reply to the request under way in the bytes
// a serial device server passes on. RTU frames carry no transaction id, so a reply that
// comes after its request's timeout looks like the answer to the next request of its
// device. Hence: whatever arrived before a request went out answers nothing asked now;
// after it, only a frame that answers this request (address, function, length, a write's
// echo) is taken, and of several in one reading the last (a device answers in order);
// a complete frame that answers something else is dropped and counted. A reply not come
// in time is still owed for lateReplyMs: a request of its device and function, which it
// could be taken for, waits until it came (and was dropped) or that time passed.
#pragma once

#include "bus/modbusrequest.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QHash>
#include <QList>

#include <optional>

namespace jumo {

class RtuStreamFramer
{
    Q_DECLARE_TR_FUNCTIONS(jumo::RtuStreamFramer)

public:
    // How long after its timeout a reply is still waited for: a delayed TCP segment
    // (a retransmission), a device server slow to pass bytes on.
    static constexpr int lateReplyMs = 1000;
    // Bytes kept while looking for a reply: far more in front of it is a flood.
    static constexpr qsizetype keptBytes = 512;

    // The frame of the request, which goes out now; it is the one under way.
    QByteArray frame(const ModbusRequest &request, qint64 nowMs);
    // Bytes from the device server: the result of the request under way once a frame
    // that answers it is complete.
    std::optional<ModbusResult> received(QByteArrayView bytes, qint64 nowMs);
    // The request's time is up: its result. Its reply is owed from now on.
    ModbusResult timedOut(qint64 nowMs);
    // A request must not go out before this time (a reply it could be taken for is
    // owed); nowMs or earlier: it may go now.
    qint64 holdUntil(const ModbusRequest &request, qint64 nowMs);
    // A new connection: nothing received, nothing under way, nothing owed.
    void reset();

    qsizetype pendingBytes() const { return m_buffer.size(); }
    int owedReplies() const { return int(m_owed.size()); }

    // Finds the reply to the request in the bytes received so far: its length once one
    // is complete, with *skipped bytes in front of it that are not taken (stray bytes,
    // an echo of the request, a frame with a bad CRC: counted in *crcErrors, a frame
    // that answers something else: counted in *mismatches). Of several replies the last.
    // nullopt while more must arrive.
    static std::optional<qsizetype> findReply(const ModbusRequest &request, const QByteArray &buffer,
                                              qsizetype *skipped, int *crcErrors, int *mismatches = nullptr);
    // What a received reply frame (address .. CRC, CRC checked) means for the request:
    // the same checks as a serial line's.
    static ModbusResult resultOfFrame(const ModbusRequest &request, QByteArrayView frame);
    // True when the frame (address .. CRC, CRC checked) answers the request.
    static bool answers(const ModbusRequest &request, QByteArrayView frame);

private:
    struct Owed
    {
        ModbusRequest request;
        qint64 untilMs = 0;
    };
    void settleOwed();

    std::optional<ModbusRequest> m_request;
    QByteArray m_buffer;
    QList<Owed> m_owed;
    QHash<quint8, int> m_lateReplies;   // owed replies that came, per device: its next result's mismatches
    int m_unframed = 0;                 // bytes dropped unread at a request: the next result's
    qsizetype m_heardBytes = 0;         // bytes in front of m_buffer already counted so
};

} // namespace jumo
