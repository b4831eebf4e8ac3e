// The bus against the device simulator over a pty line: scan, error values, atomic
// float writes, broadcasts, command words, RAM overrides, setpoint hold, the IPC/TYA
// bus-error keepalive, and a port that goes away and comes back.
#include "bus/bus.h"
#include "logs/datalogger.h"
#include "bus/devicescanner.h"
#include "protocol/rtuframe.h"
#include "testpeers.h"

#include <QSignalSpy>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

namespace {

struct Frames
{
    QList<QByteArray> all;

    int count(quint8 slave, quint8 function, quint16 address = 0xFFFF) const
    {
        int n = 0;
        for (const QByteArray &f : all) {
            const quint16 a = quint16(quint8(f[2]) << 8 | quint8(f[3]));
            if (quint8(f[0]) == slave && quint8(f[1]) == function && (address == 0xFFFF || a == address))
                ++n;
        }
        return n;
    }
};

} // namespace

class tst_BusSimulator : public QObject
{
    Q_OBJECT

private slots:
    void scanFindsOneDeviceOfEachFamily();
    void errorValuesAreReportedAsSuch();
    void floatIsWrittenAtomicallyWith0x10();
    void broadcastIsReadBackFromEveryDevice();
    void commandWordsTakeEffect();
    void ramOverrideAndBackToDeviceValue();
    void holdRewritesRamSetpointButNeverEeprom();
    void holdStoppedForAnUnconfirmedDeviceSaysSo();
    void busErrorKeepalive();
    void lostPortFailsWritesAndComesBack();
    void dataLoggingRotatesFiles();
    void closeDuringAWriteSendsNothingLater();
    void broadcastRefusedWithOtherFamiliesOnTheLine();

private:
    struct Setup
    {
        TestLine line;
        SimulatorPeer sim;
        Bus bus;
        Frames frames;
    };
    bool prepare(Setup &s, const QList<QPair<QString, quint8>> &devices);
};

bool tst_BusSimulator::prepare(Setup &s, const QList<QPair<QString, quint8>> &devices)
{
    if (!s.line.start())
        return false;
    for (const auto &[family, address] : devices)
        s.sim.line().addDevice(families().family(family), address);
    if (!s.sim.start(s.line.deviceEnd(), {}))
        return false;
    QObject::connect(&s.sim.line(), &SimulatorLine::requestReceived, &s.bus,
                     [&s](const QByteArray &frame) { s.frames.all << frame; });
    BusSettings settings;
    settings.portName = s.line.masterEnd();
    settings.format = testFormat();
    settings.timeoutMs = 500;
    settings.reconnectIntervalMs = 200;
    s.bus.setSettings(settings);
    return s.bus.open();
}

void tst_BusSimulator::scanFindsOneDeviceOfEachFamily()
{
    Setup s;
    QVERIFY(prepare(s, {{"ipc300", 1}, {"tya200", 2}, {"quantrol", 3}, {"dtron300", 4}}));
    // Without a timeout override the scan must wait for the slowest family (250 ms).
    BusSettings settings = s.bus.settings();
    settings.timeoutMs = 0;
    s.bus.setSettings(settings);
    DeviceScanner scanner(s.bus, families().families());
    QMap<int, QString> found;
    connect(&scanner, &DeviceScanner::found, this,
            [&found](int address, std::shared_ptr<const RegisterMap> map) { found.insert(address, map->family); });
    QSignalSpy finished(&scanner, &DeviceScanner::finished);
    scanner.start(1, 6);
    QVERIFY(finished.wait(30000));
    QCOMPARE(found, (QMap<int, QString>{{1, "ipc300"}, {2, "tya200"}, {3, "quantrol"}, {4, "dtron300"}}));
}

