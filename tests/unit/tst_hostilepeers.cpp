// The TCP transports against peers that misbehave on purpose, over real sockets: a
// Modbus TCP gateway that sends part of a reply (or an MBAP header with an impossible
// length) and then nothing, and a serial device server that never falls silent. Each
// request must come to an end, never wait for ever with the line "connected".
#include "bus/rtutcptransport.h"
#include "bus/tcptransport.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>

using namespace jumo;


namespace {

// Answers every request on its connection with what `answer` makes of it.
class HostilePeer : public QObject
{
public:
    explicit HostilePeer(std::function<QByteArray(const QByteArray &)> answer) : m_answer(std::move(answer))
    {
        m_server.listen(QHostAddress::LocalHost, 0);
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            QTcpSocket *socket = m_server.nextPendingConnection();
            connect(socket, &QTcpSocket::readyRead, socket, [this, socket] {
                const QByteArray reply = m_answer(socket->readAll());
                if (!reply.isEmpty())
                    socket->write(reply);
            });
            m_sockets << socket;
        });
    }
    quint16 port() const { return m_server.serverPort(); }
    QList<QTcpSocket *> sockets() const { return m_sockets; }

private:
    QTcpServer m_server;
    std::function<QByteArray(const QByteArray &)> m_answer;
    QList<QTcpSocket *> m_sockets;
};

LineAddress addressOf(const QString &text)
{
    return *LineAddress::parse(text, nullptr);
}

} // namespace

class tst_HostilePeers : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { qRegisterMetaType<jumo::ModbusResult>(); }
    void gatewayStallsInTheMiddleOfAReply_data();
    void gatewayStallsInTheMiddleOfAReply();
    void deviceServerNeverFallsSilent();
};

void tst_HostilePeers::gatewayStallsInTheMiddleOfAReply_data()
{
    QTest::addColumn<QByteArray>("tail");   // after the request's transaction id
    // The header and the first bytes of a 2-word reply, then nothing.
    QTest::newRow("half a reply") << QByteArray::fromHex("0000000701030400");
    // A length that counts from 0 and wraps, and one no Modbus PDU has.
    QTest::newRow("length 0") << QByteArray::fromHex("00000000010304000a000b");
    QTest::newRow("length 65535") << QByteArray::fromHex("0000ffff010304000a000b");
}

void tst_HostilePeers::gatewayStallsInTheMiddleOfAReply()
{
    QFETCH(QByteArray, tail);
    HostilePeer gateway([tail](const QByteArray &request) { return request.left(2) + tail; });
    TcpTransport transport(addressOf(QStringLiteral("tcp://127.0.0.1:%1").arg(gateway.port())),
                           *LineFormat::parse(19200, QStringLiteral("8N1")));
    QSignalSpy opened(&transport, &Transport::opened);
    QSignalSpy finished(&transport, &Transport::finished);
    QString error;
    QVERIFY2(transport.open(&error), qPrintable(error));
    QVERIFY(opened.wait());
    ModbusRequest request = ModbusRequest::read(1, 0x00B1, 2);
    request.timeoutMs = 200;
    transport.send(request);
    // Qt's client stops its timer once a header has come: without a guard of our own,
    // this request would never finish.
    QVERIFY(finished.wait(10000));
    const auto result = finished.first().first().value<ModbusResult>();
    QVERIFY(result.status != ModbusResult::Status::Ok);
    QVERIFY2(!result.errorText.isEmpty(), "says why");
}

void tst_HostilePeers::deviceServerNeverFallsSilent()
{
    HostilePeer server([](const QByteArray &) { return QByteArray(); });
    RtuTcpTransport transport(addressOf(QStringLiteral("rtu+tcp://127.0.0.1:%1").arg(server.port())),
                              *LineFormat::parse(9600, QStringLiteral("8N1")));
    QSignalSpy opened(&transport, &Transport::opened);
    QSignalSpy finished(&transport, &Transport::finished);
    QString error;
    QVERIFY2(transport.open(&error), qPrintable(error));
    QVERIFY(opened.wait());
    QTRY_COMPARE(server.sockets().size(), 1);
    // Noise (or another master) on the serial side, without a pause as long as the
    // frame gap at 9600 baud.
    QTcpSocket *socket = server.sockets().constFirst();
    QTimer noise;
    noise.setInterval(0);
    connect(&noise, &QTimer::timeout, socket, [socket] {
        if (socket->bytesToWrite() < 4096)
            socket->write(QByteArray(16, char(0x55)));
    });
    noise.start();
    ModbusRequest request = ModbusRequest::read(1, 0x00B1, 2);
    request.timeoutMs = 200;
    transport.send(request);
    QVERIFY(finished.wait(10000));
    const auto result = finished.first().first().value<ModbusResult>();
    // It ends, as a timeout. Which one depends on the machine: noise without a gap keeps
    // the request from going out ("never silent"); on a busy machine a gap may come, the
    // request goes out and the noise is no reply that fits ("no complete reply").
    QCOMPARE(result.status, ModbusResult::Status::Timeout);
    QVERIFY2(result.errorText.contains(QLatin1String("silent")) || result.errorText.contains(QLatin1String("no complete reply")),
             qPrintable(result.errorText));
}

QTEST_GUILESS_MAIN(tst_HostilePeers)
#include "tst_hostilepeers.moc"
