// The TCP transports against peers that misbehave on purpose, over real sockets: a
// Modbus TCP gateway that sends part of a reply (or an MBAP header with an impossible
// length) and then nothing, replies of another unit, with another protocol id or junk
// behind them, and a serial device server that never falls silent, answers late or sends
// two replies at once. Each request must come to an end, never wait for ever with the
// line "connected", never take a reply that is not its own, and one bad frame must not
// cut the line off.
#include "bus/rtutcptransport.h"
#include "bus/tcptransport.h"
#include "protocol/mbapframe.h"
#include "protocol/rtuframe.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>

#include <memory>
#include <type_traits>

using namespace jumo;


namespace {

// Answers every request on its connection with what `answer` makes of it, after what
// `delay` says (at once when it says 0).
class HostilePeer : public QObject
{
public:
    explicit HostilePeer(std::function<QByteArray(const QByteArray &)> answer,
                         std::function<int(const QByteArray &)> delay = {})
        : m_answer(std::move(answer)), m_delay(std::move(delay))
    {
        m_server.listen(QHostAddress::LocalHost, 0);
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            QTcpSocket *socket = m_server.nextPendingConnection();
            connect(socket, &QTcpSocket::readyRead, socket, [this, socket] {
                const QByteArray request = socket->readAll();
                const QByteArray reply = m_answer(request);
                if (reply.isEmpty())
                    return;
                if (const int ms = m_delay ? m_delay(request) : 0; ms > 0)
                    QTimer::singleShot(ms, socket, [socket, reply] { socket->write(reply); });
                else
                    socket->write(reply);   // in one write: one segment on the loopback
            });
            m_sockets << socket;
        });
    }
    quint16 port() const { return m_server.serverPort(); }
    QList<QTcpSocket *> sockets() const { return m_sockets; }

private:
    QTcpServer m_server;
    std::function<QByteArray(const QByteArray &)> m_answer;
    std::function<int(const QByteArray &)> m_delay;
    QList<QTcpSocket *> m_sockets;
};

// The words a peer holds: each register's own address, so a reply tells what was read.
QByteArray readReplyPdu(quint16 start, quint16 count)
{
    QByteArray pdu(1, char(0x03));
    pdu.append(char(2 * count));
    for (quint16 a = start; a < start + count; ++a)
        pdu.append(char(a >> 8)).append(char(a));
    return pdu;
}

QList<quint16> wordsAt(quint16 start, quint16 count)
{
    QList<quint16> words;
    for (quint16 a = start; a < start + count; ++a)
        words << a;
    return words;
}

quint16 wordAt(const QByteArray &bytes, qsizetype at)
{
    return quint16(quint8(bytes.at(at)) << 8 | quint8(bytes.at(at + 1)));
}

// A gateway's honest answer to an MBAP read request: its transaction id, its unit, the words.
QByteArray honestGatewayReply(const QByteArray &request)
{
    const MbapFrame::Taken taken = MbapFrame::take(request);
    if (taken.kind != MbapFrame::Taken::Kind::Frame)
        return {};
    return MbapFrame::build(taken.header.transaction, taken.header.unit,
                            readReplyPdu(wordAt(taken.pdu, 1), wordAt(taken.pdu, 3)));
}

// A device server's honest answer to an RTU read request.
QByteArray honestDeviceReply(const QByteArray &request)
{
    if (request.size() != 8 || !RtuFrame::hasValidCrc(request))
        return {};
    return RtuFrame::build(quint8(request[0]), readReplyPdu(wordAt(request, 2), wordAt(request, 4)));
}

LineAddress addressOf(const QString &text)
{
    return *LineAddress::parse(text, nullptr);
}

// A transport to the peer on the loopback, its connection standing; null if it did not.
template<typename T>
std::unique_ptr<T> connectedTo(const HostilePeer &peer)
{
    const char *scheme = std::is_same_v<T, TcpTransport> ? "tcp" : "rtu+tcp";
    auto transport = std::make_unique<T>(addressOf(QStringLiteral("%1://127.0.0.1:%2").arg(scheme).arg(peer.port())),
                                         *LineFormat::parse(19200, QStringLiteral("8N1")));
    QSignalSpy opened(transport.get(), &Transport::opened);
    QString error;
    if (!transport->open(&error) || !opened.wait(10000))
        return nullptr;
    return transport;
}

