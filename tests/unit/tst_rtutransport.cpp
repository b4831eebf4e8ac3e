// RtuTransport::resultOf, the step between Qt's Modbus client and the bus: replies decoded
// by Qt's own client code (QModbusClient::processResponse, as on reception) and then
// classified. A read is decoded only when the reply fits it; a write is confirmed only by
// an echo of what was written; an exception keeps its code.
#include "bus/rtutransport.h"
#include "protocol/rtuframe.h"

#include <QModbusRtuSerialClient>
#include <QtTest>

using namespace jumo;

namespace {

class QtDecoder : public QModbusRtuSerialClient
{
public:
    using QModbusRtuSerialClient::processResponse;
};

// What the transport makes of a reply PDU (hex, function code first) to a request, with
// the error Qt gives it: ProtocolError for an exception, UnknownError for a response Qt
// cannot decode.
ModbusResult resultFor(const ModbusRequest &request, const char *pduHex)
{
    static QtDecoder qt;
    const QByteArray pdu = QByteArray::fromHex(pduHex);
    const QModbusResponse response(QModbusPdu::FunctionCode(quint8(pdu.at(0))), pdu.mid(1));
    QModbusDataUnit unit(QModbusDataUnit::HoldingRegisters, request.start,
                         request.isWrite() ? request.words : QList<quint16>(request.count));
    QModbusDevice::Error error = QModbusDevice::NoError;
    if (response.isException())
        error = QModbusDevice::ProtocolError;
    else if (!qt.processResponse(response, &unit))
        error = QModbusDevice::UnknownError;
    return RtuTransport::resultOf(request, error, unit, response, QStringLiteral("Qt's error text"));
}

} // namespace

class tst_RtuTransport : public QObject
{
    Q_OBJECT

private slots:
    void readReplies_data();
    void readReplies();
    void writeEchoes_data();
    void writeEchoes();
    void exceptionKeepsItsCode();
    void timeoutAndLostLine();
};

void tst_RtuTransport::readReplies_data()
{
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<int>("status");
    QTest::addColumn<QList<quint16>>("words");
    // IPC 300 manual 3.1: two words at 0x00B1 (load current).
    QTest::newRow("fits") << QByteArray("030470a34145") << int(ModbusResult::Status::Ok)
                          << QList<quint16>{0x70a3, 0x4145};
    QTest::newRow("one word short") << QByteArray("030270a3") << int(ModbusResult::Status::BadReply) << QList<quint16>{};
    QTest::newRow("one word more") << QByteArray("030670a341450001") << int(ModbusResult::Status::BadReply)
                                   << QList<quint16>{};
    QTest::newRow("byte count lies") << QByteArray("030670a34145") << int(ModbusResult::Status::BadReply)
                                     << QList<quint16>{};
}

void tst_RtuTransport::readReplies()
{
    QFETCH(QByteArray, pdu);
    QFETCH(int, status);
    QFETCH(QList<quint16>, words);
    const ModbusResult r = resultFor(ModbusRequest::read(1, 0x00b1, 2), pdu.constData());
    QCOMPARE(int(r.status), status);
    QCOMPARE(r.words, words);
    if (r.status != ModbusResult::Status::Ok)
        QVERIFY(!r.errorText.isEmpty());
}

void tst_RtuTransport::writeEchoes_data()
{
    QTest::addColumn<QList<quint16>>("written");
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<bool>("confirmed");
    QTest::newRow("single, echo") << QList<quint16>{0x0001} << QByteArray("0600100001") << true;
    QTest::newRow("single, other value") << QList<quint16>{0x0001} << QByteArray("0600100003") << false;
    QTest::newRow("single, other register") << QList<quint16>{0x0001} << QByteArray("0600110001") << false;
    QTest::newRow("multiple, echo") << QList<quint16>{0x0000, 0x41c8} << QByteArray("1000100002") << true;
    QTest::newRow("multiple, other register") << QList<quint16>{0x0000, 0x41c8} << QByteArray("1000120002") << false;
    QTest::newRow("multiple, other count") << QList<quint16>{0x0000, 0x41c8} << QByteArray("1000100001") << false;
    QTest::newRow("answer of a read") << QList<quint16>{0x0000, 0x41c8} << QByteArray("030400000000") << false;
}

void tst_RtuTransport::writeEchoes()
{
    QFETCH(QList<quint16>, written);
    QFETCH(QByteArray, pdu);
    QFETCH(bool, confirmed);
    const ModbusResult r = resultFor(ModbusRequest::write(1, 0x0010, written), pdu.constData());
    QCOMPARE(r.status == ModbusResult::Status::Ok, confirmed);
    if (!confirmed)
        QCOMPARE(int(r.status), int(ModbusResult::Status::BadReply));
    QVERIFY(RtuFrame::hasValidCrc(r.replyFrame));
}

void tst_RtuTransport::exceptionKeepsItsCode()
{
    for (int code : {0x01, 0x02, 0x03, 0x04, 0x06, 0x0a, 0x0b, 0xff}) {
        const ModbusResult r = resultFor(ModbusRequest::read(1, 0x00b1, 2),
                                         QByteArray("83" + QByteArray::number(code, 16).rightJustified(2, '0')).constData());
        QCOMPARE(int(r.status), int(ModbusResult::Status::Exception));
        QCOMPARE(r.exceptionCode, code);
        QCOMPARE(r.replyFrame, RtuFrame::build(1, QByteArray::fromHex("83") + char(code)));
    }
}

void tst_RtuTransport::timeoutAndLostLine()
{
    const ModbusRequest request = ModbusRequest::read(1, 0, 1);
    const ModbusResult timeout = RtuTransport::resultOf(request, QModbusDevice::TimeoutError, {}, {}, QStringLiteral("t"));
    QCOMPARE(int(timeout.status), int(ModbusResult::Status::Timeout));
    QVERIFY(timeout.replyFrame.isEmpty());
    QVERIFY(timeout.words.isEmpty());
    const ModbusResult lost = RtuTransport::resultOf(request, QModbusDevice::ConnectionError, {}, {}, QStringLiteral("l"));
    QCOMPARE(int(lost.status), int(ModbusResult::Status::LineDown));
    QCOMPARE(lost.errorText, QStringLiteral("l"));
}

QTEST_GUILESS_MAIN(tst_RtuTransport)
#include "tst_rtutransport.moc"
