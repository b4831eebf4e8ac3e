// The parameter editor's model under QAbstractItemModelTester, on a line of simulated
// devices: the tree by the manual's groups, what a person may type (the locale's numbers,
// ranges, whole numbers, enum labels) and what is refused with a reason, a value the
// device holds is no change, outcomes of writes (a confirmed change leaves, the others
// stay), read-only mode and a write under way refuse edits, and the device's value is
// never shown as current when it is not.
#include "bus/entrystate.h"
#include "fakeline.h"
#include "models/parametereditmodel.h"
#include "models/viewinterest.h"
#include "bus/valuetext.h"
#include "protocol/valuecodec.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QtTest>

using namespace jumo;
using namespace jumo::test;

class tst_ParameterEditModel : public QObject
{
    Q_OBJECT

private slots:
    void treeByTheManualsGroups_data();
    void treeByTheManualsGroups();
    void typedValuesAreCheckedAndRefusedWithAReason_data();
    void typedValuesAreCheckedAndRefusedWithAReason();
    void aValueTheDeviceHoldsIsNoChange();
    void enumsAndSwitchesTakeTheirLabels();
    void outcomesOfWrites();
    void readOnlyAndWritingRefuseEdits();
    void deviceValueIsNeverShownAsCurrentWhenItIsNot();
    void readBackShowsAtOnce();
};

namespace {

// A dTRON whose first alarm-text word is a choice and its second a switch: the shipped
// maps have no parameter of either kind, the editor must still offer them as such.
std::shared_ptr<const RegisterMap> dtronWithChoices()
{
    auto map = std::make_shared<RegisterMap>(*families().family("dtron300"));
    QList<RegisterEntry> entries = map->entries();
    for (RegisterEntry &e : entries) {
        if (e.id == "alarm_text_1_2") {
            e.type = ValueType::Enum;
            e.enumValues = {{0, "No text"}, {1, "Overtemperature"}, {2, "Sensor break"}};
        } else if (e.id == "alarm_text_3_4") {
            e.type = ValueType::Bool;
        }
    }
    map->setEntries(entries);
    return map;
}

QString section(const QString &group)
{
    return group.section(QLatin1Char(' '), 0, 0);
}

} // namespace

void tst_ParameterEditModel::treeByTheManualsGroups_data()
{
    QTest::addColumn<QString>("family");
    for (const char *family : {"ipc300", "tya200", "quantrol", "dtron300"})
        QTest::newRow(family) << QString::fromLatin1(family);
}

void tst_ParameterEditModel::treeByTheManualsGroups()
{
    QFETCH(QString, family);
    Line line({{family, 7}});
    QVERIFY(line.bus->open());
    const auto map = families().family(family);
    const DeviceId device = line.bus->addDevice(map, 7);
    ParameterEditModel model(line.bus.get(), device);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);

    // Every writable, unreserved parameter of the map once, in groups of its section.
    QStringList expected;
    for (const RegisterEntry &e : map->entries()) {
        if (e.control == "parameter" && e.isWritable() && !e.reserved)
            expected << e.id;
    }
    QStringList listed = model.entryIds();
    QCOMPARE(listed.size(), expected.size());
    std::sort(listed.begin(), listed.end());
    std::sort(expected.begin(), expected.end());
    QCOMPARE(listed, expected);
    QStringList groups;
    for (int g = 0; g < model.rowCount(); ++g) {
        const QModelIndex group = model.index(g, 0);
        groups << section(group.data().toString());
        QVERIFY(model.rowCount(group) > 0);
        QVERIFY(!(model.flags(group) & Qt::ItemIsEditable));
        for (int r = 0; r < model.rowCount(group); ++r) {
            const QString id = model.index(r, 0, group).data(ParameterEditModel::EntryIdRole).toString();
            QCOMPARE(section(map->entry(id)->group), groups.last());
            // Only the new value is edited; the search finds name, id and address.
            QVERIFY(model.flags(model.index(r, ParameterEditModel::NewValueColumn, group)) & Qt::ItemIsEditable);
            QVERIFY(!(model.flags(model.index(r, ParameterEditModel::DeviceColumn, group)) & Qt::ItemIsEditable));
            const QString search = model.index(r, 0, group).data(ParameterEditModel::SearchTextRole).toString();
            QVERIFY(search.contains(id));
            QVERIFY(search.contains(formatAddress(map->entry(id)->address)));
            QVERIFY(model.index(r, 0, group).data(Qt::ToolTipRole).toString().contains(formatAddress(map->entry(id)->address)));
        }
    }
    // In the manual's order (5.3 before 5.4), whatever the order of the addresses.
    QStringList sorted = groups;
    std::sort(sorted.begin(), sorted.end());
    QCOMPARE(groups, sorted);
    QCOMPARE(model.indexOf(expected.first()).data(ParameterEditModel::EntryIdRole).toString(), expected.first());
    line.run(3000);
}

