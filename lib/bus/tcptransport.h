// The transport of a Modbus TCP gateway: MBAP frames over a TCP connection (MbapFramer),
// the unit id the device's address, one request at a time with its own transaction id.
// A reply is taken only when its transaction id, protocol id, unit id, function and
// length fit the request (Qt's QModbusTcpClient checked none of the ids); one that does
// not is never decoded. Bytes that cannot be framed make the connection anew at once,
// so one bad frame costs one request, not the device.
#pragma once

#include "bus/mbapframer.h"
#include "bus/sockettransport.h"

namespace jumo {

class TcpTransport final : public SocketTransport
{
    Q_OBJECT

public:
    TcpTransport(const LineAddress &address, const LineFormat &format, QObject *parent = nullptr);

private:
    Link openLink(QString *error) override;
    void transmit(const ModbusRequest &request) override;
    ModbusResult timedOut(const ModbusRequest &request) override;
    void received(const QByteArray &bytes) override;

    MbapFramer m_framer;
};

} // namespace jumo
