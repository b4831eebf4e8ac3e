// The scan in simulated line time: a quick scan of 1..247 finds every device in seconds,
// a device that answers late is found all the same (its late answer heard and never taken
// for another probe's), and a thorough scan probes every silent address twice at the full
// timeout. The pty tests of jumoctl scan against the simulator remain the proof on a line.
#include "bus/devicescanner.h"
#include "fakeline.h"

#include <QSignalSpy>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

class tst_DeviceScanner : public QObject
{
    Q_OBJECT

private slots:
    void quickScanTakesSeconds_data();
    void quickScanTakesSeconds();
    void lateDevicesAreFound_data();
    void lateDevicesAreFound();
    void thoroughScanGivesEveryAddressTheFullTimeout();
    void shortRangesAndGatewaysAreScannedThoroughly();
    void monitoredAddressesGetNoQuickProbe();

private:
    struct Outcome
    {
        QList<int> found;
        qint64 lineMs = -1;
        int reprobed = 0;
    };
    static Outcome scan(Line &line, int first, int last, DeviceScanner::Mode mode);
};

tst_DeviceScanner::Outcome tst_DeviceScanner::scan(Line &line, int first, int last, DeviceScanner::Mode mode)
{
    Outcome out;
    if (line.bus->state() != LineState::Connected && !line.bus->open())
        return out;
    DeviceScanner scanner(*line.bus, families().families());
    scanner.setMode(mode);
    QObject::connect(&scanner, &DeviceScanner::found, &scanner, [&](int address) { out.found << address; });
    QSignalSpy finished(&scanner, &Job::finished);
    const qint64 start = line.clock.nowMs();
    scanner.start(first, last);
    if (!line.runUntil([&] { return finished.count() == 1; }, 3600 * 1000) || scanner.result() != Job::Result::Succeeded)
        return out;
    out.lineMs = line.clock.nowMs() - start;
    out.reprobed = scanner.reprobed();
    std::sort(out.found.begin(), out.found.end());
    return out;
}

void tst_DeviceScanner::quickScanTakesSeconds_data()
{
    QTest::addColumn<int>("baud");
    QTest::addColumn<int>("limitS");   // the bound for 1..247
    QTest::newRow("38400") << 38400 << 30;
    QTest::newRow("19200") << 19200 << 45;
    QTest::newRow("9600") << 9600 << 60;
}

void tst_DeviceScanner::quickScanTakesSeconds()
{
    QFETCH(int, baud);
    QFETCH(int, limitS);
    Line line({{"ipc300", 1}, {"tya200", 5}, {"quantrol", 120}, {"dtron300", 200}}, baud);
    const Outcome quick = scan(line, 1, 247, DeviceScanner::Mode::Quick);
    QCOMPARE(quick.found, QList<int>({1, 5, 120, 200}));
    QVERIFY2(quick.lineMs <= limitS * 1000, qPrintable(QStringLiteral("%1 ms of line time").arg(quick.lineMs)));
    QCOMPARE(line.transport->lateAnswersTakenAsOwn, 0);
    qInfo("quick scan of 1..247 at %d baud: %.1f s of line time, %d address(es) probed again, %lld requests", baud,
          double(quick.lineMs) / 1000.0, quick.reprobed, qint64(line.transport->sent.size()));
}

void tst_DeviceScanner::lateDevicesAreFound_data()
{
    QTest::addColumn<int>("lateAddress");
    QTest::addColumn<QString>("family");
    QTest::addColumn<int>("delayMs");
    // First, in the middle, last of the range: the last one's late answer comes after the
    // quick pass, while only the listener's probe is out.
    QTest::newRow("dtron300 at 1, 200 ms late") << 1 << "dtron300" << 200;
    QTest::newRow("ipc300 at 77, 200 ms late") << 77 << "ipc300" << 200;
    QTest::newRow("quantrol at 246, 200 ms late") << 246 << "quantrol" << 200;
    QTest::newRow("tya200 at 247, 200 ms late") << 247 << "tya200" << 200;
    QTest::newRow("dtron300 at 100, 100 ms late") << 100 << "dtron300" << 100;
    QTest::newRow("dtron300 at 100, 250 ms late") << 100 << "dtron300" << 250;
}

