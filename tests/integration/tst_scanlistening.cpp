// What a quick scan hears on a serial line, through Qt's RTU client over a pty pair: the
// device end is a raw port that the test writes bytes to at chosen moments. A late answer
// can land anywhere: inside the next probe (Qt calls it a mismatch), between two probes
// (Qt drops it unread), or split across the two, its tail in front of the next probe's
// window (Qt cannot frame what follows and times out without a word). Each must count as
// heard (Bus::strayReplies), and a reply that fits its request must not.
#include "bus/bus.h"
#include "bus/linetiming.h"
#include "protocol/rtuframe.h"
#include "testpeers.h"

#include <QSerialPort>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

class tst_ScanListening : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void fittingReplyIsNoStray();
    void silenceIsNoStray();
    void answerForAnotherAddressIsHeard();
    void tailOfALateAnswerIsHeard();
    void answerBetweenTwoProbesIsHeard();

private:
    // A quick probe of one word at 0x0000; when its frame reaches the device end, the
    // bytes are written there (none: silence). Returns whether it timed out.
    bool probe(quint8 slave, const QByteArray &answer);
    // The reply frame of slave to a one-word read: value 0x1234.
    static QByteArray reply(quint8 slave);

    std::unique_ptr<TestLine> m_line;
    std::unique_ptr<QSerialPort> m_device;
    std::unique_ptr<Bus> m_bus;
    ProtocolInfo m_timing;
};

void tst_ScanListening::init()
{
    m_line = std::make_unique<TestLine>();
    QVERIFY(m_line->start());
    m_device = std::make_unique<QSerialPort>(m_line->deviceEnd());
    m_device->setBaudRate(19200);
    QVERIFY(m_device->open(QIODevice::ReadWrite));
    m_bus = std::make_unique<Bus>();
    BusSettings settings;
    settings.portName = m_line->masterEnd();
    settings.format = testFormat();
    m_bus->setSettings(settings);
    QVERIFY(m_bus->open());
    m_timing = families().family("dtron300")->protocol;
}

void tst_ScanListening::cleanup()
{
    m_bus.reset();
    m_device.reset();
    m_line.reset();
}

QByteArray tst_ScanListening::reply(quint8 slave)
{
    return RtuFrame::build(slave, QByteArray::fromHex("03021234"));
}

bool tst_ScanListening::probe(quint8 slave, const QByteArray &answer)
{
    QByteArray received;
    const QByteArray request = RtuFrame::build(slave, QByteArray::fromHex("0300000001"));
    const QMetaObject::Connection c = connect(m_device.get(), &QSerialPort::readyRead, this, [&] {
        received += m_device->readAll();
        if (received.endsWith(request) && !answer.isEmpty()) {
            m_device->write(answer);
            m_device->flush();
        }
    });
    QSignalSpy finished(m_bus.get(), &Bus::probeFinished);
    const int ticket = m_bus->quickProbe(slave, 0x0000, 1, m_timing);
    const bool done = finished.wait(5000);
    disconnect(c);
    if (!done || finished.first().at(0).toInt() != ticket)
        return false;
    return finished.first().at(2).toBool();
}

void tst_ScanListening::fittingReplyIsNoStray()
{
    const quint64 before = m_bus->strayReplies();
    for (int i = 0; i < 5; ++i)
        QVERIFY(!probe(7, reply(7)));
    QTest::qWait(100);
    QVERIFY(probe(8, {}));   // the next request hears nothing of the replies before it
    QCOMPARE(m_bus->strayReplies(), before);
}

void tst_ScanListening::silenceIsNoStray()
{
    const quint64 before = m_bus->strayReplies();
    for (quint8 slave = 20; slave < 25; ++slave)
        QVERIFY(probe(slave, {}));
    QCOMPARE(m_bus->strayReplies(), before);
}

void tst_ScanListening::answerForAnotherAddressIsHeard()
{
    // The late answer of address 9 comes while 10 is asked: Qt's mismatch.
    const quint64 before = m_bus->strayReplies();
    QVERIFY(probe(10, reply(9)));
    QVERIFY(m_bus->strayReplies() > before);
}

void tst_ScanListening::tailOfALateAnswerIsHeard()
{
    // The last bytes of a late answer come in front of the next probe's window: Qt takes
    // the first for an address and the next for a function code, and either fails the
    // CRC or waits for bytes that never come.
    const QByteArray late = reply(9);
    const quint64 before = m_bus->strayReplies();
    QVERIFY(probe(10, late.right(3)));
    QVERIFY2(m_bus->strayReplies() > before, "the tail of a late answer went unheard");
}

void tst_ScanListening::answerBetweenTwoProbesIsHeard()
{
    // A whole late answer while nothing is out: Qt drops it when the next request goes.
    QVERIFY(probe(11, {}));
    const quint64 before = m_bus->strayReplies();
    m_device->write(reply(11));
    m_device->flush();
    QTest::qWait(200);
    QVERIFY(probe(12, {}));
    QVERIFY2(m_bus->strayReplies() > before, "an answer between two probes went unheard");
}

QTEST_GUILESS_MAIN(tst_ScanListening)
#include "tst_scanlistening.moc"
