// The simulated device follows the map's access rules and the family's limits with the
// manuals' exception codes, and its models move the way the issue describes.
#include "protocol/familyregistry.h"
#include "sim/simulateddevice.h"

#include <QTest>

using namespace jumo;

namespace {

const FamilyRegistry &registry()
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return r;
}

QByteArray pdu(const char *hex)
{
    return QByteArray::fromHex(hex);
}

} // namespace

class tst_SimulatedDevice : public QObject
{
    Q_OBJECT

private slots:
    void accessRules_data();
    void accessRules();
    void broadcastIsAppliedWithoutReply();
    void powerControllerFollowsSetpoint();
    void processControllerFollowsSetpointAndSwitchesLimits();
    void unpluggedInputReadsAsErrorValue();
};

void tst_SimulatedDevice::accessRules_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("reply");   // empty: no reply at all

    QTest::newRow("ipc300 read load current") << "ipc300" << pdu("0300B10002") << QByteArray();   // checked by size below
    QTest::newRow("ipc300 undefined address 0x0022 -> 02") << "ipc300" << pdu("0300220001") << pdu("8302");
    QTest::newRow("ipc300 read of write-only 0x00F1 -> 02") << "ipc300" << pdu("0300F10001") << pdu("8302");
    QTest::newRow("ipc300 126 words -> 02") << "ipc300" << pdu("030023007E") << pdu("8302");
    QTest::newRow("ipc300 write to read-only load current -> 08") << "ipc300" << pdu("1000B100020400000000")
                                                                  << pdu("9008");
    QTest::newRow("ipc300 function 0x2B -> 01") << "ipc300" << pdu("2B0E0100") << pdu("AB01");
    QTest::newRow("ipc300 read of zero words: silence") << "ipc300" << pdu("0300B10000") << QByteArray();
    QTest::newRow("quantrol 33 words -> 02") << "quantrol" << pdu("0300200021") << pdu("8302");
    QTest::newRow("quantrol write setpoint 25.0") << "quantrol" << pdu("1031000002040000" "41C8") << pdu("1031000002");
    QTest::newRow("dtron300 write one word of a float") << "dtron300" << pdu("0600778000") << pdu("0600778000");
}

void tst_SimulatedDevice::accessRules()
{
    QFETCH(QString, family);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, reply);
    SimulatedDevice device(registry().family(family), 1);
    const QByteArray answer = device.process(request, false);
    if (QByteArray(QTest::currentDataTag()).contains("read load current")) {
        QCOMPARE(answer.size(), 2 + 4);
        QCOMPARE(answer.left(2), pdu("0304"));
        return;
    }
    QCOMPARE(answer.toHex(), reply.toHex());
}

void tst_SimulatedDevice::broadcastIsAppliedWithoutReply()
{
    SimulatedDevice device(registry().family("ipc300"), 3);
    QCOMPARE(device.process(pdu("1000D50002040000" "4220"), true), QByteArray());
    QCOMPARE(device.number("input_setpoint"), 40.0);
}

void tst_SimulatedDevice::powerControllerFollowsSetpoint()
{
    SimulatedDevice device(registry().family("tya200"), 1);
    device.setNumber("setpoint", 0);
    device.advance(1.0);
    QVERIFY(device.number("load_current") < 0.1);
    device.setNumber("setpoint", 80);
    device.advance(1.0);
    const double current = device.number("load_current");
    QVERIFY2(current > 15 && current < 25, qPrintable(QString::number(current)));   // 184 V over 9.5 ohm
    QVERIFY(qAbs(device.number("power") - device.number("load_voltage") * current) < 5);
    // Above the max. alarm limit (30 A) the alarm bit and its bool twin switch on.
    device.setNumber("load_resistance", 5);
    device.setNumber("setpoint", 100);
    device.advance(1.0);
    QVERIFY(device.flag("malfunction_signals_1.max_alarm"));
    QVERIFY(device.flag("high_alarm"));
}

void tst_SimulatedDevice::processControllerFollowsSetpointAndSwitchesLimits()
{
    SimulatedDevice device(registry().family("quantrol"), 1);
    device.setNumber("controller_setpoint", 180);
    double previous = device.number("actual_value_filtered");
    for (int i = 0; i < 10; ++i) {
        device.advance(1.0);
        const double pv = device.number("actual_value_filtered");
        QVERIFY(pv > previous);   // first-order lag towards the setpoint
        previous = pv;
    }
    QVERIFY(!device.flag("limit_value_monitoring.limit_value_monitoring_2"));
    for (int i = 0; i < 60; ++i)
        device.advance(1.0);
    QVERIFY(qAbs(device.number("actual_value_filtered") - 180) < 1);
    QVERIFY(device.flag("limit_value_monitoring.limit_value_monitoring_1"));   // above 150
    QVERIFY(!device.flag("limit_value_monitoring.limit_value_monitoring_2"));  // below 200
    // Self-optimisation start (0x0047 bit 0) shows in the controller status.
    QCOMPARE(device.process(pdu("0600470001"), false), pdu("0600470001"));
    QVERIFY(device.tuning());
    QVERIFY(device.flag("controller_status.self_optimization_active"));
}

void tst_SimulatedDevice::unpluggedInputReadsAsErrorValue()
{
    SimulatedDevice device(registry().family("ipc300"), 1);
    QVERIFY(device.forceStatus("load_current", ValueStatus::Overrange));
    QCOMPARE(device.process(pdu("0300B10002"), false), pdu("0304" "0000" "7F80"));
    QVERIFY(device.forceStatus("load_current", ValueStatus::Invalid));
    QCOMPARE(device.process(pdu("0300B10002"), false), pdu("0304" "0000" "7FC0"));
    QVERIFY(device.forceStatus("load_current", ValueStatus::Underrange));
    QCOMPARE(device.process(pdu("0300B10002"), false), pdu("0304" "0000" "FF80"));
}

QTEST_GUILESS_MAIN(tst_SimulatedDevice)
#include "tst_simulateddevice.moc"
