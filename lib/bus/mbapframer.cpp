#include "bus/mbapframer.h"

#include "bus/rtutransport.h"
#include "protocol/mbapframe.h"
#include "protocol/rtuframe.h"

namespace jumo {

QByteArray MbapFramer::frame(const ModbusRequest &request)
{
    m_request = request;
    ++m_transaction;
    return MbapFrame::build(m_transaction, request.slave, request.pdu());
}

MbapFramer::Outcome MbapFramer::received(QByteArrayView bytes)
{
    m_buffer.append(bytes.data(), bytes.size());
    Outcome outcome;
    // Everything complete is framed now, also what follows a reply: junk behind it
    // breaks the stream at once, not only when the next request's reply is due.
    while (!outcome.broken) {
        const MbapFrame::Taken taken = MbapFrame::take(m_buffer);
        if (taken.kind == MbapFrame::Taken::Kind::Incomplete)
            break;
        const QByteArrayView head = QByteArrayView(m_buffer).first(std::min<qsizetype>(m_buffer.size(), 32));
        if (taken.kind == MbapFrame::Taken::Kind::Unframable) {
            outcome.broken = true;
            outcome.what = taken.header.protocol != 0
                    ? tr("a header with protocol id %1 (Modbus is 0): %2")
                              .arg(taken.header.protocol)
                              .arg(QString::fromLatin1(RtuFrame::toHex(head)))
                    : tr("a header with length %1 (a Modbus TCP frame has %2..%3): %4")
                              .arg(taken.header.length)
                              .arg(MbapFrame::minLength)
                              .arg(MbapFrame::maxLength)
                              .arg(QString::fromLatin1(RtuFrame::toHex(head)));
            break;
        }
        if (!MbapFrame::isConsistentResponse(taken.pdu)) {
            // The length field does not agree with the PDU: where this frame ends, and so
            // where the next begins, is not known.
            outcome.broken = true;
            outcome.what = tr("a frame whose length does not fit its content: %1")
                                   .arg(QString::fromLatin1(RtuFrame::toHex(head.first(std::min(head.size(), taken.size)))));
            break;
        }
        m_buffer.remove(0, taken.size);
        if (!m_request || taken.header.transaction != m_transaction) {
            // A reply that came too late for its request, or one nobody asked for.
            ++m_dropped;
            outcome.what = m_request ? tr("a reply with transaction id %1 (%2 expected)")
                                               .arg(taken.header.transaction)
                                               .arg(m_transaction)
                                     : tr("a reply with transaction id %1 while nothing was asked")
                                               .arg(taken.header.transaction);
            continue;
        }
        const ModbusRequest request = *std::exchange(m_request, std::nullopt);
        ModbusResult result;
        if (taken.header.unit != request.slave) {
            result.status = ModbusResult::Status::BadReply;
            result.errorText = tr("a reply from unit %1 to a request for unit %2").arg(taken.header.unit).arg(request.slave);
        } else {
            result = RtuTransport::resultOfResponse(request, taken.pdu);
        }
        if (result.status == ModbusResult::Status::BadReply) {
            outcome.what = result.errorText;
            ++m_dropped;
        }
        result.mismatches = std::exchange(m_dropped, 0);
        outcome.result = result;
    }
    if (!outcome.broken)
        return outcome;
    // Nothing more on this connection can be read.
    m_buffer.clear();
    if (m_request) {
        m_request.reset();
        ModbusResult result;
        result.status = ModbusResult::Status::BadReply;
        result.errorText = tr("the gateway sent %1").arg(outcome.what);
        result.mismatches = std::exchange(m_dropped, 0) + 1;
        outcome.result = result;
    }
    return outcome;
}

ModbusResult MbapFramer::timedOut(bool *broken)
{
    ModbusResult result;
    result.status = ModbusResult::Status::Timeout;
    const int timeoutMs = m_request ? m_request->timeoutMs : 0;
    *broken = !m_buffer.isEmpty();
    result.errorText = m_buffer.isEmpty()
            ? tr("no reply within %1 ms").arg(timeoutMs)
            : tr("an incomplete reply within %1 ms (%2 byte(s): %3)")
                      .arg(timeoutMs)
                      .arg(m_buffer.size())
                      .arg(QString::fromLatin1(RtuFrame::toHex(QByteArrayView(m_buffer).first(
                              std::min<qsizetype>(m_buffer.size(), 16)))));
    result.mismatches = std::exchange(m_dropped, 0);
    m_request.reset();
    if (*broken)
        m_buffer.clear();
    return result;
}

void MbapFramer::reset()
{
    m_request.reset();
    m_buffer.clear();
}

} // namespace jumo
