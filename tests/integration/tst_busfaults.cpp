// The bus against both peers (our simulator and the libmodbus server) with injected
// faults: late replies, a stray byte, CRC errors, every exception code, a dropped
// reply and a dead device among live ones. Two devices poll two blocks of the same
// size with distinct constant values, so a reply taken for the wrong request would
// show up as a wrong value: none may ever reach a model.
#include "bus/bus.h"
#include "testpeers.h"

#include <QTest>

#include <cmath>

using namespace jumo;
using namespace jumo::test;

namespace {

// Counts what the bus delivers: good values, wrong values, and the statuses seen.
struct Observer
{
    QHash<DeviceId, int> good;
    int wrong = 0;
    QSet<QString> statuses;
};

} // namespace

class tst_BusFaults : public QObject
{
    Q_OBJECT

private slots:
    void faultsNeverDeliverWrongValues_data();
    void faultsNeverDeliverWrongValues();
    void deadDeviceAmongLiveOnes_data();
    void deadDeviceAmongLiveOnes();
    void readOnlyModeSendsNoWriteFrame_data();
    void readOnlyModeSendsNoWriteFrame();
    void writeConfirmedAndRefused_data();
    void writeConfirmedAndRefused();

private:
    struct Setup
    {
        TestLine line;
        std::unique_ptr<Peer> peer;
        Bus bus;
        DeviceId first = 0;
        DeviceId second = 0;
        Observer observed;
    };
    bool prepare(Setup &s, const QString &peerName);
    static void addPeerRows();
};

void tst_BusFaults::addPeerRows()
{
    QTest::addColumn<QString>("peer");
}

bool tst_BusFaults::prepare(Setup &s, const QString &peerName)
{
    if (!s.line.start())
        return false;
    s.peer = makePeer(peerName);
    if (!s.peer->start(s.line.deviceEnd(), {1, 2}))
        return false;
    const auto map = families().family("ipc300");
    for (quint8 slave : {quint8(1), quint8(2)}) {
        for (const QString &id : polledIds) {
            const RegisterEntry *e = map->entry(id);
            const QList<quint16> words = ValueCodec::encodeFloat(float(expectedValue(id, slave)), WordOrder::CDAB);
            if (!s.peer->setWords(slave, e->address, words))
                return false;
        }
    }
    BusSettings settings;
    settings.portName = s.line.masterEnd();
    settings.format = testFormat();
    settings.timeoutMs = 300;   // generous: tests run on slow, busy machines
    settings.retries = 2;
    s.bus.setSettings(settings);
    if (!s.bus.open())
        return false;
    s.first = s.bus.addDevice(map, 1);
    s.second = s.bus.addDevice(map, 2);
    for (DeviceId id : {s.first, s.second})
        s.bus.setPollEntries(id, polledIds);
    QObject::connect(&s.bus, &Bus::entriesUpdated, &s.bus, [&s](DeviceId id, const QStringList &ids) {
        const quint8 slave = s.bus.deviceAddress(id);
        for (const QString &entryId : ids) {
            const EntryState *state = s.bus.entryState(id, entryId);
            s.observed.statuses << QStringLiteral("%1:%2").arg(slave).arg(state->statusName());
            if (state->error != ReadError::None)
                continue;
            if (std::fabs(state->value.value.toDouble() - expectedValue(entryId, slave)) > 1e-3) {
                ++s.observed.wrong;
                qWarning() << "wrong value" << slave << entryId << state->value.display;
            } else {
                ++s.observed.good[id];
            }
        }
    });
    return true;
}

void tst_BusFaults::faultsNeverDeliverWrongValues_data()
{
    QTest::addColumn<QString>("peer");
    QTest::addColumn<QString>("fault");
    QTest::addColumn<int>("argument");
    QTest::addColumn<QString>("mustSee");      // a status the bus reports during the fault
    QTest::addColumn<QString>("mustNotSee");   // a status a retry must have hidden
    for (const char *peer : {"simulator", "libmodbus"}) {
        QTest::addRow("%s: late reply", peer) << peer << "late" << 450 << "" << "1:timeout";
        QTest::addRow("%s: stray byte before reply", peer) << peer << "stray" << 0 << "" << "1:timeout";
        QTest::addRow("%s: CRC error", peer) << peer << "badcrc" << 0 << "" << "1:timeout";
        QTest::addRow("%s: dropped reply", peer) << peer << "drop" << 0 << "" << "1:timeout";
        QTest::addRow("%s: exception 6 busy is retried", peer) << peer << "exception" << 6 << "" << "1:exception:6";
        for (int code : {1, 3, 4, 8})
            QTest::addRow("%s: exception %d", peer, code) << peer << "exception" << code
                                                          << QStringLiteral("1:exception:%1").arg(code) << "";
        // Exception 02 means "no such address": the block is split and the entry asked
        // again before it is called unavailable, so a single one hides nothing.
        QTest::addRow("%s: exception 2 once", peer) << peer << "exception" << 2 << "" << "1:unavailable";
    }
}