ModbusResult resultOf(QSignalSpy &finished, int index)
{
    return finished.at(index).first().value<ModbusResult>();
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
    void gatewayReplyThatIsNotTheRequests_data();
    void gatewayReplyThatIsNotTheRequests();
    void oneBadGatewayFrameCostsOneRequest_data();
    void oneBadGatewayFrameCostsOneRequest();
    void deviceServerLateReplyIsNotTheNextRequests();
    void deviceServerTwoRepliesInOneSegment();
    void finishedOnceNeverFromInsideSend_data();
    void finishedOnceNeverFromInsideSend();
    void closedRequestDoesNotEndTheNextConnections_data();
    void closedRequestDoesNotEndTheNextConnections();
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
    const std::unique_ptr<TcpTransport> transport = connectedTo<TcpTransport>(gateway);
    QVERIFY(transport);
    QSignalSpy finished(transport.get(), &Transport::finished);
    ModbusRequest request = ModbusRequest::read(1, 0x00B1, 2);
    request.timeoutMs = 200;
    transport->send(request);
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

void tst_HostilePeers::gatewayReplyThatIsNotTheRequests_data()
{
    QTest::addColumn<QByteArray>("header");   // what the gateway puts in its MBAP header after the transaction id
    QTest::addColumn<QString>("said");
    // Unit 2's reply to a request for unit 1: right in everything but the unit id.
    QTest::newRow("another unit's reply") << QByteArray::fromHex("0000000702") << "unit 2";
    QTest::newRow("protocol id 1") << QByteArray::fromHex("0001000701") << "protocol id 1";
    QTest::newRow("protocol id 0xFFFF") << QByteArray::fromHex("FFFF000701") << "protocol id 65535";
}

void tst_HostilePeers::gatewayReplyThatIsNotTheRequests()
{
    QFETCH(QByteArray, header);
    QFETCH(QString, said);
    int requests = 0;
    HostilePeer gateway([&requests, header](const QByteArray &request) {
        const MbapFrame::Taken taken = MbapFrame::take(request);
        // The first request gets the lie, every later one the truth.
        if (requests++ > 0)
            return honestGatewayReply(request);
        return request.left(2) + header + readReplyPdu(wordAt(taken.pdu, 1), wordAt(taken.pdu, 3));
    });
    const std::unique_ptr<TcpTransport> transport = connectedTo<TcpTransport>(gateway);
    QVERIFY(transport);
    QSignalSpy finished(transport.get(), &Transport::finished);
    QSignalSpy lost(transport.get(), &Transport::lost);
    ModbusRequest request = ModbusRequest::read(1, 0x00B1, 2);
    request.timeoutMs = 2000;
    transport->send(request);
    QVERIFY(finished.wait(10000));
    const ModbusResult result = resultOf(finished, 0);
    QCOMPARE(result.status, ModbusResult::Status::BadReply);
    QVERIFY(result.words.isEmpty());
    QVERIFY2(result.errorText.contains(said), qPrintable(result.errorText));
    QCOMPARE(result.mismatches, 1);

    // The next request is answered and taken, on this connection or a new one.
    transport->send(request);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 10000);
    QCOMPARE(resultOf(finished, 1).status, ModbusResult::Status::Ok);
    QCOMPARE(resultOf(finished, 1).words, wordsAt(0x00B1, 2));
    QCOMPARE(lost.count(), 0);
}

void tst_HostilePeers::oneBadGatewayFrameCostsOneRequest_data()
{
    QTest::addColumn<QByteArray>("tail");   // after the transaction id, to the first request
    const QByteArray reply = QByteArray::fromHex("0000000701") + readReplyPdu(0x00B1, 2);
    QTest::newRow("13 junk bytes after the reply") << reply + QByteArray::fromHex("5a5a5a5a5a5a5a5a5a5a5a5a5a");
    QTest::newRow("13 zero bytes after the reply") << reply + QByteArray(13, '\0');
    QTest::newRow("an MBAP length 2 bytes short") << QByteArray::fromHex("0000000501") + readReplyPdu(0x00B1, 2);
    QTest::newRow("an MBAP length 2 bytes over") << QByteArray::fromHex("0000000901") + readReplyPdu(0x00B1, 2);
    QTest::newRow("half a reply") << QByteArray::fromHex("0000000701030400");
}

