// A Modbus TCP gateway that lies, for the tests: it serves a simulated line as a gateway
// does (MBAP in, the unit id picks the device) and, for the units told to, answers with
// another unit's reply, with its own unit id or protocol id changed, with junk behind
// the reply or with an MBAP length 2 bytes short. Everything else is answered honestly.
#pragma once

#include "protocol/mbapframe.h"
#include "protocol/rtuframe.h"
#include "sim/simulatorline.h"

#include <QHash>
#include <QTcpServer>
#include <QTcpSocket>

namespace jumo::test {

class LyingGateway : public QObject
{
public:
    enum class Lie {
        None,
        OtherUnitsReply,     // the request goes to unit + 1; its reply comes back with unit + 1 in the header
        UnitIdChanged,       // the right device's reply, with unit + 1 in the header
        ProtocolIdChanged,   // the right reply with protocol id 1
        JunkAfterReply,      // the right reply and 13 junk bytes behind it
        LengthTwoShort,      // the right reply with an MBAP length 2 bytes short
        CutMidReply,         // the device acts; half its reply, then the connection is reset
    };

    explicit LyingGateway(SimulatorLine *line) : m_line(line)
    {
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *socket = m_server.nextPendingConnection()) {
                socket->setParent(this);
                ++m_connections;
                connect(socket, &QTcpSocket::readyRead, this, [this, socket] { serve(socket); });
                connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
                    m_buffers.remove(socket);
                    socket->deleteLater();
                });
            }
        });
    }

    bool listen(const QHostAddress &address = QHostAddress::LocalHost) { return m_server.listen(address, 0); }
    quint16 port() const { return m_server.serverPort(); }
    QString url() const { return QStringLiteral("tcp://127.0.0.1:%1").arg(port()); }
    int connections() const { return m_connections; }

    // Lies to the next `count` requests for the unit (-1: until told otherwise), or to its
    // write requests only.
    void lie(quint8 unit, Lie lie, int count = -1, bool writesOnly = false)
    {
        m_lies.insert(unit, {lie, count, writesOnly});
    }

private:
    struct Told
    {
        Lie lie = Lie::None;
        int remaining = -1;
        bool writesOnly = false;
    };

    Lie nextLie(quint8 unit, const QByteArray &pdu)
    {
        auto it = m_lies.find(unit);
        if (it == m_lies.end())
            return Lie::None;
        const quint8 function = pdu.isEmpty() ? 0 : quint8(pdu[0]);
        if (it->writesOnly && function != 0x06 && function != 0x10)
            return Lie::None;
        const Lie lie = it->lie;
        if (it->remaining > 0 && --it->remaining == 0)
            m_lies.erase(it);
        return lie;
    }

    void serve(QTcpSocket *socket)
    {
        QByteArray &buffer = m_buffers[socket];
        buffer += socket->readAll();
        while (true) {
            const MbapFrame::Taken request = MbapFrame::take(buffer);
            if (request.kind != MbapFrame::Taken::Kind::Frame)
                return;
            buffer.remove(0, request.size);
            const quint8 unit = request.header.unit;
            const Lie lie = nextLie(unit, request.pdu);
            const quint8 asked = lie == Lie::OtherUnitsReply ? quint8(unit + 1) : unit;
            const SimulatorLine::Answer answer = m_line->answer(RtuFrame::build(asked, request.pdu));
            if (answer.frame.size() < 4)
                continue;   // a silent device: the client's timeout
            const QByteArray pdu = answer.frame.mid(1, answer.frame.size() - 3);
            const quint8 headerUnit = lie == Lie::OtherUnitsReply || lie == Lie::UnitIdChanged ? quint8(unit + 1) : unit;
            QByteArray reply = MbapFrame::build(request.header.transaction, headerUnit, pdu);
            switch (lie) {
            case Lie::ProtocolIdChanged:
                reply[3] = 1;
                break;
            case Lie::JunkAfterReply:
                reply += QByteArray::fromHex("4a554e4b4a554e4b4a554e4b4a");
                break;
            case Lie::LengthTwoShort:
                reply[5] = char(quint8(reply[5]) - 2);
                break;
            case Lie::CutMidReply:
                socket->write(reply.left(reply.size() / 2));
                socket->flush();
                socket->abort();
                return;
            default:
                break;
            }
            m_line->sendLater(socket, reply, answer.delayMs);
        }
    }

    SimulatorLine *m_line;
    QTcpServer m_server;
    QHash<QTcpSocket *, QByteArray> m_buffers;
    QHash<quint8, Told> m_lies;
    int m_connections = 0;
};

} // namespace jumo::test
