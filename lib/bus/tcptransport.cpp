#include "bus/tcptransport.h"

namespace jumo {

TcpTransport::TcpTransport(const LineAddress &address, const LineFormat &format, QObject *parent)
    : SocketTransport(PeerKind::Gateway, address, format, parent)
{
}

ClientTransport::Link TcpTransport::openLink(QString *error)
{
    m_framer.reset();
    return SocketTransport::openLink(error);
}

void TcpTransport::transmit(const ModbusRequest &request)
{
    if (request.isBroadcast()) {
        // The bus refuses broadcasts on a Modbus TCP line before they come here.
        fail(ModbusResult::Status::LineDown, tr("broadcasts are not sent through a Modbus TCP gateway"));
        return;
    }
    write(m_framer.frame(request));
    startReplyTimer(request.timeoutMs);
}

ModbusResult TcpTransport::timedOut(const ModbusRequest &)
{
    bool broken = false;
    const ModbusResult result = m_framer.timedOut(&broken);
    if (broken) {
        // Part of a frame and then nothing: where the next one begins is not known.
        noteRejected(result.errorText);
        relink(result.errorText);
    }
    return result;
}

void TcpTransport::received(const QByteArray &bytes)
{
    const MbapFramer::Outcome outcome = m_framer.received(bytes);
    if (!outcome.what.isEmpty())
        noteRejected(outcome.what);
    // The new connection first: whatever is sent next, on hearing the result, waits for it.
    if (outcome.broken)
        relink(outcome.what);
    if (outcome.result)
        complete(*outcome.result);
}

} // namespace jumo