void tst_ParameterEditModel::typedValuesAreCheckedAndRefusedWithAReason_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("id");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("exact");   // empty: refused
    QTest::addColumn<QString>("reason");  // part of the refusal

    QTest::newRow("in range") << "ipc300" << "en_US" << "load_monitoring_limit" << "42.5" << "42.5" << "";
    QTest::newRow("German comma") << "ipc300" << "de_DE" << "load_monitoring_limit" << "42,5" << "42.5" << "";
    QTest::newRow("German dot read one way only") << "ipc300" << "de_DE" << "load_monitoring_limit" << "42.5" << "42.5" << "";
    QTest::newRow("German 1.500 is 1500 or 1.5") << "ipc300" << "de_DE" << "setpoint_fixed_value" << "1.500" << ""
                                                  << "thousands separators";
    QTest::newRow("above the maximum") << "ipc300" << "en_US" << "load_monitoring_limit" << "120" << ""
                                       << "120 is out of range: Limit value for load monitoring takes 0.0 to 100.0 %";
    QTest::newRow("below the minimum") << "tya200" << "en_US" << "load_monitoring_limit" << "5" << ""
                                       << "takes 10.0 to 50.0 %";
    QTest::newRow("German range") << "ipc300" << "de_DE" << "load_monitoring_limit" << "100,5" << ""
                                  << "0,0 to 100,0 %";
    QTest::newRow("negative time") << "dtron300" << "en_US" << "ps1_dt" << "-5" << "" << "takes 0 to 65535 s";
    QTest::newRow("beyond int16") << "dtron300" << "en_US" << "ps1_y0" << "40000" << "" << "takes -32768 to 32767 %";
    QTest::newRow("fraction of a whole number") << "dtron300" << "en_US" << "ps1_dt" << "2.5" << ""
                                                << "takes whole numbers only";
    QTest::newRow("whole number with a zero fraction") << "dtron300" << "en_US" << "ps1_dt" << "25.0" << "25" << "";
    QTest::newRow("no number") << "dtron300" << "en_US" << "ps1_pb1" << "abc" << "" << "'abc' is no number";
    QTest::newRow("float beyond a float") << "dtron300" << "en_US" << "ps1_pb1" << "1e40" << "" << "too large";
    QTest::newRow("unbounded float") << "dtron300" << "en_US" << "ps1_pb1" << "-12.25" << "-12.25" << "";
}

