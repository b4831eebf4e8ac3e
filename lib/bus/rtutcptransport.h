// The transport of RTU over TCP: raw RTU frames through a serial device server (a port
// server, a Moxa NPort in "TCP server" mode, socat). The frames and the timing are a
// serial line's: the frame gap at the configured baud before each request, a reply
// framed by its expected length and checked by CRC and against the request
// (RtuStreamFramer, which also keeps a late reply from being taken for the next
// request's). Unlike Qt's RTU client it skips stray bytes in front of a reply.
#pragma once

#include "bus/rtustreamframer.h"
#include "bus/sockettransport.h"

#include <QElapsedTimer>
#include <QTimer>

namespace jumo {

class RtuTcpTransport final : public SocketTransport
{
    Q_OBJECT

public:
    RtuTcpTransport(const LineAddress &address, const LineFormat &format, QObject *parent = nullptr);

private:
    Link openLink(QString *error) override;
    void transmit(const ModbusRequest &request) override;
    ModbusResult timedOut(const ModbusRequest &request) override;
    void received(const QByteArray &bytes) override;
    // Sends the request once nothing owed could be taken for its reply and the line has
    // kept its frame gap.
    void transmitWhenReady();

    RtuStreamFramer m_framer;
    QElapsedTimer m_clock;
    QTimer m_waitTimer;           // an owed reply, then the frame gap, before a request
    QElapsedTimer m_lastTraffic;
    QElapsedTimer m_gapWait;      // since the gap is waited for: no longer than the request's timeout
    bool m_written = false;       // the request under way went out
};

} // namespace jumo
