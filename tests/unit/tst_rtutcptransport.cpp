// RTU over TCP finds the reply to its request in what the device server passes on:
// the manual's frames (IPC 300, 3.1), with stray bytes, an echo of the request, a
// garbled copy or another slave's answer in front, split replies, two replies at once,
// the checks that a reply fits its request, and a late reply never taken for the next
// request's.
#include "bus/rtustreamframer.h"
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
    void bytesBeforeTheRequestAnswerNothing();
    void lateReplyHoldsTheNextRequestOfItsDevice();
    void lateReplyThatNeverComesIsWaitedForOnlySoLong();
};

void tst_RtuTcpTransport::findsTheReply_data()
{
    QTest::addColumn<QByteArray>("received");
    QTest::addColumn<int>("skipped");     // -1: no reply (yet)
    QTest::addColumn<int>("crcErrors");
    QTest::addColumn<int>("mismatches");
    QByteArray garbled = readReply;
    garbled[4] = char(garbled[4] ^ 0x01);
    QTest::newRow("the manual's reply alone") << readReply << 0 << 0 << 0;
    QTest::newRow("a zero byte in front") << (QByteArray(1, '\0') + readReply) << 1 << 0 << 0;
    QTest::newRow("noise that starts like the reply") << (QByteArray::fromHex("0103") + readReply) << 2 << 1 << 0;
    QTest::newRow("the adapter's echo of the request") << (readRequestFrame + readReply) << 8 << 0 << 0;
    QTest::newRow("a garbled copy, then the reply") << (garbled + readReply) << 9 << 1 << 0;
    QTest::newRow("another slave's answer in front")
            << (RtuFrame::build(2, QByteArray::fromHex("03040000 0000")) + readReply) << 9 << 0 << 0;
    QTest::newRow("half a reply: wait") << readReply.left(5) << -1 << 0 << 0;
    QTest::newRow("only the address byte: wait") << readReply.left(1) << -1 << 0 << 0;
    QTest::newRow("a garbled reply alone: none") << garbled << -1 << 1 << 0;
    QTest::newRow("an exception reply") << RtuFrame::build(1, QByteArray::fromHex("8302")) << 0 << 0 << 0;
    QTest::newRow("another function's reply: none, counted")
            << RtuFrame::build(1, QByteArray::fromHex("060001 0002")) << -1 << 0 << 1;
    // An earlier reply of the same shape and then this one's: a device answers once, in
    // order, so the earlier one answered an earlier request.
    const QByteArray earlier = RtuFrame::build(1, QByteArray::fromHex("0304 4334 0000"));
    QTest::newRow("two replies at once: the last") << (earlier + readReply) << 9 << 0 << 1;
    QTest::newRow("a reply to a write of this device in front")
            << (RtuFrame::build(1, QByteArray::fromHex("1000D50002")) + readReply) << 8 << 0 << 1;
    QTest::newRow("a reply of another size in front")
            << (RtuFrame::build(1, QByteArray::fromHex("0302 4334")) + readReply) << 7 << 0 << 1;
    QTest::newRow("the reply and a stray byte behind it") << (readReply + QByteArray(1, '\x01')) << 0 << 0 << 0;
}

void tst_RtuTcpTransport::findsTheReply()
{
    QFETCH(QByteArray, received);
    QFETCH(int, skipped);
    QFETCH(int, crcErrors);
    QFETCH(int, mismatches);
    qsizetype skippedBytes = -1;
    int badFrames = -1;
    int otherFrames = -1;
    const std::optional<qsizetype> length
            = RtuStreamFramer::findReply(loadCurrentRead(), received, &skippedBytes, &badFrames, &otherFrames);
    QCOMPARE(badFrames, crcErrors);
    QCOMPARE(otherFrames, mismatches);
    if (skipped < 0) {
        QVERIFY(!length);
        return;
    }
    QVERIFY(length);
    QCOMPARE(int(skippedBytes), skipped);
    const QByteArray frame = received.mid(skippedBytes, *length);
    QVERIFY(RtuFrame::hasValidCrc(frame));
    // The reply is the last frame in what was received (a stray byte may follow it).
    QVERIFY(skippedBytes + *length >= received.size() - 1);
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
    const ModbusResult result = RtuStreamFramer::resultOfFrame(request, reply);
    QCOMPARE(int(result.status), status);
    QCOMPARE(result.words, words);
    QCOMPARE(result.exceptionCode, exceptionCode);
    if (result.status != ModbusResult::Status::Ok)
        QVERIFY(!result.errorText.isEmpty() || result.status == ModbusResult::Status::Exception);
    QCOMPARE(result.replyFrame, reply);
}