void tst_ParameterEditModel::typedValuesAreCheckedAndRefusedWithAReason()
{
    QFETCH(QString, family);
    QFETCH(QString, locale);
    QFETCH(QString, id);
    QFETCH(QString, typed);
    QFETCH(QString, exact);
    QFETCH(QString, reason);
    const QLocale before;
    QLocale::setDefault(QLocale(locale));
    const auto restore = qScopeGuard([before] { QLocale::setDefault(before); });

    Line line({{family, 7}});
    const DeviceId device = line.bus->addDevice(families().family(family), 7);
    ParameterEditModel model(line.bus.get(), device);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QSignalSpy counted(&model, &ParameterEditModel::changeCountChanged);
    QString message;
    const bool taken = model.setNewValue(id, typed, &message);
    QCOMPARE(taken, !exact.isEmpty());
    if (taken) {
        QCOMPARE(model.newValue(id), exact);
        QVERIFY(model.isChanged(id));
        QCOMPARE(model.changedIds(), QStringList{id});
        QCOMPARE(counted.size(), 1);
        QVERIFY(model.indexOf(id, ParameterEditModel::NewValueColumn).data(ParameterEditModel::ChangedRole).toBool());
        // Shown bold by the view, and marked in words and in the group's title too.
        QVERIFY(model.indexOf(id).data().toString().startsWith(QChar(0x25CF)));
        QVERIFY(model.indexOf(id).parent().data().toString().contains("(1 changed)"));
    } else {
        QVERIFY2(message.contains(reason), qPrintable(message));
        QVERIFY(!model.isChanged(id));
        QCOMPARE(counted.size(), 0);
    }
    // Through the view's way in as well.
    QCOMPARE(model.setData(model.indexOf(id, ParameterEditModel::NewValueColumn), typed), taken);
    // An empty field drops the change.
    QVERIFY(model.setNewValue(id, QString()));
    QVERIFY(!model.isChanged(id));
    QCOMPARE(model.changeCount(), 0);
}

void tst_ParameterEditModel::aValueTheDeviceHoldsIsNoChange()
{
    Line line({{"dtron300", 7}});
    QVERIFY(line.bus->open());
    const DeviceId device = line.bus->addDevice(families().family("dtron300"), 7);
    ParameterEditModel model(line.bus.get(), device);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    line.sim(7)->setNumber("ps1_pb1", 12.34);
    line.sim(7)->setNumber("ps1_dt", 80);
    QVERIFY(line.runUntil([&] {
        return model.indexOf("ps1_pb1", ParameterEditModel::DeviceColumn).data(ParameterEditModel::ValidityRole).toInt()
                == int(Validity::Current);
    }, 20000));
    // The edit starts from every digit the device holds, not from the one decimal shown.
    QCOMPARE(model.editText("ps1_pb1"), QString("12.34"));
    QString note;
    QVERIFY(model.setNewValue("ps1_pb1", "12.34", &note));
    QVERIFY(!model.isChanged("ps1_pb1"));
    QVERIFY2(note.contains("already holds"), qPrintable(note));
    QVERIFY(model.setNewValue("ps1_dt", "90", &note));
    QVERIFY(note.isEmpty());
    QVERIFY(model.isChanged("ps1_dt"));
    // Typed back to what the device holds: the change is gone.
    QVERIFY(model.setNewValue("ps1_dt", "80", &note));
    QVERIFY(!model.isChanged("ps1_dt"));
    QCOMPARE(model.changeCount(), 0);
    // Discard drops every change.
    QVERIFY(model.setNewValue("ps1_dt", "90"));
    QVERIFY(model.setNewValue("ps1_rt", "100"));
    QCOMPARE(model.changedIds(), QStringList({"ps1_dt", "ps1_rt"}));
    model.discardAll();
    QCOMPARE(model.changeCount(), 0);
}

void tst_ParameterEditModel::enumsAndSwitchesTakeTheirLabels()
{
    Line line(QList<QPair<QString, int>>{});
    const auto map = dtronWithChoices();
    line.add(map, 7);
    QVERIFY(line.bus->open());
    const DeviceId device = line.bus->addDevice(map, 7);
    ParameterEditModel model(line.bus.get(), device);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(model.setNewValue("alarm_text_1_2", "Sensor break"));
    QCOMPARE(model.newValue("alarm_text_1_2"), QString("2"));
    QCOMPARE(model.newValueText("alarm_text_1_2"), QString("Sensor break"));
    QVERIFY(model.setNewValue("alarm_text_1_2", "1"));
    QCOMPARE(model.newValueText("alarm_text_1_2"), QString("Overtemperature"));
    QCOMPARE(model.editText("alarm_text_1_2"), QString("1"));
    QString why;
    QVERIFY(!model.setNewValue("alarm_text_1_2", "7", &why));
    QVERIFY2(why.contains("is not a value"), qPrintable(why));
    QVERIFY(model.setNewValue("alarm_text_3_4", "On"));
    QCOMPARE(model.newValue("alarm_text_3_4"), QString("1"));
    QCOMPARE(model.newValueText("alarm_text_3_4"), QString("On"));
}