void tst_BusSimulator::errorValuesAreReportedAsSuch()
{
    Setup s;
    QVERIFY(prepare(s, {{"ipc300", 1}}));
    SimulatedDevice *device = s.sim.line().device(1);
    device->forceStatus("load_current", ValueStatus::Overrange);
    device->forceStatus("load_voltage", ValueStatus::Underrange);
    device->forceStatus("power", ValueStatus::Invalid);
    const DeviceId id = s.bus.addDevice(families().family("ipc300"), 1);
    s.bus.setPolling(false);
    QSignalSpy cycle(&s.bus, &Bus::pollCycleFinished);
    s.bus.requestCycle(id);
    QVERIFY(cycle.wait(20000));
    QCOMPARE(s.bus.entryState(id, "load_current")->statusName(), QString("overrange"));
    QCOMPARE(s.bus.entryState(id, "load_voltage")->statusName(), QString("underrange"));
    QCOMPARE(s.bus.entryState(id, "power")->statusName(), QString("invalid"));
    QCOMPARE(s.bus.entryState(id, "load_current")->value.display, QString("Overrange"));
    QVERIFY(!s.bus.entryState(id, "load_current")->value.value.isValid());
    QCOMPARE(s.bus.entryState(id, "device_name")->value.display, QString("IPC300  "));
    // Every readable entry of the family was read in that one cycle.
    int readable = 0;
    for (const RegisterEntry &e : families().family("ipc300")->entries()) {
        if (e.isReadable() && e.alias.isEmpty()) {
            ++readable;
            QVERIFY2(s.bus.entryState(id, e.id) && s.bus.entryState(id, e.id)->hasValue(), qPrintable(e.id));
        }
    }
    QCOMPARE(readable, 111);
}

void tst_BusSimulator::floatIsWrittenAtomicallyWith0x10()
{
    Setup s;
    QVERIFY(prepare(s, {{"tya200", 7}}));
    const DeviceId id = s.bus.addDevice(families().family("tya200"), 7);
    QSignalSpy finished(&s.bus, &Bus::writeFinished);
    s.bus.write(id, "setpoint", "66.6");
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.at(0).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Confirmed);
    QCOMPARE(s.frames.count(7, 0x10, 0x010A), 1);
    QCOMPARE(s.frames.count(7, 0x06), 0);
    QCOMPARE(s.sim.line().device(7)->number("setpoint"), 66.6);
    // A one-word value goes out as 0x06.
    s.bus.write(id, "digital_output", "1");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 10000);
    QCOMPARE(s.frames.count(7, 0x06, 0x014A), 1);
}

void tst_BusSimulator::broadcastIsReadBackFromEveryDevice()
{
    Setup s;
    QVERIFY(prepare(s, {{"ipc300", 1}, {"ipc300", 5}}));
    s.bus.setPolling(false);
    s.bus.addDevice(families().family("ipc300"), 1);
    s.bus.addDevice(families().family("ipc300"), 5);
    QSignalSpy finished(&s.bus, &Bus::writeFinished);
    s.bus.writeBroadcast("ipc300", "input_setpoint", "33");
    QVERIFY(finished.wait(10000));
    const WriteOutcome outcome = finished.at(0).at(1).value<WriteOutcome>();
    QVERIFY2(outcome.result == WriteOutcome::Result::Confirmed, qPrintable(outcome.message));
    QCOMPARE(s.frames.count(0, 0x10, 0x00D5), 1);
    QCOMPARE(s.frames.count(1, 0x03, 0x00D5), 1);
    QCOMPARE(s.frames.count(5, 0x03, 0x00D5), 1);
    QCOMPARE(s.sim.line().device(1)->number("input_setpoint"), 33.0);
    QCOMPARE(s.sim.line().device(5)->number("input_setpoint"), 33.0);
}

void tst_BusSimulator::commandWordsTakeEffect()
{
    Setup s;
    QVERIFY(prepare(s, {{"quantrol", 3}}));
    const DeviceId id = s.bus.addDevice(families().family("quantrol"), 3);
    s.bus.setPollEntries(id, {"binary_outputs", "controller_status"});
    QSignalSpy finished(&s.bus, &Bus::writeFinished);
    // Quantrol 4.2: output K2 is 0x8002 (bit 1 with the activation bit 15).
    s.bus.write(id, "binary_output_control", "output_k2");
    s.bus.write(id, "controller_functions", "manual_mode");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 10000);
    // The output word is readable: confirmed by read-back. The command word is an action:
    // acknowledged, and nothing can read it back.
    QCOMPARE(finished.at(0).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Confirmed);
    QCOMPARE(finished.at(1).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Accepted);
    QCOMPARE(s.frames.count(3, 0x06, 0x0025), 1);
    QCOMPARE(s.sim.line().device(3)->word(0x0025), quint16(0x8002));
    QVERIFY(s.sim.line().device(3)->manualMode());
    QTRY_COMPARE_WITH_TIMEOUT(s.bus.entryState(id, "binary_outputs") ? s.bus.entryState(id, "binary_outputs")->value.raw : 0u,
                              0x0002u, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(s.bus.entryState(id, "controller_status")
                                     && (s.bus.entryState(id, "controller_status")->value.raw & 0x1000),
                             10000);
}

