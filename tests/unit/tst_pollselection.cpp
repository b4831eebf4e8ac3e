// What "--poll FAMILY:..." makes of the words, against the real maps: the faceplate's
// entries (shown, scales, modes, program), the alarm bit fields, named entries, in
// address order and each once; and what it refuses.
#include "bus/pollselection.h"
#include "protocol/familyregistry.h"

#include <QTest>

using namespace jumo;

class tst_PollSelection : public QObject
{
    Q_OBJECT

private slots:
    void faceplateOfAPowerUnit();
    void faceplateOfAProgrammer();
    void alarms();
    void namedEntriesInAddressOrderOnce();
    void refused_data();
    void refused();

private:
    const FamilyRegistry m_registry = FamilyRegistry::load({}, true);
};

void tst_PollSelection::faceplateOfAPowerUnit()
{
    QString error;
    const auto selection = PollSelection::parse("ipc300:faceplate", m_registry, &error);
    QVERIFY2(selection, qPrintable(error));
    QCOMPARE(selection->family, QString("ipc300"));
    // The four values, what their bars are scaled by, where the modes come from.
    for (const char *id : {"input_setpoint", "load_voltage", "load_current", "power", "load_voltage_limit",
                           "power_limit", "nominal_current"})
        QVERIFY2(selection->entries.contains(id), id);
    const auto map = m_registry.family("ipc300");
    for (const FaceplateState &mode : map->faceplate.modes)
        QVERIFY2(selection->entries.contains(mode.when.section('.', 0, 0)), qPrintable(mode.when));
    // Nothing else: no identity texts, no alarm words.
    QVERIFY(!selection->entries.contains("software_version"));
    QVERIFY(!selection->entries.contains("malfunction_signal_1"));
}

void tst_PollSelection::faceplateOfAProgrammer()
{
    const auto selection = PollSelection::parse("dtron300:faceplate", m_registry, nullptr);
    QVERIFY(selection);
    for (const char *id : {"filtered_process_value", "setpoint", "output_level", "controller_status", "segment_number",
                           "number_of_segments", "residual_segment_time", "program_status"})
        QVERIFY2(selection->entries.contains(id), id);
}

void tst_PollSelection::alarms()
{
    const auto ipc = PollSelection::parse("ipc300:alarms", m_registry, nullptr);
    QVERIFY(ipc);
    QVERIFY(ipc->entries.contains("malfunction_signal_1"));
    QVERIFY(ipc->entries.contains("malfunction_signal_2"));    // one alarm bit among status bits
    QVERIFY(!ipc->entries.contains("binary_signal_1"));        // status bits only
    const auto tya = PollSelection::parse("tya200:alarms", m_registry, nullptr);
    QVERIFY(tya);
    for (const char *id : {"malfunction_signals_1", "malfunction_signals_2", "malfunction_signals_3", "malfunction_signals_4"})
        QVERIFY2(tya->entries.contains(id), id);
    QVERIFY(!tya->entries.contains("binary_signals_2"));
    const auto map = m_registry.family("tya200");
    for (const QString &id : tya->entries) {
        const RegisterEntry *e = map->entry(id);
        QVERIFY(e && e->isReadable() && !e->bits.isEmpty());
    }
}

void tst_PollSelection::namedEntriesInAddressOrderOnce()
{
    const auto map = m_registry.family("ipc300");
    QString error;
    const auto entries = PollSelection::expand(*map, {"power", " load_voltage ", "power", "faceplate"}, &error);
    QVERIFY2(entries, qPrintable(error));
    QCOMPARE(entries->count("power"), 1);
    QVERIFY(entries->contains("load_voltage"));
    for (qsizetype i = 1; i < entries->size(); ++i)
        QVERIFY(map->entry(entries->at(i - 1))->address < map->entry(entries->at(i))->address);
}

void tst_PollSelection::refused_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("no family") << "faceplate" << "is not FAMILY:ENTRY";
    QTest::newRow("empty family") << ":faceplate" << "is not FAMILY:ENTRY";
    QTest::newRow("unknown family") << "s7:faceplate" << "unknown family 's7'";
    QTest::newRow("unknown entry") << "quantrol:faceplate,load_voltage" << "'load_voltage' is no entry of quantrol";
    QTest::newRow("write-only entry") << "ipc300:binary_signal_write" << "cannot be read";
    QTest::newRow("nothing") << "tya200:," << "name at least one entry of tya200";
    QTest::newRow("a reserve") << "ipc300:load_voltage,reserve_0023" << "ipc300 'reserve_0023' is a reserve";
}

void tst_PollSelection::refused()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    QString error;
    QVERIFY(!PollSelection::parse(text, m_registry, &error));
    QVERIFY2(error.contains(message), qPrintable(error));
}

QTEST_GUILESS_MAIN(tst_PollSelection)
#include "tst_pollselection.moc"