void tst_ParameterEditModel::outcomesOfWrites()
{
    Line line({{"dtron300", 7}});
    const DeviceId device = line.bus->addDevice(families().family("dtron300"), 7);
    ParameterEditModel model(line.bus.get(), device);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    for (const QString &id : QStringList{"ps1_dt", "ps1_rt", "ps1_tt", "ps1_y0"})
        QVERIFY(model.setNewValue(id, "11"));
    model.setWriting({"ps1_dt", "ps1_rt", "ps1_tt"});
    QCOMPARE(model.writeState("ps1_dt"), WriteCommand::State::Pending);
    QCOMPARE(model.resultText("ps1_dt"), QString("Writing..."));

    WriteOutcome confirmed;
    confirmed.result = WriteOutcome::Result::Confirmed;
    confirmed.message = "confirmed by read-back: 11";
    confirmed.readBack.status = ValueStatus::Ok;
    confirmed.readBack.value = qint64(11);
    confirmed.readBack.display = "11";
    model.setOutcome("ps1_dt", confirmed);
    WriteOutcome refused;
    refused.result = WriteOutcome::Result::Refused;
    refused.message = "refused by the device: exception 8, Write access to parameter denied";
    model.setOutcome("ps1_rt", refused);
    WriteOutcome lost;
    lost.result = WriteOutcome::Result::Unknown;
    lost.message = "no answer after 2 attempts";
    model.setOutcome("ps1_tt", lost);

    // Confirmed leaves the changes, shown as confirmed; the others stay with their outcome.
    QVERIFY(!model.isChanged("ps1_dt"));
    QCOMPARE(model.resultText("ps1_dt"), QString("Confirmed by read-back: 11 s"));
    QVERIFY(model.isChanged("ps1_rt"));
    QCOMPARE(model.writeState("ps1_rt"), WriteCommand::State::Refused);
    QVERIFY(model.indexOf("ps1_rt", ParameterEditModel::ResultColumn).data().toString().contains("Write access to parameter denied"));
    QVERIFY(model.isChanged("ps1_tt"));
    QVERIFY(model.resultText("ps1_tt").startsWith("Unknown, check the device"));
    QCOMPARE(model.changedIds(), QStringList({"ps1_rt", "ps1_tt", "ps1_y0"}));
    // A new value is another change: the old outcome no longer speaks for it.
    QVERIFY(model.setNewValue("ps1_rt", "12"));
    QCOMPARE(model.writeState("ps1_rt"), WriteCommand::State::Idle);
    QVERIFY(model.resultText("ps1_rt").isEmpty());
    model.setNotWritten("ps1_y0", "stopped before its turn");
    QCOMPARE(model.resultText("ps1_y0"), QString("Not written: stopped before its turn"));
    // Taking a change back takes its outcome with it.
    model.revert("ps1_tt");
    QVERIFY(!model.isChanged("ps1_tt"));
    QVERIFY(model.resultText("ps1_tt").isEmpty());
}

void tst_ParameterEditModel::readOnlyAndWritingRefuseEdits()
{
    Line line({{"quantrol", 7}});
    const DeviceId device = line.bus->addDevice(families().family("quantrol"), 7);
    ParameterEditModel model(line.bus.get(), device);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    const QModelIndex cell = model.indexOf("controller_y0", ParameterEditModel::NewValueColumn);
    QVERIFY(model.setNewValue("controller_y0", "5"));
    model.setLocked(true);
    QVERIFY(!(model.flags(cell) & Qt::ItemIsEditable));
    QString why;
    QVERIFY(!model.setNewValue("controller_y0", "6", &why));
    QVERIFY2(why.contains("write is under way"), qPrintable(why));
    QCOMPARE(model.newValue("controller_y0"), QString("5"));
    model.setLocked(false);
    model.discardAll();
    model.setReadOnly(true);
    QVERIFY(!(model.flags(cell) & Qt::ItemIsEditable));
    QVERIFY(!model.setNewValue("controller_y0", "6", &why));
    QVERIFY(why.contains("read-only"));
    QVERIFY(!model.setExactValue("controller_y0", "6", &why));
    QVERIFY(!model.setData(cell, "6"));
    QCOMPARE(model.changeCount(), 0);
}