void tst_BusSimulator::ramOverrideAndBackToDeviceValue()
{
    Setup s;
    QVERIFY(prepare(s, {{"quantrol", 3}}));
    s.bus.setPolling(false);
    const DeviceId id = s.bus.addDevice(families().family("quantrol"), 3);
    SimulatedDevice *device = s.sim.line().device(3);
    QSignalSpy finished(&s.bus, &Bus::writeFinished);
    s.bus.write(id, "ram_controller_actual_value", "55");
    QVERIFY(finished.wait(10000));
    device->advance(1.0);
    QCOMPARE(device->number("actual_value_unfiltered"), 55.0);
    // Quantrol 4.7: 200001 hands the value back to the device's own measurement.
    s.bus.write(id, "ram_controller_actual_value", "200001");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 10000);
    QCOMPARE(finished.at(1).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Accepted);
    device->advance(1.0);
    QVERIFY(device->number("actual_value_unfiltered") != 55.0);
}

void tst_BusSimulator::holdRewritesRamSetpointButNeverEeprom()
{
    Setup s;
    QVERIFY(prepare(s, {{"ipc300", 1}, {"quantrol", 3}}));
    const DeviceId ipc = s.bus.addDevice(families().family("ipc300"), 1);
    const DeviceId quantrol = s.bus.addDevice(families().family("quantrol"), 3);
    QCOMPARE(s.bus.setHold(ipc, "input_setpoint", "25", 300), QString());
    const QString refused = s.bus.setHold(quantrol, "setpoint_sp1", "25", 300);
    QVERIFY2(refused.contains("EEPROM"), qPrintable(refused));
    QTRY_VERIFY_WITH_TIMEOUT(s.frames.count(1, 0x10, 0x00D5) >= 4, 10000);
    QCOMPARE(s.frames.count(3, 0x10), 0);
    QCOMPARE(s.sim.line().device(1)->number("input_setpoint"), 25.0);
    QCOMPARE(s.bus.setHold(ipc, "input_setpoint", QString()), QString());
    const int written = s.frames.count(1, 0x10, 0x00D5);
    QTest::qWait(1000);
    QCOMPARE(s.frames.count(1, 0x10, 0x00D5), written);
}

// 26.17: a hold that ends because the device is no longer confirmed (it was gone and
// answers again, so its identity is checked anew) ends with a word, not silently.
void tst_BusSimulator::holdStoppedForAnUnconfirmedDeviceSaysSo()
{
    Setup s;
    QVERIFY(prepare(s, {{"ipc300", 1}}));
    s.bus.setIdentityCheck(families().families());
    const DeviceId ipc = s.bus.addDevice(families().family("ipc300"), 1);
    QTRY_VERIFY_WITH_TIMEOUT(s.bus.identities().isTrusted(ipc), 20000);
    QSignalSpy stopped(&s.bus, &Bus::holdStopped);
    QCOMPARE(s.bus.setHold(ipc, "input_setpoint", "25", 2000), QString());
    QTRY_VERIFY_WITH_TIMEOUT(s.frames.count(1, 0x10, 0x00D5) >= 2, 10000);
    QVERIFY(stopped.isEmpty());
    // The device goes silent, is taken for offline and forgotten: the hold's next turn
    // finds a device whose identity is not confirmed.
    Fault dead;
    dead.mode = FaultMode::Dead;
    s.sim.line().setFault(1, dead);
    QTRY_VERIFY_WITH_TIMEOUT(!s.bus.identities().isTrusted(ipc), 30000);
    QTRY_COMPARE_WITH_TIMEOUT(stopped.count(), 1, 30000);
    QCOMPARE(stopped.first().at(0).toInt(), ipc);
    QCOMPARE(stopped.first().at(1).toString(), QString("input_setpoint"));
    QVERIFY2(stopped.first().at(2).toString().contains("not confirmed"), qPrintable(stopped.first().at(2).toString()));
    s.sim.line().setFault(1, Fault{});
    QTRY_VERIFY_WITH_TIMEOUT(s.bus.identities().isTrusted(ipc), 30000);
    // Once confirmed again nothing is written that nobody asked for since.
    const int written = s.frames.count(1, 0x10, 0x00D5);
    QTest::qWait(1000);
    QCOMPARE(s.frames.count(1, 0x10, 0x00D5), written);
}

