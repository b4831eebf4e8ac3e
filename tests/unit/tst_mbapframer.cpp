// Modbus TCP framing and the checks of a gateway's reply, without a socket: MbapFrame
// takes frames off a stream, MbapFramer takes a reply only when transaction id, protocol
// id, unit id, function and length fit the request, drops replies of earlier
// transactions, and says when a stream can no longer be framed. The frames are the IPC
// 300 manual's (3.1, 3.3) in MBAP headers.
#include "bus/mbapframer.h"
#include "protocol/mbapframe.h"

#include <QTest>

using namespace jumo;

Q_DECLARE_METATYPE(jumo::ModbusRequest)

namespace {

// IPC 300, 3.1: the load current (2 words at 0x00B1) of slave 1, and its answer's PDU.
ModbusRequest loadCurrentRead()
{
    return ModbusRequest::read(1, 0x00B1, 2);
}
const QByteArray readReplyPdu = QByteArray::fromHex("030470A34145");

QByteArray mbap(const char *headerHex, const QByteArray &pdu)
{
    return QByteArray::fromHex(headerHex) + pdu;
}

} // namespace

class tst_MbapFramer : public QObject
{
    Q_OBJECT

private slots:
    void takesFrames_data();
    void takesFrames();
    void consistentResponses_data();
    void consistentResponses();
    void checksTheReply_data();
    void checksTheReply();
    void repliesInPieces();
    void transactionIdsGoOnAfterAReset();
    void incompleteReplyBreaksTheStreamAtTimeout();
};

void tst_MbapFramer::takesFrames_data()
{
    QTest::addColumn<QByteArray>("stream");
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("size");
    const int incomplete = int(MbapFrame::Taken::Kind::Incomplete);
    const int frame = int(MbapFrame::Taken::Kind::Frame);
    const int unframable = int(MbapFrame::Taken::Kind::Unframable);
    const QByteArray reply = mbap("00070000000701", readReplyPdu);
    QTest::newRow("a whole reply") << reply << frame << 13;
    QTest::newRow("a reply and the next one's start") << reply + reply.left(5) << frame << 13;
    QTest::newRow("six header bytes") << reply.left(6) << incomplete << 0;
    QTest::newRow("a header and half its PDU") << reply.left(10) << incomplete << 0;
    QTest::newRow("protocol id 1") << mbap("00070001000701", readReplyPdu) << unframable << 0;
    QTest::newRow("length 1: no PDU") << QByteArray::fromHex("00070000000101") << unframable << 0;
    QTest::newRow("length 0") << QByteArray::fromHex("00070000000001") << unframable << 0;
    QTest::newRow("length 255") << QByteArray::fromHex("000700000" "0ff01") << unframable << 0;
    QTest::newRow("length 65535") << QByteArray::fromHex("0007000" "0ffff01") << unframable << 0;
    QTest::newRow("13 zero bytes") << QByteArray(13, '\0') << unframable << 0;
}

void tst_MbapFramer::takesFrames()
{
    QFETCH(QByteArray, stream);
    QFETCH(int, kind);
    QFETCH(int, size);
    const MbapFrame::Taken taken = MbapFrame::take(stream);
    QCOMPARE(int(taken.kind), kind);
    QCOMPARE(int(taken.size), size);
    if (taken.kind == MbapFrame::Taken::Kind::Frame) {
        QCOMPARE(taken.header.transaction, 7);
        QCOMPARE(taken.header.unit, 1);
        QCOMPARE(taken.pdu, readReplyPdu);
        QCOMPARE(MbapFrame::build(7, 1, taken.pdu), stream.left(size));
    }
}

void tst_MbapFramer::consistentResponses_data()
{
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<bool>("consistent");
    QTest::newRow("a read reply of 2 words") << readReplyPdu << true;
    QTest::newRow("a read reply 2 bytes short of its count") << QByteArray::fromHex("030470A3") << false;
    QTest::newRow("a read reply 2 bytes over its count") << QByteArray::fromHex("030470A341450000") << false;
    QTest::newRow("a read reply without its count") << QByteArray::fromHex("03") << false;
    QTest::newRow("a 0x10 reply") << QByteArray::fromHex("1000D50002") << true;
    QTest::newRow("a 0x10 reply cut short") << QByteArray::fromHex("1000D500") << false;
    QTest::newRow("a 0x06 reply") << QByteArray::fromHex("0600200007") << true;
    QTest::newRow("an exception") << QByteArray::fromHex("830B") << true;
    QTest::newRow("an exception with a byte more") << QByteArray::fromHex("830B00") << false;
    QTest::newRow("a function nobody here speaks") << QByteArray::fromHex("2B0E01") << false;
}

