// Parameter files: what they hold, how they round-trip, and what is refused.
#include "protocol/familyregistry.h"
#include "commissioning/parameterset.h"

#include <QTest>

using namespace jumo;

namespace {

const RegisterMap &map(const QString &family)
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return *r.family(family);
}

} // namespace

class tst_ParameterSet : public QObject
{
    Q_OBJECT

private slots:
    void holdsParametersNotCommandsOrOutputs();
    void jsonRoundTrip();
    void refusesBadFiles_data();
    void refusesBadFiles();
    void sameKeyInOtherObjectsIsNoDuplicate();
    void incompatibility();
    void differencesCompareStoredWords();
    void zeroAndNegativeZeroAreEqual();
    void restoreWritesOnlyWhatTheFileHolds();
};

void tst_ParameterSet::holdsParametersNotCommandsOrOutputs()
{
    const QStringList ipc = ParameterSet::parameterIds(map("ipc300"));
    QVERIFY(ipc.contains("input_setpoint"));
    QVERIFY(ipc.contains("max_alarm_limit"));
    QVERIFY(!ipc.contains("digital_output"));
    QVERIFY(!ipc.contains("load_current"));
    const QStringList quantrol = ParameterSet::parameterIds(map("quantrol"));
    QVERIFY(quantrol.contains("controller_xp1"));
    QVERIFY(!quantrol.contains("controller_functions"));       // command word
    QVERIFY(!quantrol.contains("binary_output_control"));      // outputs
    QVERIFY(!quantrol.contains("ram_controller_setpoint"));    // write-only override
    QVERIFY(ParameterSet::parameterIds(map("dtron300")).contains("segment_setpoint_1"));
}

void tst_ParameterSet::jsonRoundTrip()
{
    ParameterSet set;
    set.family = "ipc300";
    set.address = 7;
    set.time = QDateTime(QDate(2026, 11, 22), QTime(3, 30), Qt::UTC);
    set.softwareVersion = "123.01.01";
    set.identity.insert("device_name", "IPC300");
    set.values.insert("input_setpoint", "12.3399992");
    QString error;
    const std::optional<ParameterSet> back = ParameterSet::fromJson(set.toJson(), &error);
    QVERIFY2(back, qPrintable(error));
    QCOMPARE(back->family, set.family);
    QCOMPARE(back->address, 7);
    QCOMPARE(back->time, set.time);
    QCOMPARE(back->softwareVersion, set.softwareVersion);
    QCOMPARE(back->identity, set.identity);
    QCOMPARE(back->values, set.values);
}

void tst_ParameterSet::refusesBadFiles_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("problem");
    QTest::newRow("not JSON") << QByteArray("{ nope") << "not a parameter file";
    QTest::newRow("another JSON file") << QByteArray("{\"family\": \"ipc300\"}") << "jumo-parameters";
    QTest::newRow("future version") << QByteArray("{\"format\": \"jumo-parameters\", \"version\": 2}") << "version 2";
    QTest::newRow("no values") << QByteArray("{\"format\": \"jumo-parameters\", \"version\": 1, \"family\": \"ipc300\"}")
                               << "lacks";
    QTest::newRow("number instead of text")
            << QByteArray("{\"format\": \"jumo-parameters\", \"version\": 1, \"family\": \"ipc300\", \"values\": {\"input_setpoint\": 5}}")
            << "must be a text";
    const QByteArray head("{\"format\": \"jumo-parameters\", \"version\": 1, \"family\": \"ipc300\", \"values\": {}, ");
    QTest::newRow("version as a text") << QByteArray("{\"format\": \"jumo-parameters\", \"version\": \"1\"}") << "version 1 is not";
    QTest::newRow("address as a word") << head + "\"address\": \"one\"}" << "'address' must be a whole number 0..255";
    QTest::newRow("address 300") << head + "\"address\": 300}" << "'address' must be a whole number 0..255, not 300";
    QTest::newRow("family as a number") << QByteArray("{\"format\": \"jumo-parameters\", \"version\": 1, \"family\": 5, "
                                                      "\"values\": {}}")
                                        << "lacks";
    QTest::newRow("time that is none") << head + "\"time\": \"yesterday\"}" << "'time' is no ISO 8601 time";
    QTest::newRow("identity text as a number") << head + "\"identity\": {\"device_name\": 5}}"
                                               << "'device_name' must be a string, not 5";
    QTest::newRow("misspelt key") << head + "\"softwareVersoin\": \"1\"}" << "unknown key 'softwareVersoin'";
    // Qt's parser keeps one of two values of a key silently: a hand-edited file with a value
    // given twice would have one of them written.
    const QByteArray top("{\"format\": \"jumo-parameters\", \"version\": 1, \"family\": \"ipc300\", ");
    QTest::newRow("a value given twice")
            << top + "\"values\": {\"input_setpoint\": \"42\", \"input_setpoint\": \"43\"}}" << "'input_setpoint' twice";
    QTest::newRow("a value given twice, once escaped")
            << top + "\"values\": {\"input_setpoint\": \"42\", \"input\\u005fsetpoint\": \"43\"}}"
            << "'input_setpoint' twice";
    QTest::newRow("values given twice")
            << top + "\"values\": {\"input_setpoint\": \"42\"}, \"values\": {\"base_load\": \"5\"}}" << "'values' twice";
    QTest::newRow("family given twice") << top + "\"family\": \"tya200\", \"values\": {}}" << "'family' twice";
}