void tst_RtuTcpTransport::bytesBeforeTheRequestAnswerNothing()
{
    RtuStreamFramer framer;
    // The reply arrives before the request went out (a late one, or a lying server
    // sending ahead): it answers nothing asked now.
    QVERIFY(!framer.received(readReply, 0));
    QCOMPARE(framer.frame(loadCurrentRead(), 10), readRequestFrame);
    QVERIFY(!framer.received(QByteArray(), 11));
    const std::optional<ModbusResult> result = framer.received(readReply, 12);
    QVERIFY(result);
    QCOMPARE(result->status, ModbusResult::Status::Ok);
    // But it was heard (a scan learns so of late answers), once.
    QCOMPARE(result->unframedReceptions, 1);
    QCOMPARE(framer.frame(loadCurrentRead(), 20), readRequestFrame);
    QCOMPARE(framer.received(readReply, 21)->unframedReceptions, 0);
    // Bytes that make no frame during a request that gets no reply: heard too.
    framer.frame(loadCurrentRead(), 30);
    QVERIFY(!framer.received(readReply.right(3), 31));
    QCOMPARE(framer.timedOut(600).unframedReceptions, 1);
    framer.frame(loadCurrentRead(), 1700);
    QCOMPARE(framer.timedOut(2300).unframedReceptions, 0);
}

void tst_RtuTcpTransport::lateReplyHoldsTheNextRequestOfItsDevice()
{
    RtuStreamFramer framer;
    ModbusRequest first = ModbusRequest::read(1, 0x0100, 2);
    first.timeoutMs = 200;
    framer.frame(first, 0);
    const ModbusResult timeout = framer.timedOut(200);
    QCOMPARE(timeout.status, ModbusResult::Status::Timeout);
    QCOMPARE(framer.owedReplies(), 1);
    // The load current has the shape of the first's reply: it waits for that reply.
    const qint64 owedUntil = 200 + RtuStreamFramer::lateReplyMs;
    QCOMPARE(framer.holdUntil(loadCurrentRead(), 400), owedUntil);
    QCOMPARE(framer.holdUntil(ModbusRequest::read(1, 0x00B1, 10), 400), owedUntil);   // an exception fits any size
    QCOMPARE(framer.holdUntil(ModbusRequest::read(2, 0x00B1, 2), 400), 400);          // another device: not
    QCOMPARE(framer.holdUntil(ModbusRequest::write(1, 0x00D5, {1}), 400), 400);        // another function: not
    // The first's reply, late (its values are not the load current's).
    const QByteArray late = RtuFrame::build(1, QByteArray::fromHex("0304 4334 0000"));
    QVERIFY(!framer.received(late.left(4), 740));
    QCOMPARE(framer.holdUntil(loadCurrentRead(), 745), owedUntil);
    QVERIFY(!framer.received(late.mid(4), 750));
    QCOMPARE(framer.owedReplies(), 0);
    QCOMPARE(framer.holdUntil(loadCurrentRead(), 750), 750);
    framer.frame(loadCurrentRead(), 750);
    const std::optional<ModbusResult> result = framer.received(readReply, 760);
    QVERIFY(result);
    QCOMPARE(result->status, ModbusResult::Status::Ok);
    QCOMPARE(result->words, (QList<quint16>{0x70A3, 0x4145}));
    QCOMPARE(result->mismatches, 1);   // the late reply, dropped
}

void tst_RtuTcpTransport::lateReplyThatNeverComesIsWaitedForOnlySoLong()
{
    RtuStreamFramer framer;
    ModbusRequest request = loadCurrentRead();
    request.timeoutMs = 200;
    for (int attempt = 0; attempt < 3; ++attempt) {
        const qint64 sent = attempt * 2000;
        QCOMPARE(framer.holdUntil(request, sent), sent);
        framer.frame(request, sent);
        framer.timedOut(sent + 200);
        QCOMPARE(framer.holdUntil(request, sent + 400), sent + 200 + RtuStreamFramer::lateReplyMs);
    }
    // The device answers again: its reply is taken once nothing is owed any more.
    framer.frame(request, 6000);
    QVERIFY(framer.received(readReply, 6001));
    QCOMPARE(framer.owedReplies(), 0);
}

QTEST_GUILESS_MAIN(tst_RtuTcpTransport)
#include "tst_rtutcptransport.moc"