void tst_ParameterEditModel::deviceValueIsNeverShownAsCurrentWhenItIsNot()
{
    Line line({{"dtron300", 7}});
    QVERIFY(line.bus->open());
    const DeviceId device = line.bus->addDevice(families().family("dtron300"), 7);
    ParameterEditModel model(line.bus.get(), device);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    const QModelIndex cell = model.indexOf("ps1_dt", ParameterEditModel::DeviceColumn);
    // Before the first reply: no number at all.
    QCOMPARE(cell.data().toString(), ValueText::noValue());
    line.sim(7)->setNumber("ps1_dt", 80);
    QVERIFY(line.runUntil([&] { return cell.data().toString() == "80"; }, 20000));
    QCOMPARE(cell.data(ParameterEditModel::ValidityRole).toInt(), int(Validity::Current));
    // Every reply lost: at every step on the way to unknown, a value that is not current
    // is marked stale in words or shows no number at all.
    line.transport->drop = [](const ModbusRequest &) { return true; };
    QStringList wrong;
    QVERIFY(line.runUntil([&] {
        const auto validity = Validity(cell.data(ParameterEditModel::ValidityRole).toInt());
        const QString shown = cell.data().toString();
        if ((validity == Validity::Stale && shown != "80 (stale)")
            || (validity == Validity::Unknown && shown != ValueText::noValue()))
            wrong << shown;
        return validity == Validity::Unknown;
    }, 120000));
    QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(", ")));
    QCOMPARE(cell.data().toString(), ValueText::noValue());
    QVERIFY(cell.data(Qt::ToolTipRole).toString().contains("Last known value: 80 s"));
    // A change made while the device is gone is kept, shown against no device value.
    QVERIFY(model.setNewValue("ps1_dt", "80"));
    QVERIFY(model.isChanged("ps1_dt"));
}

// 26.12: a confirmed write's read-back is the device's value at once, never the poll's of
// a moment before beside "Confirmed by read-back: 5000 W"; a later poll takes over.
void tst_ParameterEditModel::readBackShowsAtOnce()
{
    Line line({{"ipc300", 7}});
    QVERIFY(line.bus->open());
    const auto map = families().family("ipc300");
    const DeviceId device = line.bus->addDevice(map, 7);
    ParameterEditModel model(line.bus.get(), device);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    const QModelIndex cell = model.indexOf("power_limit", ParameterEditModel::DeviceColumn);
    line.sim(7)->setNumber("power_limit", 6000);
    QVERIFY(line.runUntil([&] { return cell.data().toString() == "6000"; }, 20000));
    QVERIFY(model.setNewValue("power_limit", "5000"));
    model.setWriting({"power_limit"});
    line.sim(7)->setNumber("power_limit", 5000);   // what the write did on the device
    WriteOutcome confirmed;
    confirmed.result = WriteOutcome::Result::Confirmed;
    confirmed.message = "confirmed by read-back: 5000";
    confirmed.readBack = ValueCodec::decode(*map->entry("power_limit"), *map,
                                            ValueCodec::encodeFloat(5000, map->protocol.floatWordOrder));
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    model.setOutcome("power_limit", confirmed);
    QCOMPARE(model.resultText("power_limit"), QString("Confirmed by read-back: 5000 W"));
    QCOMPARE(cell.data().toString(), QString("5000"));
    QCOMPARE(cell.data(ParameterEditModel::ValidityRole).toInt(), int(Validity::Current));
    QVERIFY(!changed.isEmpty());   // the view is told, not left to the next poll
    // A poll after the write reads what the device has now: soon, while the editor shows
    // the parameter (a setting not shown is read only about once a minute).
    ViewInterest shown(line.bus.get(), device);
    shown.setShown(&model, true, {"power_limit"});
    line.sim(7)->setNumber("power_limit", 4500);
    QVERIFY(line.runUntil([&] { return cell.data().toString() == "4500"; }, 20000));
}

QTEST_MAIN(tst_ParameterEditModel)
#include "tst_parametereditmodel.moc"