void tst_MbapFramer::consistentResponses()
{
    QFETCH(QByteArray, pdu);
    QFETCH(bool, consistent);
    QCOMPARE(MbapFrame::isConsistentResponse(pdu), consistent);
}

void tst_MbapFramer::checksTheReply_data()
{
    QTest::addColumn<ModbusRequest>("request");
    QTest::addColumn<QByteArray>("tail");        // what the gateway sends after the transaction id
    QTest::addColumn<bool>("ended");             // the request has its result
    QTest::addColumn<int>("status");
    QTest::addColumn<QList<quint16>>("words");
    QTest::addColumn<bool>("broken");            // the connection must be made anew
    QTest::addColumn<int>("mismatches");
    QTest::addColumn<QString>("what");           // in the reason given (empty: no reason)
    const int ok = int(ModbusResult::Status::Ok);
    const int exception = int(ModbusResult::Status::Exception);
    const int badReply = int(ModbusResult::Status::BadReply);
    const QList<quint16> none;
    const QList<quint16> loadCurrent{0x70A3, 0x4145};
    const ModbusRequest read = loadCurrentRead();
    // IPC 300, 3.3: 12.34 written to 0x00D5 as one 0x10 request.
    const ModbusRequest write = ModbusRequest::write(1, 0x00D5, {0x70A4, 0x4145});

    QTest::newRow("the manual's reply") << read << mbap("0000000701", readReplyPdu) << true << ok << loadCurrent << false
                                        << 0 << "";
    QTest::newRow("an exception") << read << QByteArray::fromHex("00000003018302") << true << exception << none << false
                                  << 0 << "";
    QTest::newRow("the gateway's exception 11") << read << QByteArray::fromHex("0000000301830B") << true << exception
                                                << none << false << 0 << "";
    QTest::newRow("unit 2's reply to unit 1") << read << mbap("0000000702", readReplyPdu) << true << badReply << none
                                              << false << 1 << "unit 2";
    QTest::newRow("unit 2's exception to unit 1") << read << QByteArray::fromHex("0000000302830B") << true << badReply
                                                  << none << false << 1 << "unit 2";
    QTest::newRow("a reply of 3 words to a read of 2")
            << read << mbap("0000000901", QByteArray::fromHex("030670A341450000")) << true << badReply << none << false
            << 1 << "3 words";
    QTest::newRow("a reply of another function") << read << mbap("0000000701", QByteArray::fromHex("040470A34145"))
                                                 << true << badReply << none << false << 1 << "function code 4";
    QTest::newRow("protocol id 1") << read << mbap("0001000701", readReplyPdu) << true << badReply << none << true << 1
                                   << "protocol id 1";
    QTest::newRow("an MBAP length 2 bytes short") << read << mbap("0000000501", readReplyPdu) << true << badReply
                                                  << none << true << 1 << "length does not fit";
    QTest::newRow("an MBAP length of 0") << read << QByteArray::fromHex("00000000010304000a000b") << true << badReply
                                         << none << true << 1 << "length 0";
    QTest::newRow("the reply and 13 junk bytes")
            << read << mbap("0000000701", readReplyPdu) + QByteArray::fromHex("deadbeefdeadbeefdeadbeefde") << true << ok
            << loadCurrent << true << 0 << "protocol id 48879";
    QTest::newRow("the reply twice") << read << mbap("0000000701", readReplyPdu) + QByteArray::fromHex("0001")
                    + mbap("0000000701", readReplyPdu)
                                     << true << ok << loadCurrent << false << 0 << "transaction id 1";
    QTest::newRow("the write echoed") << write << mbap("0000000601", QByteArray::fromHex("1000D50002")) << true << ok
                                      << none << false << 0 << "";
    QTest::newRow("the write echoed by unit 2") << write << mbap("0000000602", QByteArray::fromHex("1000D50002"))
                                                << true << badReply << none << false << 1 << "unit 2";
    QTest::newRow("the write echoed with other registers")
            << write << mbap("0000000601", QByteArray::fromHex("1000D60002")) << true << badReply << none << false << 1
            << "write reply";
}