void tst_BusSimulator::busErrorKeepalive()
{
    Setup s;
    QVERIFY(prepare(s, {{"ipc300", 1}, {"quantrol", 3}}));
    const DeviceId ipc = s.bus.addDevice(families().family("ipc300"), 1);
    const DeviceId quantrol = s.bus.addDevice(families().family("quantrol"), 3);
    s.bus.setPollEntries(ipc, {"load_current"});
    s.bus.setPollEntries(quantrol, {"controller_status"});
    s.bus.setPollInterval(ipc, 60000);
    s.bus.setPollInterval(quantrol, 60000);
    QTRY_VERIFY_WITH_TIMEOUT(s.frames.count(1, 0x03) >= 1 && s.frames.count(3, 0x03) >= 1, 10000);
    // IPC 300 raises a bus error after 10 s without a telegram: the bus talks to it at
    // least every 5 s whatever its poll interval; the Quantrol has no such timer.
    QTRY_VERIFY_WITH_TIMEOUT(s.frames.count(1, 0x03) >= 2, 8000);
    QCOMPARE(s.frames.count(3, 0x03), 1);
}

void tst_BusSimulator::lostPortFailsWritesAndComesBack()
{
    Setup s;
    QVERIFY(prepare(s, {{"ipc300", 1}}));
    const DeviceId id = s.bus.addDevice(families().family("ipc300"), 1);
    s.bus.setPollEntries(id, {"load_current"});
    QSignalSpy updated(&s.bus, &Bus::entriesUpdated);
    QVERIFY(updated.wait(10000));
    QSignalSpy state(&s.bus, &Bus::stateChanged);
    QSignalSpy finished(&s.bus, &Bus::writeFinished);

    // The device stops answering writes, then the adapter goes away with a write pending.
    s.sim.setFault(1, "drop", -1, 0);
    s.bus.write(id, "input_setpoint", "10");
    QTest::qWait(100);
    s.sim.stop();
    s.line.stop();
    QTRY_COMPARE_WITH_TIMEOUT(s.bus.state(), LineState::Lost, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 10000);
    const WriteOutcome lost = finished.at(0).at(1).value<WriteOutcome>();
    // It went out and its answer never came: nobody can say whether it was taken.
    QCOMPARE(lost.result, WriteOutcome::Result::Unknown);

    // The adapter comes back: the line reconnects by itself, polling resumes, and the
    // failed write is not replayed.
    s.sim.setFault(1, "none", -1, 0);
    QVERIFY(s.line.restart());
    QVERIFY(s.sim.reopen());
    const int writesBefore = s.sim.writeFrames();
    QTRY_COMPARE_WITH_TIMEOUT(s.bus.state(), LineState::Connected, 10000);
    updated.clear();
    QVERIFY(updated.wait(10000));
    QTRY_VERIFY_WITH_TIMEOUT(s.bus.entryState(id, "load_current")->isCurrent(), 10000);
    QTest::qWait(500);
    QCOMPARE(s.sim.writeFrames(), writesBefore);
    QCOMPARE(finished.count(), 1);
}

