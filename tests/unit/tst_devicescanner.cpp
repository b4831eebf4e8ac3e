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
    void thoroughScanIsTheDefault();
    void shortRangesBorrowListeners_data();
    void shortRangesBorrowListeners();
    void aShortRangeOfPromptDevicesIsProbedOnce();
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

void tst_DeviceScanner::thoroughScanIsTheDefault()
{
    Line line({{"ipc300", 1}}, 38400);
    QVERIFY(line.bus->open());
    DeviceScanner scanner(*line.bus, families().families());
    QCOMPARE(scanner.effectiveMode(1, 247), DeviceScanner::Mode::Thorough);   // not asked for
    QVERIFY(scanner.listenersFor(1, 3).isEmpty());
    scanner.setMode(DeviceScanner::Mode::Quick);
    QCOMPARE(scanner.effectiveMode(1, 247), DeviceScanner::Mode::Quick);
    QCOMPARE(scanner.effectiveMode(7, 7), DeviceScanner::Mode::Quick);
    QVERIFY(scanner.listenersFor(1, 247).isEmpty());
    QVERIFY(scanner.listenersFor(1, 31).isEmpty());
    // 248..255 alone borrow from 247 down, not from 1 up.
    const QList<int> high = scanner.listenersFor(250, 255);
    QVERIFY(!high.isEmpty());
    for (int a : high)
        QVERIFY2(a <= 247 && a > 247 - high.size(), qPrintable(QString::number(a)));
    // A long timeout would make the listeners a scan of their own: a short range is then
    // probed thoroughly.
    BusSettings slow = line.bus->settings();
    slow.timeoutMs = 5000;
    line.bus->setSettings(slow);
    QCOMPARE(scanner.effectiveMode(1, 3), DeviceScanner::Mode::Thorough);
    QVERIFY(scanner.listenersFor(1, 3).isEmpty());
    QCOMPARE(scanner.effectiveMode(1, 247), DeviceScanner::Mode::Quick);
}

void tst_DeviceScanner::shortRangesBorrowListeners_data()
{
    QTest::addColumn<QList<int>>("range");
    QTest::addColumn<QString>("family");     // the device in the range, answering late
    QTest::addColumn<int>("address");        // 0: none
    QTest::addColumn<int>("neighbour");      // a dTRON just outside the range, 0: none
    QTest::addColumn<bool>("monitored");     // the neighbour is on the bus
    // A range too short for its own first address to have gone quiet long enough, by the
    // end of the quick pass, to listen for the last ones' late answers.
    QTest::newRow("1..3, empty") << QList<int>{1, 2, 3} << QString() << 0 << 0 << false;
    QTest::newRow("1..3, dtron300 at 3 200 ms late, dtron300 at 5") << QList<int>{1, 2, 3} << "dtron300" << 3 << 5 << false;
    QTest::newRow("1..3, tya200 at 1 200 ms late, monitored dtron300 at 4") << QList<int>{1, 2, 3} << "tya200" << 1 << 4 << true;
    // As jumoctl find has it: 255 too, which is no place to look for listeners.
    QTest::newRow("1, 2 and 255, empty") << QList<int>{1, 2, 255} << QString() << 0 << 0 << false;
    QTest::newRow("7, tya200 at 7 200 ms late") << QList<int>{7} << "tya200" << 7 << 0 << false;
    QTest::newRow("245..247, quantrol at 247 200 ms late") << QList<int>{245, 246, 247} << "quantrol" << 247 << 244 << false;
}

