#include "bus/rtutcptransport.h"

#include <cmath>

namespace jumo {

RtuTcpTransport::RtuTcpTransport(const LineAddress &address, const LineFormat &format, QObject *parent)
    : SocketTransport(PeerKind::DeviceServer, address, format, parent)
{
    m_clock.start();
    m_lastTraffic.start();
    m_waitTimer.setSingleShot(true);
    m_waitTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_waitTimer, &QTimer::timeout, this, &RtuTcpTransport::transmitWhenReady);
}

ClientTransport::Link RtuTcpTransport::openLink(QString *error)
{
    m_waitTimer.stop();
    m_framer.reset();
    m_lastTraffic.restart();
    return SocketTransport::openLink(error);
}

void RtuTcpTransport::transmit(const ModbusRequest &)
{
    m_written = false;
    m_gapWait.invalidate();
    transmitWhenReady();
}

void RtuTcpTransport::transmitWhenReady()
{
    const ModbusRequest *const request = this->request();
    if (!request || m_written || !isOpen())
        return;
    const qint64 now = m_clock.elapsed();
    if (const qint64 until = m_framer.holdUntil(*request, now); until > now) {
        // A reply owed to an earlier request of this device could be taken for this
        // one's: it goes out once that reply came (received() calls again) or is no
        // longer waited for.
        m_waitTimer.start(int(until - now));
        return;
    }
    // The device server passes bytes on as they come: the silence before a request must
    // be kept here, at the baud rate of its serial side.
    const qint64 gapMs = qint64(std::ceil(interFrameDelayMs()));
    if (!m_gapWait.isValid())
        m_gapWait.start();
    if (const qint64 waited = m_lastTraffic.elapsed(); waited < gapMs) {
        if (m_gapWait.elapsed() >= request->timeoutMs) {
            // Noise, or another master on the serial side: a request sent now would
            // collide with it. Said as such, not waited for until the end of time.
            fail(ModbusResult::Status::Timeout,
                 tr("not sent: the line was never silent for %1 ms within %2 ms (noise or another master on the "
                    "serial side?)")
                         .arg(gapMs)
                         .arg(request->timeoutMs));
            return;
        }
        m_waitTimer.start(int(gapMs - waited));
        return;
    }
    m_waitTimer.stop();
    m_written = true;
    write(m_framer.frame(*request, now));
    m_lastTraffic.restart();
    if (request->isBroadcast()) {
        // Nobody answers address 0: done once it is handed on, as on a serial line.
        ModbusResult sent;
        sent.status = ModbusResult::Status::Ok;
        complete(sent);
        return;
    }
    startReplyTimer(request->timeoutMs);
}

ModbusResult RtuTcpTransport::timedOut(const ModbusRequest &)
{
    const ModbusResult result = m_framer.timedOut(m_clock.elapsed());
    if (result.mismatches > 0)
        noteRejected(result.errorText);
    return result;
}

void RtuTcpTransport::received(const QByteArray &bytes)
{
    m_lastTraffic.restart();
    const std::optional<ModbusResult> result = m_framer.received(bytes, m_clock.elapsed());
    if (result) {
        if (result->mismatches > 0)
            noteRejected(tr("%n frame(s) before the reply that answer another request", nullptr, result->mismatches));
        complete(*result);
        return;
    }
    if (request() && !m_written)
        transmitWhenReady();   // an owed reply may have come
}

} // namespace jumo
