// Clearing a broadcast in simulated time: the whole address range is scanned, and any
// device of another family (or of none) stops the scan and refuses; nothing is written.
#include "bus/broadcastclearance.h"
#include "fakeline.h"

#include <QSignalSpy>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

class tst_BroadcastClearance : public QObject
{
    Q_OBJECT

private slots:
    void lineOfOneFamilyIsCleared();
    void otherFamilyRefuses_data();
    void otherFamilyRefuses();

private:
    static bool clear(Line &line, BroadcastClearance &clearance, const QString &family);
};

bool tst_BroadcastClearance::clear(Line &line, BroadcastClearance &clearance, const QString &family)
{
    if (!line.bus->open())
        return false;
    QSignalSpy finished(&clearance, &Job::finished);
    clearance.start(families().family(family));
    return line.runUntil([&] { return finished.count() == 1; }, 24 * 3600 * 1000);
}

void tst_BroadcastClearance::lineOfOneFamilyIsCleared()
{
    Line line({{"dtron300", 3}, {"dtron300", 200}});
    BroadcastClearance clearance(*line.bus, families().families());
    QVERIFY(clear(line, clearance, "dtron300"));
    QCOMPARE(clearance.result(), Job::Result::Succeeded);
    QCOMPARE(clearance.familyAddresses(), (QList<quint8>{3, 200}));
    // Every address of the range was asked.
    for (int address = BroadcastClearance::firstAddress; address <= BroadcastClearance::lastAddress; ++address)
        QVERIFY2(line.transport->count(quint8(address)) > 0, qPrintable(QString::number(address)));
    QCOMPARE(line.transport->count(0), 0);
}

void tst_BroadcastClearance::otherFamilyRefuses_data()
{
    QTest::addColumn<QString>("other");
    QTest::addColumn<int>("address");
    QTest::addColumn<QString>("reason");
    QTest::newRow("ipc300 below") << "ipc300" << 1 << "address 1 answers as ipc300";
    QTest::newRow("quantrol above") << "quantrol" << 247 << "address 247 answers as quantrol";
    // The range ends at 255, where IPC 300 and TYA 200 answer whatever their address.
    QTest::newRow("tya200 at 255") << "tya200" << 255 << "address 255 answers as tya200";
}

void tst_BroadcastClearance::otherFamilyRefuses()
{
    QFETCH(QString, other);
    QFETCH(int, address);
    QFETCH(QString, reason);
    Line line({{"dtron300", 100}, {other, address}});
    BroadcastClearance clearance(*line.bus, families().families());
    QVERIFY(clear(line, clearance, "dtron300"));
    QCOMPARE(clearance.result(), Job::Result::Failed);
    QVERIFY2(clearance.errorText().contains(reason), qPrintable(clearance.errorText()));
    // It stops at the first other device.
    QCOMPARE(line.transport->count(quint8(address + 1)), 0);
    for (const FakeTransport::Sent &s : std::as_const(line.transport->sent))
        QVERIFY(!s.request.isWrite());
}

QTEST_GUILESS_MAIN(tst_BroadcastClearance)
#include "tst_broadcastclearance.moc"