void tst_DeviceScanner::lateDevicesAreFound()
{
    QFETCH(int, lateAddress);
    QFETCH(QString, family);
    QFETCH(int, delayMs);
    Line line({{"ipc300", 10}, {family, lateAddress}, {"dtron300", 200}}, 38400);
    QVERIFY(line.bus->open());
    line.transport->answerDelayMs.insert(quint8(lateAddress), delayMs);
    const Outcome quick = scan(line, 1, 247, DeviceScanner::Mode::Quick);
    QList<int> expected{10, lateAddress, 200};
    std::sort(expected.begin(), expected.end());
    QCOMPARE(quick.found, expected);
    // Its late answer was heard, by a probe of another address, and taken for nothing.
    QVERIFY(line.transport->lateAnswersHeard >= 1);
    QCOMPARE(line.transport->lateAnswersTakenAsOwn, 0);
    // Only what was heard is probed again: a few addresses, not the range.
    QVERIFY2(quick.reprobed <= 8, qPrintable(QString::number(quick.reprobed)));
    // Each costs a thorough probe or two: seconds more, not minutes.
    QVERIFY2(quick.lineMs <= 45 * 1000, qPrintable(QStringLiteral("%1 ms of line time").arg(quick.lineMs)));
    qInfo("%s: %.1f s of line time, %d address(es) probed again", QTest::currentDataTag(),
          double(quick.lineMs) / 1000.0, quick.reprobed);
}

void tst_DeviceScanner::thoroughScanGivesEveryAddressTheFullTimeout()
{
    Line line({{"ipc300", 3}, {"dtron300", 6}}, 38400);
    QVERIFY(line.bus->open());
    DeviceScanner timing(*line.bus, families().families());
    const int full = timing.fullTimeoutMs();
    QVERIFY(timing.quickTimeoutMs() < full);
    const Outcome thorough = scan(line, 1, 40, DeviceScanner::Mode::Thorough);
    QCOMPARE(thorough.found, QList<int>({3, 6}));
    QCOMPARE(thorough.reprobed, 0);
    for (int a = 1; a <= 40; ++a) {
        if (a == 3 || a == 6)
            continue;
        int probes = 0;
        for (const FakeTransport::Sent &s : std::as_const(line.transport->sent)) {
            if (s.request.slave == a) {
                QCOMPARE(s.request.timeoutMs, full);
                ++probes;
            }
        }
        QCOMPARE(probes, 2);   // asked again once when unanswered
    }
    QVERIFY2(thorough.lineMs >= 38 * 2 * full, qPrintable(QString::number(thorough.lineMs)));
}

void tst_DeviceScanner::shortRangesAndGatewaysAreScannedThoroughly()
{
    Line line({{"ipc300", 1}}, 38400);
    QVERIFY(line.bus->open());
    DeviceScanner scanner(*line.bus, families().families());
    QCOMPARE(scanner.effectiveMode(1, 247), DeviceScanner::Mode::Thorough);   // not asked for
    scanner.setMode(DeviceScanner::Mode::Quick);
    QCOMPARE(scanner.effectiveMode(1, 247), DeviceScanner::Mode::Quick);
    QCOMPARE(scanner.effectiveMode(1, 31), DeviceScanner::Mode::Quick);
    // Too short to have an address silent long enough to listen after the quick pass.
    QCOMPARE(scanner.effectiveMode(1, 5), DeviceScanner::Mode::Thorough);
    QCOMPARE(scanner.effectiveMode(7, 7), DeviceScanner::Mode::Thorough);
    const Outcome shortRange = scan(line, 1, 5, DeviceScanner::Mode::Quick);
    QCOMPARE(shortRange.found, QList<int>({1}));
    for (const FakeTransport::Sent &s : std::as_const(line.transport->sent))
        QCOMPARE(s.request.timeoutMs, scanner.fullTimeoutMs());
}

void tst_DeviceScanner::monitoredAddressesGetNoQuickProbe()
{
    // A monitored device is polled: a poll right after a lost quick probe of its address
    // could take the probe's late answer for its own. Its address is probed at the full
    // timeout; every other address quickly.
    Line line({{"ipc300", 1}, {"dtron300", 30}}, 38400);
    QVERIFY(line.bus->open());
    line.bus->addDevice(families().family("dtron300"), 30);
    line.transport->answerDelayMs.insert(30, 200);
    DeviceScanner timing(*line.bus, families().families());
    const qint64 start = line.clock.nowMs();
    const Outcome quick = scan(line, 1, 247, DeviceScanner::Mode::Quick);
    QCOMPARE(quick.found, QList<int>({1, 30}));
    QCOMPARE(line.transport->lateAnswersTakenAsOwn, 0);
    int quickProbes = 0;
    for (const FakeTransport::Sent &s : std::as_const(line.transport->sent)) {
        if (s.atMs < start)
            continue;
        if (s.request.slave == 30)
            QVERIFY(s.request.timeoutMs != timing.quickTimeoutMs());
        else if (s.request.timeoutMs == timing.quickTimeoutMs())
            ++quickProbes;
    }
    QVERIFY2(quickProbes >= 240, qPrintable(QString::number(quickProbes)));
}

QTEST_GUILESS_MAIN(tst_DeviceScanner)
#include "tst_devicescanner.moc"
