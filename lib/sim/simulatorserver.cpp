#include "sim/simulatorserver.h"

#include "protocol/mbapframe.h"
#include "protocol/rtuframe.h"
#include "sim/simulatorline.h"

#include <QLoggingCategory>
#include <QTcpSocket>

Q_DECLARE_LOGGING_CATEGORY(lcSim)

namespace jumo {

namespace {

constexpr quint8 gatewayTargetFailed = 0x0B;

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
    while (true) {
        const MbapFrame::Taken request = MbapFrame::take(buffer);
        if (request.kind == MbapFrame::Taken::Kind::Incomplete)
            return;
        if (request.kind == MbapFrame::Taken::Kind::Unframable) {
            // Not Modbus: a gateway closes such a connection.
            qCWarning(lcSim) << "not a Modbus TCP frame, closing the connection";
            m_buffers.remove(socket);
            socket->abort();
            socket->deleteLater();
            return;
        }
        buffer.remove(0, request.size);
        const quint16 transaction = request.header.transaction;
        const quint8 unit = request.header.unit;
        const QByteArray &pdu = request.pdu;

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
            m_line->sendLater(socket, MbapFrame::build(transaction, unit, exception), m_gatewayTimeoutMs);
            continue;
        }
        m_line->sendLater(socket, MbapFrame::build(transaction, unit, QByteArrayView(reply).sliced(1, reply.size() - 3)),
                          answer.delayMs);
    }
}

} // namespace jumo