void tst_BusFaults::faultsNeverDeliverWrongValues()
{
    QFETCH(QString, peer);
    QFETCH(QString, fault);
    QFETCH(int, argument);
    QFETCH(QString, mustSee);
    QFETCH(QString, mustNotSee);
    Setup s;
    QVERIFY(prepare(s, peer));
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 4 && s.observed.good.value(s.second) >= 4, 20000);

    s.observed = Observer();
    QVERIFY(s.peer->setFault(1, fault, 1, argument));
    // The fault hits one request of slave 1; both devices must go on with good values.
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 8 && s.observed.good.value(s.second) >= 8, 30000);
    QCOMPARE(s.observed.wrong, 0);
    if (!mustSee.isEmpty())
        QVERIFY2(s.observed.statuses.contains(mustSee), qPrintable(QStringList(s.observed.statuses.values()).join(' ')));
    if (!mustNotSee.isEmpty())
        QVERIFY2(!s.observed.statuses.contains(mustNotSee), qPrintable(mustNotSee));

    const DeviceStatistics *stats = s.bus.statistics(s.first);
    if (fault == "late" || fault == "stray" || fault == "drop")
        QVERIFY(stats->timeouts >= 1);
    if (fault == "badcrc")
        QVERIFY(stats->crcErrors >= 1);
    if (fault == "exception")
        QCOMPARE(stats->exceptions.value(argument), 1);
    QCOMPARE(s.bus.statistics(s.second)->timeouts, 0);
    QVERIFY(s.bus.isOnline(s.first));
}

void tst_BusFaults::deadDeviceAmongLiveOnes_data()
{
    addPeerRows();
    QTest::newRow("simulator") << "simulator";
    QTest::newRow("libmodbus") << "libmodbus";
}

void tst_BusFaults::deadDeviceAmongLiveOnes()
{
    QFETCH(QString, peer);
    Setup s;
    QVERIFY(prepare(s, peer));
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 4, 20000);
    QSignalSpy online(&s.bus, &Bus::onlineChanged);

    QVERIFY(s.peer->setFault(1, "dead"));
    QTRY_VERIFY_WITH_TIMEOUT(!s.bus.isOnline(s.first), 20000);
    QCOMPARE(online.count(), 1);
    // Once it is offline, the live device keeps its pace.
    const int before = s.observed.good.value(s.second);
    QTest::qWait(2000);
    QVERIFY2(s.observed.good.value(s.second) - before >= 20,
             qPrintable(QString::number(s.observed.good.value(s.second) - before)));
    QVERIFY(s.observed.statuses.contains("1:timeout"));

    QVERIFY(s.peer->setFault(1, "none"));
    QTRY_VERIFY_WITH_TIMEOUT(s.bus.isOnline(s.first), 20000);
    const int after = s.observed.good.value(s.first);
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) > after, 10000);
    QCOMPARE(s.observed.wrong, 0);
}

void tst_BusFaults::readOnlyModeSendsNoWriteFrame_data()
{
    deadDeviceAmongLiveOnes_data();
}

void tst_BusFaults::readOnlyModeSendsNoWriteFrame()
{
    QFETCH(QString, peer);
    Setup s;
    QVERIFY(prepare(s, peer));
    const QList<quint16> setpointBefore = s.peer->words(1, 0x00D5, 2);
    s.bus.setReadOnly(true);
    QSignalSpy finished(&s.bus, &Bus::writeFinished);
    s.bus.write(s.first, "input_setpoint", "50");
    s.bus.write(s.first, "digital_output", "1");
    s.bus.writeBroadcast("ipc300", "input_setpoint", "50");
    QVERIFY(!s.bus.setHold(s.first, "input_setpoint", "50").isEmpty());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 3, 10000);
    for (const QList<QVariant> &args : finished)
        QCOMPARE(args.at(1).value<WriteOutcome>().result, WriteOutcome::Result::ReadOnlyMode);
    // Polling goes on; the far end has seen no write frame at all.
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 6, 20000);
    QCOMPARE(s.peer->writeFrames(), 0);
    QCOMPARE(s.peer->words(1, 0x00D5, 2), setpointBefore);
}

void tst_BusFaults::writeConfirmedAndRefused_data()
{
    deadDeviceAmongLiveOnes_data();
}

void tst_BusFaults::writeConfirmedAndRefused()
{
    QFETCH(QString, peer);
    Setup s;
    QVERIFY(prepare(s, peer));
    // Only the writes go over the line, so an injected fault meets the write it is for.
    s.bus.setPolling(false);
    QTest::qWait(300);
    QSignalSpy finished(&s.bus, &Bus::writeFinished);

    // A float goes out as one 0x10 request and is confirmed by reading it back.
    const int ticket = s.bus.write(s.first, "input_setpoint", "12.34");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 10000);
    QCOMPARE(finished.at(0).at(0).toInt(), ticket);
    WriteOutcome outcome = finished.at(0).at(1).value<WriteOutcome>();
    QCOMPARE(outcome.result, WriteOutcome::Result::Confirmed);
    QCOMPARE(outcome.readBack.display, QString("12.34"));
    QCOMPARE(s.peer->words(1, 0x00D5, 2), ValueCodec::encodeFloat(12.34f, WordOrder::CDAB));
    QCOMPARE(s.peer->writeFrames(), 1);

    // Refused with the family's own meaning of the exception code and the precondition.
    QVERIFY(s.peer->setFault(1, "exception", 1, 3));
    s.bus.write(s.first, "input_setpoint", "20");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 10000);
    outcome = finished.at(1).at(1).value<WriteOutcome>();
    QCOMPARE(outcome.result, WriteOutcome::Result::Refused);
    QCOMPARE(outcome.exceptionCode, 3);
    QVERIFY2(outcome.message.contains("Data value outside admissible value range"), qPrintable(outcome.message));
    QVERIFY2(outcome.message.contains("interface"), qPrintable(outcome.message));

    // Out of range: refused before the line, nothing sent.
    const int framesBefore = s.peer->writeFrames();
    s.bus.write(s.first, "input_setpoint", "150");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 3, 10000);
    QCOMPARE(finished.at(2).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Invalid);
    QCOMPARE(s.peer->writeFrames(), framesBefore);
    QCOMPARE(s.peer->words(1, 0x00D5, 2), ValueCodec::encodeFloat(12.34f, WordOrder::CDAB));
}

QTEST_GUILESS_MAIN(tst_BusFaults)
#include "tst_busfaults.moc"
