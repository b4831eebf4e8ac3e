// Modbus TCP as the gateway's transport speaks it, without the socket: each request
// framed with a transaction id of its own, and the bytes received taken apart into
// frames and checked before anything is decoded. A reply is taken only with the
// request's transaction id, protocol id 0 and unit id, and a function and length that
// fit the request (as on a serial line). A frame of an earlier transaction is dropped
// and counted; a frame of this one that does not fit ends the request as a bad reply;
// bytes that cannot be framed (or a frame whose length disagrees with its content) say
// that the stream is broken: the connection must be made anew.
#pragma once

#include "bus/modbusrequest.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

#include <optional>

namespace jumo {

class MbapFramer
{
    Q_DECLARE_TR_FUNCTIONS(jumo::MbapFramer)

public:
    // What the bytes received so far came to.
    struct Outcome
    {
        // The request under way ended: Ok, Exception or BadReply (a frame of its
        // transaction that does not fit it, or a stream that broke while it waited).
        std::optional<ModbusResult> result;
        // The stream cannot be framed any more: the connection must be made anew.
        bool broken = false;
        // Why a frame was not taken, for the log; empty when all was well.
        QString what;
    };

    // The frame of the request, with the next transaction id; it is the one under way now.
    QByteArray frame(const ModbusRequest &request);
    // Bytes from the gateway.
    Outcome received(QByteArrayView bytes);
    // The request's time is up: its result; *broken when part of a frame had come (the
    // rest of the stream can no longer be framed).
    ModbusResult timedOut(bool *broken);
    // A new connection: nothing received and nothing under way (transaction ids go on,
    // so a frame of the old connection can never be taken for a new request).
    void reset();

    quint16 transaction() const { return m_transaction; }
    // Bytes received and not yet framed.
    qsizetype pendingBytes() const { return m_buffer.size(); }

private:
    std::optional<ModbusRequest> m_request;
    quint16 m_transaction = 0;
    QByteArray m_buffer;
    int m_dropped = 0;   // frames of other transactions since the last result
};

} // namespace jumo
