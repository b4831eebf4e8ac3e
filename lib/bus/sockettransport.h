// The TCP connection of a network line, shared by the Modbus TCP gateway's transport and
// the serial device server's: connecting in the background within a limit, small frames
// sent at once, and a connection refused, dropped or never made being the loss of the
// line. What goes over the connection (MBAP or raw RTU frames) is the subclass's.
#pragma once

#include "bus/clienttransport.h"
#include "bus/lineaddress.h"
#include "protocol/lineformat.h"

#include <QTcpSocket>
#include <QTimer>

namespace jumo {

class SocketTransport : public ClientTransport
{
    Q_OBJECT

public:
    // How long the far end may take to accept the connection.
    static constexpr int connectTimeoutMs = 5000;

    ~SocketTransport() override;

    double interFrameDelayMs() const override;

protected:
    enum class PeerKind { Gateway, DeviceServer };

    SocketTransport(PeerKind kind, const LineAddress &address, const LineFormat &format, QObject *parent);

    QString peer() const override;
    Link openLink(QString *error) override;
    void closeLink() override;

    // Bytes from the far end.
    virtual void received(const QByteArray &bytes) = 0;
    void write(const QByteArray &bytes) { m_socket.write(bytes); }

    const LineAddress &address() const { return m_address; }
    const LineFormat &format() const { return m_format; }

private:
    void onConnected();
    void onDisconnected();
    void onError();
    void onConnectTimeout();

    PeerKind m_kind;
    LineAddress m_address;
    LineFormat m_format;
    QTcpSocket m_socket;
    QTimer m_connectTimer;
    bool m_connected = false;
};

} // namespace jumo