void tst_HostilePeers::oneBadGatewayFrameCostsOneRequest()
{
    QFETCH(QByteArray, tail);
    int requests = 0;
    HostilePeer gateway([&requests, tail](const QByteArray &request) {
        return requests++ == 0 ? request.left(2) + tail : honestGatewayReply(request);
    });
    const std::unique_ptr<TcpTransport> transport = connectedTo<TcpTransport>(gateway);
    QVERIFY(transport);
    QSignalSpy finished(transport.get(), &Transport::finished);
    QSignalSpy lost(transport.get(), &Transport::lost);
    ModbusRequest request = ModbusRequest::read(1, 0x00B1, 2);
    request.timeoutMs = 300;
    // The bad frame may end its own request well or not; the requests after it are
    // answered, without the line being given up.
    QElapsedTimer clock;
    clock.start();
    for (int sent = 0; sent < 4; ++sent) {
        transport->send(request);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), sent + 1, 10000);
    }
    const ModbusResult first = resultOf(finished, 0);
    QVERIFY2(first.status != ModbusResult::Status::Ok || first.words == wordsAt(0x00B1, 2), qPrintable(first.errorText));
    for (int i = 1; i < 4; ++i) {
        const ModbusResult later = resultOf(finished, i);
        QVERIFY2(later.status == ModbusResult::Status::Ok, qPrintable(QStringLiteral("%1: %2").arg(i).arg(later.errorText)));
        QCOMPARE(later.words, wordsAt(0x00B1, 2));
    }
    QCOMPARE(lost.count(), 0);
    QVERIFY(transport->isOpen());
    qInfo("four requests, the first answered badly, in %lld ms; %d connection(s)", clock.elapsed(),
          int(gateway.sockets().size()));
}

void tst_HostilePeers::deviceServerLateReplyIsNotTheNextRequests()
{
    // Every reply 0.75 s late, beyond the requests' 0.5 s timeout.
    HostilePeer server(&honestDeviceReply, [](const QByteArray &) { return 750; });
    const std::unique_ptr<RtuTcpTransport> transport = connectedTo<RtuTcpTransport>(server);
    QVERIFY(transport);
    QSignalSpy finished(transport.get(), &Transport::finished);
    // Two reads of one device with replies of one shape: a late reply to the first fits the second.
    ModbusRequest first = ModbusRequest::read(1, 0x0100, 2);
    ModbusRequest second = ModbusRequest::read(1, 0x0200, 2);
    first.timeoutMs = second.timeoutMs = 500;
    transport->send(first);
    QVERIFY(finished.wait(10000));
    QCOMPARE(resultOf(finished, 0).status, ModbusResult::Status::Timeout);
    transport->send(second);   // at once, with no quiet time in between
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 10000);
    const ModbusResult result = resultOf(finished, 1);
    QVERIFY2(result.words != wordsAt(0x0100, 2), "the first request's late reply was taken for the second's");
    QVERIFY2(result.status != ModbusResult::Status::Ok || result.words == wordsAt(0x0200, 2), qPrintable(result.errorText));
    // The late reply came while the second waited for it, and is counted.
    QCOMPARE(result.status, ModbusResult::Status::Timeout);
    QCOMPARE(result.mismatches, 1);
}

void tst_HostilePeers::deviceServerTwoRepliesInOneSegment()
{
    // The first request is answered; the second with the first's reply again and then
    // its own, in one segment.
    QByteArray previous;
    HostilePeer server([&previous](const QByteArray &request) {
        QByteArray reply = previous + honestDeviceReply(request);
        previous = honestDeviceReply(request);
        return reply;
    });
    const std::unique_ptr<RtuTcpTransport> transport = connectedTo<RtuTcpTransport>(server);
    QVERIFY(transport);
    QSignalSpy finished(transport.get(), &Transport::finished);
    ModbusRequest first = ModbusRequest::read(1, 0x0100, 2);
    ModbusRequest second = ModbusRequest::read(1, 0x0200, 2);
    first.timeoutMs = second.timeoutMs = 2000;
    transport->send(first);
    QVERIFY(finished.wait(10000));
    QCOMPARE(resultOf(finished, 0).words, wordsAt(0x0100, 2));
    transport->send(second);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 10000);
    const ModbusResult result = resultOf(finished, 1);
    QCOMPARE(result.status, ModbusResult::Status::Ok);
    QCOMPARE(result.words, wordsAt(0x0200, 2));
    QCOMPARE(result.mismatches, 1);
}

