#include "sim/simulatorserver.h"

#include "protocol/rtuframe.h"
#include "sim/simulatorline.h"

#include <QLoggingCategory>
#include <QTcpSocket>

Q_DECLARE_LOGGING_CATEGORY(lcSim)

namespace jumo {

namespace {

constexpr int mbapHeaderBytes = 7;
constexpr quint8 gatewayTargetFailed = 0x0B;

QByteArray mbap(quint16 transaction, quint8 unit, const QByteArray &pdu)
{
    QByteArray out;
    const quint16 length = quint16(pdu.size() + 1);
    out.append(char(transaction >> 8)).append(char(transaction & 0xFF));
    out.append('\0').append('\0');   // protocol id: Modbus
    out.append(char(length >> 8)).append(char(length & 0xFF));
    out.append(char(unit));
    out.append(pdu);
    return out;
}

} // namespace

SimulatorServer::SimulatorServer(SimulatorLine *line, Mode mode, QObject *parent)
    : QObject(parent), m_line(line), m_mode(mode)
{
    connect(&m_server, &QTcpServer::newConnection, this, &SimulatorServer::onNewConnection);
}

SimulatorServer::~SimulatorServer()
{
    close();
}

bool SimulatorServer::listen(const QHostAddress &address, quint16 port, QString *error)
{
    if (!m_server.listen(address, port)) {
        if (error)
            *error = m_server.errorString();
        return false;
    }
    return true;
}

void SimulatorServer::close()
{
    m_server.close();
    dropConnections();
}

void SimulatorServer::dropConnections()
{
    const QList<QTcpSocket *> sockets = m_buffers.keys();
    m_buffers.clear();
    for (QTcpSocket *socket : sockets) {
        socket->disconnect(this);
        socket->abort();
        socket->deleteLater();
    }
}

void SimulatorServer::onNewConnection()
{
    while (QTcpSocket *socket = m_server.nextPendingConnection()) {
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        m_buffers.insert(socket, {});
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { onReadyRead(socket); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            m_buffers.remove(socket);
            socket->deleteLater();
        });
    }
}

void SimulatorServer::onReadyRead(QTcpSocket *socket)
{
    auto it = m_buffers.find(socket);
    if (it == m_buffers.end())
        return;
    it->append(socket->readAll());
    if (m_mode == Mode::RtuOverTcp)
        serveRtu(socket, *it);
    else
        serveMbap(socket, *it);
}

void SimulatorServer::serveRtu(QTcpSocket *socket, QByteArray &buffer)
{
    while (!buffer.isEmpty()) {
        const std::optional<int> length = RtuFrame::expectedLength(buffer, RtuFrame::Direction::Request);
        if (!length)
            return;
        if (*length < 0) {
            // A function nobody on the line speaks: the devices stay silent.
            buffer.clear();
            return;
        }
        if (buffer.size() < *length)
            return;
        const QByteArray frame = buffer.left(*length);
        buffer.remove(0, *length);
        const SimulatorLine::Answer answer = m_line->answer(frame);
        if (!answer.frame.isEmpty())
            m_line->sendLater(socket, answer.frame, answer.delayMs);
    }
}

void SimulatorServer::serveMbap(QTcpSocket *socket, QByteArray &buffer)
{
    while (buffer.size() >= mbapHeaderBytes) {
        const quint16 transaction = quint16(quint8(buffer[0]) << 8 | quint8(buffer[1]));
        const quint16 protocol = quint16(quint8(buffer[2]) << 8 | quint8(buffer[3]));
        const quint16 length = quint16(quint8(buffer[4]) << 8 | quint8(buffer[5]));
        if (protocol != 0 || length < 2 || length > 254) {
            // Not Modbus: a gateway closes such a connection.
            qCWarning(lcSim) << "not a Modbus TCP frame, closing the connection";
            m_buffers.remove(socket);
            socket->abort();
            socket->deleteLater();
            return;
        }
        if (buffer.size() < 6 + length)
            return;
        const quint8 unit = quint8(buffer[6]);
        const QByteArray pdu = buffer.mid(mbapHeaderBytes, length - 1);
        buffer.remove(0, 6 + length);

        // The gateway puts the request on its serial line as an RTU frame.
        const SimulatorLine::Answer answer = m_line->answer(RtuFrame::build(unit, pdu));
        if (unit == 0)
            continue;   // a broadcast: passed on, nobody answers it
        QByteArray reply = answer.frame;
        // Stray bytes in front of the device's reply are the gateway's to skip.
        while (reply.size() > 4 && !RtuFrame::hasValidCrc(reply))
            reply.remove(0, 1);
        if (reply.size() < 4 || !RtuFrame::hasValidCrc(reply)) {
            // Silence or garbage from the device: after its timeout the gateway says so.
            QByteArray exception;
            exception.append(char(quint8(pdu.isEmpty() ? 0 : pdu[0]) | 0x80)).append(char(gatewayTargetFailed));
            m_line->sendLater(socket, mbap(transaction, unit, exception), m_gatewayTimeoutMs);
            continue;
        }
        m_line->sendLater(socket, mbap(transaction, unit, reply.mid(1, reply.size() - 3)), answer.delayMs);
    }
}

} // namespace jumo
