// RTU over TCP finds the reply to its request in what the device server passes on:
// the manual's frames (IPC 300, 3.1), with stray bytes, an echo of the request, a
// garbled copy or another slave's answer in front, split replies, and the checks that a
// reply fits its request.
#include "bus/rtutcptransport.h"
#include "protocol/rtuframe.h"

#include <QTest>

using namespace jumo;

Q_DECLARE_METATYPE(jumo::ModbusRequest)

namespace {

// IPC 300, 3.1: read the load current (2 words at 0x00B1) from slave 1, and its answer.
const QByteArray readRequestFrame = QByteArray::fromHex("010300B10002942C");
const QByteArray readReply = QByteArray::fromHex("01030470A34145E172");

ModbusRequest loadCurrentRead()
{
    return ModbusRequest::read(1, 0x00B1, 2);
}

} // namespace

class tst_RtuTcpTransport : public QObject
{
    Q_OBJECT

private slots:
    void findsTheReply_data();
    void findsTheReply();
    void resultFitsTheRequest_data();
    void resultFitsTheRequest();
};

void tst_RtuTcpTransport::findsTheReply_data()
{
    QTest::addColumn<QByteArray>("received");
    QTest::addColumn<int>("skipped");     // -1: no reply (yet)
    QTest::addColumn<int>("crcErrors");
    QByteArray garbled = readReply;
    garbled[4] = char(garbled[4] ^ 0x01);
    QTest::newRow("the manual's reply alone") << readReply << 0 << 0;
    QTest::newRow("a zero byte in front") << (QByteArray(1, '\0') + readReply) << 1 << 0;
    QTest::newRow("noise that starts like the reply") << (QByteArray::fromHex("0103") + readReply) << 2 << 1;
    QTest::newRow("the adapter's echo of the request") << (readRequestFrame + readReply) << 8 << 0;
    QTest::newRow("a garbled copy, then the reply") << (garbled + readReply) << 9 << 1;
    QTest::newRow("another slave's answer in front")
            << (RtuFrame::build(2, QByteArray::fromHex("03040000 0000")) + readReply) << 9 << 0;
    QTest::newRow("half a reply: wait") << readReply.left(5) << -1 << 0;
    QTest::newRow("only the address byte: wait") << readReply.left(1) << -1 << 0;
    QTest::newRow("a garbled reply alone: none") << garbled << -1 << 1;
    QTest::newRow("an exception reply") << RtuFrame::build(1, QByteArray::fromHex("8302")) << 0 << 0;
    QTest::newRow("another function's reply: none") << RtuFrame::build(1, QByteArray::fromHex("060001 0002")) << -1 << 0;
}

void tst_RtuTcpTransport::findsTheReply()
{
    QFETCH(QByteArray, received);
    QFETCH(int, skipped);
    QFETCH(int, crcErrors);
    qsizetype skippedBytes = -1;
    int badFrames = -1;
    const std::optional<qsizetype> length = RtuTcpTransport::findReply(loadCurrentRead(), received, &skippedBytes, &badFrames);
    QCOMPARE(badFrames, crcErrors);
    if (skipped < 0) {
        QVERIFY(!length);
        return;
    }
    QVERIFY(length);
    QCOMPARE(int(skippedBytes), skipped);
    const QByteArray frame = received.mid(skippedBytes, *length);
    QVERIFY(RtuFrame::hasValidCrc(frame));
    QCOMPARE(skippedBytes + *length, received.size());
}

void tst_RtuTcpTransport::resultFitsTheRequest_data()
{
    QTest::addColumn<ModbusRequest>("request");
    QTest::addColumn<QByteArray>("reply");
    QTest::addColumn<int>("status");
    QTest::addColumn<QList<quint16>>("words");
    QTest::addColumn<int>("exceptionCode");
    const int ok = int(ModbusResult::Status::Ok);
    const int exception = int(ModbusResult::Status::Exception);
    const int badReply = int(ModbusResult::Status::BadReply);
    QTest::newRow("the manual's read reply") << loadCurrentRead() << readReply << ok
                                             << QList<quint16>{0x70A3, 0x4145} << 0;
    QTest::newRow("a read reply of the wrong size")
            << loadCurrentRead() << RtuFrame::build(1, QByteArray::fromHex("030270A3")) << badReply << QList<quint16>{} << 0;
    QTest::newRow("exception 2") << loadCurrentRead() << RtuFrame::build(1, QByteArray::fromHex("8302")) << exception
                                 << QList<quint16>{} << 2;
    QTest::newRow("a gateway's exception 11") << loadCurrentRead() << RtuFrame::build(1, QByteArray::fromHex("830B"))
                                              << exception << QList<quint16>{} << 11;
    // IPC 300, 3.3: write 12.34 (2 words) to 0x00D5, echoed with address and count.
    const ModbusRequest write = ModbusRequest::write(1, 0x00D5, {0x70A4, 0x4145});
    QTest::newRow("a write echoed") << write << RtuFrame::build(1, QByteArray::fromHex("1000D50002")) << ok
                                    << QList<quint16>{} << 0;
    QTest::newRow("a write echo naming other registers")
            << write << RtuFrame::build(1, QByteArray::fromHex("1000D60002")) << badReply << QList<quint16>{} << 0;
    const ModbusRequest single = ModbusRequest::write(1, 0x0020, {7});
    QTest::newRow("a single write echoed") << single << RtuFrame::build(1, QByteArray::fromHex("0600200007")) << ok
                                           << QList<quint16>{} << 0;
    QTest::newRow("a single write echoing another value")
            << single << RtuFrame::build(1, QByteArray::fromHex("0600200008")) << badReply << QList<quint16>{} << 0;
}

void tst_RtuTcpTransport::resultFitsTheRequest()
{
    QFETCH(ModbusRequest, request);
    QFETCH(QByteArray, reply);
    QFETCH(int, status);
    QFETCH(QList<quint16>, words);
    QFETCH(int, exceptionCode);
    const ModbusResult result = RtuTcpTransport::resultOfFrame(request, reply);
    QCOMPARE(int(result.status), status);
    QCOMPARE(result.words, words);
    QCOMPARE(result.exceptionCode, exceptionCode);
    if (result.status != ModbusResult::Status::Ok)
        QVERIFY(!result.errorText.isEmpty() || result.status == ModbusResult::Status::Exception);
    QCOMPARE(result.replyFrame, reply);
}

QTEST_GUILESS_MAIN(tst_RtuTcpTransport)
#include "tst_rtutcptransport.moc"