void tst_MbapFramer::checksTheReply()
{
    QFETCH(ModbusRequest, request);
    QFETCH(QByteArray, tail);
    QFETCH(bool, ended);
    QFETCH(int, status);
    QFETCH(QList<quint16>, words);
    QFETCH(bool, broken);
    QFETCH(int, mismatches);
    QFETCH(QString, what);
    MbapFramer framer;
    // An earlier request that timed out: its reply comes first, and is dropped.
    framer.frame(ModbusRequest::read(1, 0x0100, 2));
    bool stale = false;
    framer.timedOut(&stale);
    const QByteArray sent = framer.frame(request);
    QCOMPARE(sent, MbapFrame::build(2, request.slave, request.pdu()));
    MbapFramer::Outcome outcome = framer.received(QByteArray::fromHex("00010000000701") + readReplyPdu);
    QVERIFY(!outcome.result);
    QVERIFY(!outcome.broken);
    QVERIFY2(outcome.what.contains("transaction id 1"), qPrintable(outcome.what));

    outcome = framer.received(sent.left(2) + tail);
    QCOMPARE(bool(outcome.result), ended);
    QCOMPARE(outcome.broken, broken);
    QVERIFY2(outcome.what.contains(what), qPrintable(outcome.what));
    if (!outcome.result)
        return;
    QCOMPARE(int(outcome.result->status), status);
    QCOMPARE(outcome.result->words, words);
    QCOMPARE(outcome.result->mismatches, mismatches + 1);   // with the late reply in front
    if (outcome.result->status == ModbusResult::Status::BadReply)
        QVERIFY(!outcome.result->errorText.isEmpty());
}

void tst_MbapFramer::repliesInPieces()
{
    MbapFramer framer;
    const QByteArray sent = framer.frame(loadCurrentRead());
    const QByteArray reply = sent.left(2) + mbap("0000000701", readReplyPdu);
    for (qsizetype i = 0; i + 1 < reply.size(); ++i) {
        const MbapFramer::Outcome outcome = framer.received(reply.mid(i, 1));
        QVERIFY2(!outcome.result && !outcome.broken, qPrintable(QString::number(i)));
    }
    const MbapFramer::Outcome outcome = framer.received(reply.right(1));
    QVERIFY(outcome.result);
    QCOMPARE(outcome.result->status, ModbusResult::Status::Ok);
    QCOMPARE(outcome.result->words, (QList<quint16>{0x70A3, 0x4145}));
    QCOMPARE(framer.pendingBytes(), 0);
}

void tst_MbapFramer::transactionIdsGoOnAfterAReset()
{
    MbapFramer framer;
    const QByteArray first = framer.frame(loadCurrentRead());
    framer.reset();
    const QByteArray second = framer.frame(loadCurrentRead());
    QVERIFY(first.left(2) != second.left(2));
    // The reply to the first, arriving on the new connection, is not the second's.
    MbapFramer::Outcome outcome = framer.received(first.left(2) + mbap("0000000701", readReplyPdu));
    QVERIFY(!outcome.result);
    outcome = framer.received(second.left(2) + mbap("0000000701", readReplyPdu));
    QVERIFY(outcome.result);
    QCOMPARE(outcome.result->mismatches, 1);
}

void tst_MbapFramer::incompleteReplyBreaksTheStreamAtTimeout()
{
    MbapFramer framer;
    const QByteArray sent = framer.frame(loadCurrentRead());
    QVERIFY(!framer.received(sent.left(2) + QByteArray::fromHex("000000070103")).result);
    bool broken = false;
    const ModbusResult result = framer.timedOut(&broken);
    QVERIFY(broken);
    QCOMPARE(result.status, ModbusResult::Status::Timeout);
    QVERIFY2(result.errorText.contains("incomplete"), qPrintable(result.errorText));
    QCOMPARE(framer.pendingBytes(), 0);

    framer.frame(loadCurrentRead());
    QVERIFY(!framer.timedOut(&broken).errorText.contains("incomplete"));
    QVERIFY(!broken);
}

QTEST_GUILESS_MAIN(tst_MbapFramer)
#include "tst_mbapframer.moc"