void tst_BusSimulator::dataLoggingRotatesFiles()
{
    Setup s;
    QVERIFY(prepare(s, {{"ipc300", 1}}));
    const DeviceId id = s.bus.addDevice(families().family("ipc300"), 1);
    s.bus.setPollEntries(id, {"load_current", "load_voltage"});
    QSignalSpy updated(&s.bus, &Bus::entriesUpdated);
    QVERIFY(updated.wait(10000));
    QTemporaryDir dir;
    DataLogger logger(&s.bus);
    DataLogger::Settings settings;
    settings.folder = dir.filePath("log");
    settings.intervalMs = 100;
    settings.maxFileBytes = 1024;
    settings.entries = {{id, "load_current"}, {id, "load_voltage"}};
    QString error;
    QVERIFY2(logger.start(settings, &error), qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(logger.files().size() >= 3, 20000);
    logger.stop();
    int rows = 0;
    for (const QString &path : logger.files()) {
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().split('\n');
        QCOMPARE(lines.first(), QByteArray("time,device,id,value,unit,status"));
        for (qsizetype i = 1; i < lines.size(); ++i) {
            if (lines[i].isEmpty())
                continue;
            const QList<QByteArray> fields = lines[i].split(',');
            QCOMPARE(fields.size(), 6);
            QCOMPARE(fields[1], QByteArray("ipc300@1"));
            QCOMPARE(fields[5], QByteArray("ok"));
            bool ok = false;
            fields[3].toDouble(&ok);
            QVERIFY(ok);
            ++rows;
        }
        QVERIFY(f.size() <= 1024 + 200);   // rotated once past the limit
    }
    QCOMPARE(rows, logger.rowsWritten());
    // Bad settings are refused with a reason.
    settings.entries.clear();
    QVERIFY(!logger.start(settings, &error));
    QVERIFY(error.contains("at least one value"));
}

void tst_BusSimulator::closeDuringAWriteSendsNothingLater()
{
    Setup s;
    QVERIFY(prepare(s, {{"ipc300", 1}}));
    s.bus.setPolling(false);
    const DeviceId id = s.bus.addDevice(families().family("ipc300"), 1);
    s.sim.setFault(1, "drop", -1, 0);   // the first write stays under way
    QList<WriteOutcome> outcomes;
    connect(&s.bus, &Bus::writeFinished, this, [&](int, const WriteOutcome &outcome) {
        outcomes << outcome;
        if (outcomes.size() == 1)
            s.bus.write(id, "input_setpoint", "21");   // a listener that chains writes
    });
    s.bus.write(id, "input_setpoint", "20");
    QTRY_COMPARE_WITH_TIMEOUT(s.sim.writeFrames(), 1, 10000);
    s.bus.close();
    QTRY_COMPARE_WITH_TIMEOUT(outcomes.size(), 2, 10000);
    QCOMPARE(outcomes[0].result, WriteOutcome::Result::Unknown);
    QVERIFY2(outcomes[0].message.contains("outcome is unknown"), qPrintable(outcomes[0].message));
    QCOMPARE(outcomes[1].result, WriteOutcome::Result::NotSent);
    s.sim.setFault(1, "none", -1, 0);
    QVERIFY(s.bus.open());
    QTest::qWait(1000);
    QCOMPARE(s.sim.writeFrames(), 1);   // the chained write never went out
}

void tst_BusSimulator::broadcastRefusedWithOtherFamiliesOnTheLine()
{
    Setup s;
    QVERIFY(prepare(s, {{"dtron300", 1}, {"quantrol", 3}}));
    s.bus.setPolling(false);
    s.bus.addDevice(families().family("dtron300"), 1);
    s.bus.addDevice(families().family("quantrol"), 3);
    QSignalSpy finished(&s.bus, &Bus::writeFinished);
    s.bus.writeBroadcast("dtron300", "setpoint", "50");   // 0x0047: a command word on a Quantrol
    QVERIFY(finished.wait(5000));
    const WriteOutcome outcome = finished.at(0).at(1).value<WriteOutcome>();
    QCOMPARE(outcome.result, WriteOutcome::Result::Invalid);
    QVERIFY2(outcome.message.contains("quantrol device at address 3"), qPrintable(outcome.message));
    QCOMPARE(s.frames.count(0, 0x10), 0);
}

QTEST_GUILESS_MAIN(tst_BusSimulator)
#include "tst_bussimulator.moc"