void tst_HostilePeers::finishedOnceNeverFromInsideSend_data()
{
    QTest::addColumn<QString>("scheme");
    QTest::addColumn<bool>("closed");
    QTest::addColumn<int>("slave");
    QTest::addColumn<int>("status");
    QTest::addColumn<QString>("said");
    const int ok = int(ModbusResult::Status::Ok);
    const int lineDown = int(ModbusResult::Status::LineDown);
    QTest::newRow("gateway, closed") << "tcp" << true << 1 << lineDown << "not connected to the gateway 127.0.0.1:";
    QTest::newRow("gateway, a broadcast") << "tcp" << false << 0 << lineDown << "broadcasts are not sent";
    QTest::newRow("device server, closed") << "rtu+tcp" << true << 1 << lineDown
                                           << "not connected to the device server 127.0.0.1:";
    QTest::newRow("device server, a broadcast") << "rtu+tcp" << false << 0 << ok << "";
}

void tst_HostilePeers::finishedOnceNeverFromInsideSend()
{
    QFETCH(QString, scheme);
    QFETCH(bool, closed);
    QFETCH(int, slave);
    QFETCH(int, status);
    QFETCH(QString, said);
    HostilePeer peer([](const QByteArray &) { return QByteArray(); });
    std::unique_ptr<Transport> transport;
    if (scheme == "tcp")
        transport = connectedTo<TcpTransport>(peer);
    else
        transport = connectedTo<RtuTcpTransport>(peer);
    QVERIFY(transport);
    if (closed)
        transport->close();
    QSignalSpy finished(transport.get(), &Transport::finished);
    const ModbusRequest request = slave == 0 ? ModbusRequest::write(0, 0x00D5, {1, 2}) : ModbusRequest::read(1, 0x00B1, 2);
    transport->send(request);
    QCOMPARE(finished.count(), 0);
    QVERIFY(finished.wait(10000));
    QTest::qWait(300);
    QCOMPARE(finished.count(), 1);
    const ModbusResult result = resultOf(finished, 0);
    QCOMPARE(int(result.status), status);
    QVERIFY2(result.errorText.contains(said), qPrintable(result.errorText));
}

void tst_HostilePeers::closedRequestDoesNotEndTheNextConnections_data()
{
    QTest::addColumn<QString>("scheme");
    QTest::newRow("gateway") << "tcp";
    QTest::newRow("device server") << "rtu+tcp";
}

void tst_HostilePeers::closedRequestDoesNotEndTheNextConnections()
{
    // Closed with a request under way and opened again at once (the bus reopening a line):
    // the old request's end, said from the event loop, must not end the new connection's
    // request with the old connection's "line down".
    QFETCH(QString, scheme);
    HostilePeer silent([](const QByteArray &) { return QByteArray(); });
    std::unique_ptr<Transport> transport;
    if (scheme == "tcp")
        transport = connectedTo<TcpTransport>(silent);
    else
        transport = connectedTo<RtuTcpTransport>(silent);
    QVERIFY(transport);
    QSignalSpy finished(transport.get(), &Transport::finished);
    transport->send(ModbusRequest::read(1, 0x00B1, 2));
    transport->close();
    // Opened again and asked again: the new request ends by its own timeout, once.
    QSignalSpy opened(transport.get(), &Transport::opened);
    QString error;
    QVERIFY2(transport->open(&error), qPrintable(error));
    QVERIFY(opened.count() > 0 || opened.wait(10000));
    ModbusRequest request = ModbusRequest::read(1, 0x00B1, 2);
    request.timeoutMs = 500;
    transport->send(request);
    QVERIFY(finished.wait(10000));
    QTest::qWait(300);
    QCOMPARE(finished.count(), 1);
    QCOMPARE(int(resultOf(finished, 0).status), int(ModbusResult::Status::Timeout));
}

QTEST_GUILESS_MAIN(tst_HostilePeers)
#include "tst_hostilepeers.moc"