void tst_DeviceScanner::shortRangesBorrowListeners()
{
    QFETCH(QList<int>, range);
    QFETCH(QString, family);
    QFETCH(int, address);
    QFETCH(int, neighbour);
    QFETCH(bool, monitored);
    QList<QPair<QString, int>> devices;
    if (address > 0)
        devices.append({family, address});
    if (neighbour > 0)
        devices.append({QStringLiteral("dtron300"), neighbour});
    Line line(devices, 38400);
    QVERIFY(line.bus->open());
    if (monitored)   // polled at its own full timeout, never at the quick one
        line.bus->addDevice(families().family("dtron300"), neighbour);
    if (address > 0)
        line.transport->answerDelayMs.insert(quint8(address), 200);

    DeviceScanner scanner(*line.bus, families().families());
    scanner.setMode(DeviceScanner::Mode::Quick);
    const QList<int> listeners = scanner.listenersFor(range);
    QVERIFY(!listeners.isEmpty());
    for (int a : listeners) {
        QVERIFY2(!range.contains(a) && a >= 1 && a <= 247, qPrintable(QString::number(a)));
        QVERIFY(!(monitored && a == neighbour));
    }

    QList<int> found;
    QList<int> shown;
    int total = -1;
    connect(&scanner, &DeviceScanner::found, &scanner, [&](int a) { found << a; });
    connect(&scanner, &DeviceScanner::unknownDevice, &scanner, [&](int a) { found << -a; });
    connect(&scanner, &DeviceScanner::progress, &scanner, [&](int a, int, int all) {
        shown << a;
        total = all;
    });
    QSignalSpy finished(&scanner, &Job::finished);
    const qsizetype before = line.transport->sent.size();
    const qint64 start = line.clock.nowMs();
    scanner.start(range);
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 3600 * 1000));
    QCOMPARE(scanner.result(), Job::Result::Succeeded);
    const qint64 lineMs = line.clock.nowMs() - start;

    // The range's device and nothing else: what answers at a listener is not reported.
    QCOMPARE(found, address > 0 ? QList<int>({address}) : QList<int>());
    QCOMPARE(line.transport->lateAnswersTakenAsOwn, 0);
    // Progress is the range's.
    for (int a : std::as_const(shown))
        QVERIFY2(range.contains(a), qPrintable(QString::number(a)));
    QCOMPARE(total, range.size() + scanner.reprobed());
    // The listeners go first, quickly; nothing but the range goes to 248..255, and nothing
    // to the monitored device at the quick timeout.
    int firstQuick = -1;
    for (qsizetype i = before; i < line.transport->sent.size(); ++i) {
        const FakeTransport::Sent &s = line.transport->sent.at(i);
        if (firstQuick < 0 && s.request.timeoutMs == scanner.quickTimeoutMs())
            firstQuick = s.request.slave;
        QVERIFY2(s.request.slave <= 247 || range.contains(s.request.slave), qPrintable(QString::number(s.request.slave)));
        if (monitored && s.request.slave == neighbour)
            QVERIFY(s.request.timeoutMs != scanner.quickTimeoutMs());
    }
    QVERIFY2(listeners.contains(firstQuick), qPrintable(QString::number(firstQuick)));
    // A listener gets one quick probe, and a thorough one (asked twice when silent) if it
    // is the one that listens after the quick pass.
    for (int a : listeners) {
        int probes = 0;
        for (qsizetype i = before; i < line.transport->sent.size(); ++i)
            probes += line.transport->sent.at(i).request.slave == a ? 1 : 0;
        QVERIFY2(probes <= 3, qPrintable(QStringLiteral("%1: %2 probes").arg(a).arg(probes)));
    }
    const qint64 thorough = scanner.thoroughWorstMs(range.size());
    if (address == 0) {   // an empty range: its addresses silent, quickly, and nothing heard
        QCOMPARE(scanner.reprobed(), 0);
        QVERIFY2(lineMs * 2 < thorough, qPrintable(QStringLiteral("%1 ms, thorough %2 ms").arg(lineMs).arg(thorough)));
    }
    qInfo("%s: %.2f s of line time (thorough at most %.2f s), %lld listener(s), %d address(es) probed again",
          QTest::currentDataTag(), double(lineMs) / 1000.0, double(thorough) / 1000.0, qint64(listeners.size()),
          scanner.reprobed());
}

void tst_DeviceScanner::aShortRangeOfPromptDevicesIsProbedOnce()
{
    // Addresses that answer at once end their probes early: the listeners span the time a
    // late answer may take on their own, so the last quick probes need no second look
    // (jumoctl scan 3..5 with a TYA 200 at 4 probed 3 and 5 again when they did not).
    Line line({{"tya200", 4}, {"ipc300", 5}}, 38400);
    QVERIFY(line.bus->open());
    const qsizetype before = line.transport->sent.size();
    const Outcome quick = scan(line, 3, 5, DeviceScanner::Mode::Quick);
    QCOMPARE(quick.found, QList<int>({4, 5}));
    QCOMPARE(quick.reprobed, 0);
    // The silent address once, quickly (probed thoroughly it had two at the full timeout).
    DeviceScanner timing(*line.bus, families().families());
    QList<int> timeouts;
    for (qsizetype i = before; i < line.transport->sent.size(); ++i) {
        if (line.transport->sent.at(i).request.slave == 3)
            timeouts << line.transport->sent.at(i).request.timeoutMs;
    }
    QCOMPARE(timeouts, QList<int>({timing.quickTimeoutMs()}));
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
