// The simulated line behind TCP: a Modbus TCP gateway (MBAP in, the unit id picks the
// device, a unit id nobody answers gets exception 0x0B as from a real gateway) or a
// serial device server (raw RTU frames in and out). The devices, their timing and
// faults are the SimulatorLine's.
#pragma once

#include <QHash>
#include <QHostAddress>
#include <QObject>
#include <QTcpServer>

class QTcpSocket;

namespace jumo {

class SimulatorLine;

class SimulatorServer : public QObject
{
    Q_OBJECT

public:
    enum class Mode { ModbusTcp, RtuOverTcp };

    SimulatorServer(SimulatorLine *line, Mode mode, QObject *parent = nullptr);
    ~SimulatorServer() override;

    // Port 0 picks a free one: port() tells which.
    bool listen(const QHostAddress &address, quint16 port, QString *error = nullptr);
    void close();
    quint16 port() const { return m_server.serverPort(); }
    QHostAddress address() const { return m_server.serverAddress(); }
    Mode mode() const { return m_mode; }
    // How long the gateway waits for a device before it answers 0x0B.
    void setGatewayTimeoutMs(int ms) { m_gatewayTimeoutMs = ms; }
    int connectionCount() const { return int(m_buffers.size()); }
    // Ends every connection (a gateway restarting); listening goes on.
    void dropConnections();

private:
    void onNewConnection();
    void onReadyRead(QTcpSocket *socket);
    void serveRtu(QTcpSocket *socket, QByteArray &buffer);
    void serveMbap(QTcpSocket *socket, QByteArray &buffer);

    SimulatorLine *m_line;
    Mode m_mode;
    QTcpServer m_server;
    QHash<QTcpSocket *, QByteArray> m_buffers;
    int m_gatewayTimeoutMs = 100;
};

} // namespace jumo