void tst_ParameterSet::refusesBadFiles()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, problem);
    QString error;
    QVERIFY(!ParameterSet::fromJson(json, &error));
    QVERIFY2(error.contains(problem), qPrintable(error));
}

void tst_ParameterSet::sameKeyInOtherObjectsIsNoDuplicate()
{
    // One key in different objects (and text that looks like a key) is fine.
    const QByteArray json("{\"format\": \"jumo-parameters\", \"version\": 1, \"family\": \"ipc300\", "
                          "\"identity\": {\"software_version\": \"123.01.01\", \"device_name\": \"\\\"x\\\": [{\\\"} \"}, "
                          "\"values\": {\"input_setpoint\": \"42\", \"base_load\": \"input_setpoint\"}}");
    QString error;
    const std::optional<ParameterSet> set = ParameterSet::fromJson(json, &error);
    QVERIFY2(set, qPrintable(error));
    QCOMPARE(set->values.value("input_setpoint"), QStringLiteral("42"));
    QCOMPARE(set->identity.value("device_name"), QStringLiteral("\"x\": [{\"} "));
}

void tst_ParameterSet::incompatibility()
{
    ParameterSet set;
    set.family = "ipc300";
    set.softwareVersion = "123.01.01";
    set.values.insert("input_setpoint", "20");
    QCOMPARE(set.incompatibility(map("ipc300"), "123.01.07"), QString());
    QVERIFY(set.incompatibility(map("ipc300"), "123.02.00").contains("software version 123.01.01"));
    QVERIFY(set.incompatibility(map("tya200"), "123.01.01").contains("family ipc300"));
    set.values.insert("input_setpoint", "250");
    QVERIFY(set.incompatibility(map("ipc300"), QString()).contains("outside the range"));
    set.values.clear();
    set.values.insert("load_current", "1");
    QVERIFY(set.incompatibility(map("ipc300"), QString()).contains("no parameter"));
}

void tst_ParameterSet::differencesCompareStoredWords()
{
    ParameterSet a;
    a.family = "quantrol";
    a.values.insert("setpoint_sp1", "25");
    a.values.insert("controller_xp1", "33.2999992");
    a.values.insert("limit_1_alarm_value", "150");
    ParameterSet b = a;
    b.values.insert("controller_xp1", "33.3");   // the same float
    b.values.insert("setpoint_sp1", "26");
    const QList<ParameterDifference> d = a.differences(b, map("quantrol"));
    QCOMPARE(d.size(), 1);
    QCOMPARE(d[0].id, QString("setpoint_sp1"));
    QCOMPARE(d[0].oldDisplay, QString("25"));
    QCOMPARE(d[0].newDisplay, QString("26"));
}

void tst_ParameterSet::zeroAndNegativeZeroAreEqual()
{
    ParameterSet a;
    a.family = "dtron300";
    a.values.insert("setpoint_w2", "0");
    a.values.insert("setpoint_w3", "-0");
    ParameterSet b = a;
    b.values.insert("setpoint_w2", "-0");
    b.values.insert("setpoint_w3", "0.0");
    QCOMPARE(a.differences(b, map("dtron300")).size(), 0);
    b.values.insert("setpoint_w3", "1e-45");   // the smallest float is no zero
    QCOMPARE(a.differences(b, map("dtron300")).size(), 1);
}

void tst_ParameterSet::restoreWritesOnlyWhatTheFileHolds()
{
    ParameterSet device;
    device.family = "quantrol";
    device.values.insert("setpoint_sp1", "25");
    device.values.insert("setpoint_sp2", "30");
    device.values.insert("limit_1_alarm_value", "150");
    ParameterSet file;   // a partial file: no setpoint 2, no limit
    file.family = "quantrol";
    file.values.insert("setpoint_sp1", "26");
    const QList<ParameterDifference> shown = device.differences(file, map("quantrol"));
    QCOMPARE(shown.size(), 3);   // a compare shows what the file lacks
    const QList<ParameterDifference> written = ParameterSet::toRestore(shown);
    QCOMPARE(written.size(), 1);
    QCOMPARE(written[0].id, QString("setpoint_sp1"));
    QCOMPARE(written[0].newValue, QString("26"));
    for (const ParameterDifference &d : shown)
        QCOMPARE(d.newHeld, d.id == QLatin1String("setpoint_sp1"));
}

QTEST_GUILESS_MAIN(tst_ParameterSet)
#include "tst_parameterset.moc"
