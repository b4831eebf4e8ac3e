#include "bus/sockettransport.h"

#include "bus/linetiming.h"

namespace jumo {

SocketTransport::SocketTransport(PeerKind kind, const LineAddress &address, const LineFormat &format, QObject *parent)
    : ClientTransport(parent), m_kind(kind), m_address(address), m_format(format)
{
    m_connectTimer.setSingleShot(true);
    m_connectTimer.setInterval(connectTimeoutMs);
    connect(&m_connectTimer, &QTimer::timeout, this, &SocketTransport::onConnectTimeout);
    connect(&m_socket, &QTcpSocket::connected, this, &SocketTransport::onConnected);
    connect(&m_socket, &QTcpSocket::disconnected, this, &SocketTransport::onDisconnected);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &SocketTransport::onError);
    connect(&m_socket, &QTcpSocket::readyRead, this, [this] { received(m_socket.readAll()); });
}

SocketTransport::~SocketTransport()
{
    m_socket.disconnect(this);
    m_socket.abort();
}

double SocketTransport::interFrameDelayMs() const
{
    // The far end keeps the frame gap of its serial side at its baud; the bus's timing
    // counts it (and RTU over TCP keeps it itself).
    return LineTiming::interFrameDelayMs(m_format);
}

QString SocketTransport::peer() const
{
    return m_kind == PeerKind::Gateway ? tr("the gateway %1").arg(m_address.endpoint())
                                       : tr("the device server %1").arg(m_address.endpoint());
}

ClientTransport::Link SocketTransport::openLink(QString *)
{
    m_socket.abort();
    m_connected = false;
    // The host as given: Qt's Modbus TCP client made a URL of host and port, which an
    // IPv6 address does not survive ("Host not found" for tcp://[::1]).
    m_socket.connectToHost(m_address.host, m_address.port);
    m_connectTimer.start();
    return Link::Connecting;
}

void SocketTransport::closeLink()
{
    m_connectTimer.stop();
    m_connected = false;
    // abort() would report the closing to this very object: it must not hear of it.
    const QSignalBlocker quiet(m_socket);
    m_socket.abort();
}

void SocketTransport::onConnected()
{
    m_connectTimer.stop();
    m_connected = true;
    // Small frames must leave at once, not wait for more to fill a segment.
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    linkUp();
}

void SocketTransport::onDisconnected()
{
    linkDown(m_kind == PeerKind::Gateway ? tr("the gateway %1 closed the connection").arg(m_address.endpoint())
                                         : tr("the device server %1 closed the connection").arg(m_address.endpoint()));
}

void SocketTransport::onError()
{
    QString why = m_socket.errorString();
    if (why.isEmpty())
        why = tr("the connection was refused or closed");
    if (m_connected)
        linkDown(m_kind == PeerKind::Gateway
                         ? tr("connection to the gateway %1 lost: %2").arg(m_address.endpoint(), why)
                         : tr("connection to the device server %1 lost: %2").arg(m_address.endpoint(), why));
    else
        linkDown(m_kind == PeerKind::Gateway
                         ? tr("no connection to the gateway %1: %2").arg(m_address.endpoint(), why)
                         : tr("no connection to the device server %1: %2").arg(m_address.endpoint(), why));
}

void SocketTransport::onConnectTimeout()
{
    linkDown(m_kind == PeerKind::Gateway
                     ? tr("the gateway %1 did not accept a connection within %2 s")
                               .arg(m_address.endpoint())
                               .arg(connectTimeoutMs / 1000)
                     : tr("the device server %1 did not accept a connection within %2 s")
                               .arg(m_address.endpoint())
                               .arg(connectTimeoutMs / 1000));
}

} // namespace jumo
