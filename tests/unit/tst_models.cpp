// The device models (live values, alarm bits, register map) under QAbstractItemModelTester
// for every family, through a device's whole life on a line: first values, changing
// values and alarm bits, lost replies, the adapter pulled, the device removed. The
// tester checks every signal and index the models give; the test checks what they show.
#include "bus/entrystate.h"
#include "bus/mirroredline.h"
#include "fakeline.h"
#include "models/alarmbitsmodel.h"
#include "models/livevaluesmodel.h"
#include "models/parametereditmodel.h"
#include "models/registermapmodel.h"

#include <QAbstractItemModelTester>
#include <QtTest>

using namespace jumo;
using namespace jumo::test;

class tst_Models : public QObject
{
    Q_OBJECT

private slots:
    void deviceModelsThroughALineLife_data();
    void deviceModelsThroughALineLife();
    void registerMapModelOfEveryFamily();
    void modelsOverAMirroredLine();
    void measuredValuesFirstInTheManualsOrder_data();
    void measuredValuesFirstInTheManualsOrder();
    void noLabelTwiceInOneView_data();
    void noLabelTwiceInOneView();
    void agesInTheLanguagesWay();
};

namespace {

int rowsWithValidity(const QAbstractItemModel &model, int role, Validity validity)
{
    int n = 0;
    for (int row = 0; row < model.rowCount(); ++row) {
        const QModelIndex index = model.index(row, 0);
        if (model.data(index, role).toInt() == int(validity))
            ++n;
    }
    return n;
}

// Reads every cell in every role the views use, as a view would.
void readAll(const QAbstractItemModel &model)
{
    for (int row = 0; row < model.rowCount(); ++row) {
        for (int column = 0; column < model.columnCount(); ++column) {
            const QModelIndex index = model.index(row, column);
            for (int role = 0; role < Qt::UserRole + 16; ++role)
                (void)model.data(index, role);
        }
    }
}

} // namespace

void tst_Models::deviceModelsThroughALineLife_data()
{
    QTest::addColumn<QString>("family");
    for (const char *family : {"ipc300", "tya200", "quantrol", "dtron300"})
        QTest::newRow(family) << QString::fromLatin1(family);
}

void tst_Models::deviceModelsThroughALineLife()
{
    QFETCH(QString, family);
    Line line({{family, 7}});
    QVERIFY(line.bus->open());
    const DeviceId device = line.bus->addDevice(families().family(family), 7);
    LiveValuesModel values(line.bus.get(), device);
    AlarmBitsModel alarms(line.bus.get(), device);
    QAbstractItemModelTester valuesTester(&values, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester alarmsTester(&alarms, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(values.rowCount() > 10);
    QVERIFY(alarms.rowCount() > 0);
    // Before the first reply nothing is current and nobody can say "no alarm".
    QCOMPARE(rowsWithValidity(values, LiveValuesModel::ValidityRole, Validity::Current), 0);
    QVERIFY(!alarms.alarmsKnown());

    QVERIFY(line.runUntil([&] { return alarms.alarmsKnown(); }, 20000));
    line.run(3000);
    const int current = rowsWithValidity(values, LiveValuesModel::ValidityRole, Validity::Current);
    QVERIFY2(current > values.rowCount() / 2, qPrintable(QStringLiteral("%1 of %2 rows current").arg(current).arg(values.rowCount())));
    readAll(values);
    readAll(alarms);

    // A bit set on the device is shown on (and counted, when it is an alarm). The dTRON
    // has no alarm bits, only status bits (binary outputs, limit comparators).
    int bitRow = -1;
    for (const BitKind kind : {BitKind::Alarm, BitKind::Warning, BitKind::Status}) {
        for (int row = 0; row < alarms.rowCount() && bitRow < 0; ++row) {
            const QModelIndex index = alarms.index(row);
            if (alarms.data(index, AlarmBitsModel::KindRole).toInt() == int(kind)
                && alarms.data(index, AlarmBitsModel::BitStateRole).toInt() == int(AlarmBitsModel::BitState::Off)
                && line.sim(7)->setFlag(alarms.data(index, AlarmBitsModel::ReferenceRole).toString(), true))
                bitRow = row;
        }
    }
    QVERIFY(bitRow >= 0);
    const bool isAlarm = alarms.data(alarms.index(bitRow), AlarmBitsModel::KindRole).toInt() == int(BitKind::Alarm);
    const int before = alarms.activeAlarms();
    QVERIFY(line.runUntil([&] {
        return alarms.data(alarms.index(bitRow), AlarmBitsModel::BitStateRole).toInt() == int(AlarmBitsModel::BitState::On);
    }, 20000));
    QCOMPARE(alarms.activeAlarms(), before + (isAlarm ? 1 : 0));

    // Every reply lost: the values turn stale, then unknown once the device is offline.
    line.transport->drop = [](const ModbusRequest &) { return true; };
    QVERIFY(line.runUntil([&] { return rowsWithValidity(values, LiveValuesModel::ValidityRole, Validity::Current) == 0; },
                          120000));
    readAll(values);
    readAll(alarms);
    line.transport->drop = {};
    QVERIFY(line.runUntil([&] { return rowsWithValidity(values, LiveValuesModel::ValidityRole, Validity::Current) > 0; },
                          120000));

    // The adapter is pulled: nothing stays current, and the alarm count is not a live one.
    line.transport->pull();
    QVERIFY(line.runUntil([&] { return rowsWithValidity(values, LiveValuesModel::ValidityRole, Validity::Current) == 0; },
                          60000));
    QVERIFY(!alarms.alarmsKnown() || alarms.alarmsStale());
    readAll(values);
    readAll(alarms);

    // The device leaves the bus while its models are still shown.
    line.bus->removeDevice(device);
    line.run(2000);
    readAll(values);
    readAll(alarms);
    QCOMPARE(rowsWithValidity(values, LiveValuesModel::ValidityRole, Validity::Current), 0);
}

void tst_Models::registerMapModelOfEveryFamily()
{
    RegisterMapModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(model.rowCount(), 0);
    for (const auto &map : families().families()) {
        model.setMap(map);
        QCOMPARE(model.map(), map);
        QVERIFY(model.rowCount() > 10);
        readAll(model);
    }
    model.setMap(nullptr);
    QCOMPARE(model.rowCount(), 0);
}

QTEST_GUILESS_MAIN(tst_Models)
// A remote viewer's line: the same models over values handed in as a station published
// them, with their validity as published, and no Bus anywhere.
void tst_Models::modelsOverAMirroredLine()
{
    const auto map = FamilyRegistry::load({}, true).family(QStringLiteral("tya200"));
    QVERIFY(map);
    MirroredLine line(QStringLiteral("cabinet-a"));
    const DeviceId id = line.addDevice(map, 3);
    QCOMPARE(line.addDevice(map, 3), id);   // reported again: the same device
    Bus bus;
    const DeviceId polled = bus.addDevice(map, 3);
    QVERIFY(polled != id);                  // ids stay unique next to a Bus's
    QCOMPARE(line.deviceName(id), QStringLiteral("tya200@3"));

    LiveValuesModel values(&line, id);
    AlarmBitsModel alarms(&line, id);
    QAbstractItemModelTester valuesTester(&values, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester alarmsTester(&alarms, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(values.rowCount() > 0);
    QCOMPARE(rowsWithValidity(values, LiveValuesModel::ValidityRole, Validity::Current), 0);
    QVERIFY(!alarms.alarmsKnown());

    auto published = [&](const QString &entryId, const QList<quint16> &words, Validity validity) {
        const RegisterEntry *entry = map->entry(entryId);
        EntryState s;
        s.words = words;
        s.value = ValueCodec::decode(*entry, *map, words);
        s.validity = validity;
        s.error = validity == Validity::Unknown ? ReadError::LineLost : ReadError::None;
        s.goodMs = s.updatedMs = line.clockMs();
        return s;
    };
    QSignalSpy updated(&line, &DeviceSource::entriesUpdated);
    line.setEntries(id, {{QStringLiteral("voltage_input"), published(QStringLiteral("voltage_input"),
                                                                      ValueCodec::encodeFloat(7.5f, map->protocol.floatWordOrder),
                                                                      Validity::Current)},
                         {QStringLiteral("malfunction_signals_1"),
                          published(QStringLiteral("malfunction_signals_1"), {0x0002}, Validity::Current)},
                         {QStringLiteral("no_such_entry"), EntryState{}}});
    QCOMPARE(updated.count(), 1);   // one signal for the set, unknown ids left out
    QCOMPARE(updated.first().at(1).toStringList().size(), 2);
    const int row = values.rowOf(QStringLiteral("voltage_input"));
    QVERIFY(row >= 0);
    QCOMPARE(values.data(values.index(row, 0), LiveValuesModel::ValidityRole).toInt(), int(Validity::Current));
    QCOMPARE(values.data(values.index(row, 0), LiveValuesModel::NumericRole).toDouble(), 7.5);
    QCOMPARE(alarms.data(alarms.index(alarms.rowOf(QStringLiteral("malfunction_signals_1.max_alarm")), 0),
                         AlarmBitsModel::BitStateRole)
                     .toInt(),
             int(AlarmBitsModel::BitState::On));

    // The station falls silent: the same values, now stale; a number is no longer current.
    line.setEntries(id, {{QStringLiteral("voltage_input"), published(QStringLiteral("voltage_input"),
                                                                      ValueCodec::encodeFloat(7.5f, map->protocol.floatWordOrder),
                                                                      Validity::Stale)}});
    QCOMPARE(values.data(values.index(row, 0), LiveValuesModel::ValidityRole).toInt(), int(Validity::Stale));
    QVERIFY(!values.data(values.index(row, 0), LiveValuesModel::NumericRole).isValid());

    QSignalSpy conditions(&line, &DeviceSource::conditionChanged);
    QSignalSpy states(&line, &DeviceSource::stateChanged);
    DeviceCondition online;
    online.state = DeviceCondition::State::Online;
    line.setCondition(id, online);
    line.setCondition(id, online);   // the same again: no signal
    QCOMPARE(conditions.count(), 1);
    QVERIFY(line.condition(id).isOnline());
    line.setState(LineState::Lost, QStringLiteral("the station stopped publishing"));
    QCOMPARE(states.count(), 1);
    QCOMPARE(line.stateReason(), QStringLiteral("the station stopped publishing"));

    line.removeDevice(id);
    QVERIFY(!line.entryState(id, QStringLiteral("voltage_input")));
    QVERIFY(line.devices().isEmpty());
}

void tst_Models::measuredValuesFirstInTheManualsOrder_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QString>("first");        // the section of the first row
    QTest::addColumn<QString>("before");       // a section that comes before...
    QTest::addColumn<QString>("after");        // ...this one
    QTest::newRow("ipc300") << "ipc300" << "5.2.1" << "5.2.7" << "5.1.1";
    QTest::newRow("tya200: 5.3 before 5.8") << "tya200" << "5.3" << "5.3" << "5.8";
    QTest::newRow("tya200: the faults before the device data") << "tya200" << "5.3" << "5.7" << "5.1";
    QTest::newRow("quantrol") << "quantrol" << "4.2" << "4.3" << "4.4";
    QTest::newRow("dtron300") << "dtron300" << "5.1" << "5.2" << "5.4";
}

// 26.13: the live values tab opens on the measured values, not on identity and settings
// (the TYA's began at row 26); the sections in the manual's order, measured ones first.
void tst_Models::measuredValuesFirstInTheManualsOrder()
{
    QFETCH(QString, family);
    QFETCH(QString, first);
    QFETCH(QString, before);
    QFETCH(QString, after);
    Line line({{family, 7}});
    const auto map = families().family(family);
    const DeviceId device = line.bus->addDevice(map, 7);
    LiveValuesModel values(line.bus.get(), device);
    QAbstractItemModelTester tester(&values, QAbstractItemModelTester::FailureReportingMode::QtTest);
    auto sectionOf = [&](int row) { return map->entry(values.entryId(row))->group.section(QLatin1Char(' '), 0, 0); };
    QCOMPARE(sectionOf(0), first);
    const RegisterEntry *top = map->entry(values.entryId(0));
    QVERIFY2(!top->isWritable(), qPrintable(top->id));
    int lastBefore = -1;
    int firstAfter = values.rowCount();
    for (int row = 0; row < values.rowCount(); ++row) {
        if (sectionOf(row) == before)
            lastBefore = row;
        if (sectionOf(row) == after)
            firstAfter = std::min(firstAfter, row);
        QCOMPARE(values.rowOf(values.entryId(row)), row);
    }
    QVERIFY(lastBefore >= 0 && firstAfter < values.rowCount());
    QVERIFY2(lastBefore < firstAfter, qPrintable(QStringLiteral("%1 ends at row %2, %3 starts at %4")
                                                         .arg(before).arg(lastBefore).arg(after).arg(firstAfter)));
    // A section is one block of rows, however its addresses are spread (the dTRON's 5.4).
    QStringList seen;
    for (int row = 0; row < values.rowCount(); ++row) {
        const QString group = map->entry(values.entryId(row))->group;
        if (seen.isEmpty() || seen.last() != group) {
            QVERIFY2(!seen.contains(group), qPrintable(group));
            seen << group;
        }
    }
}

void tst_Models::noLabelTwiceInOneView_data()
{
    QTest::addColumn<QString>("family");
    for (const char *family : {"ipc300", "tya200", "quantrol", "dtron300"})
        QTest::newRow(family) << QString::fromLatin1(family);
}

// 26.13: within what one tab shows, no two entries read alike ("Device temperature"
// twice on the IPC 300, in °C and in °F; "Analog input 1" twice on the dTRON).
void tst_Models::noLabelTwiceInOneView()
{
    QFETCH(QString, family);
    Line line({{family, 7}});
    const auto map = families().family(family);
    const DeviceId device = line.bus->addDevice(map, 7);
    auto twice = [](const QStringList &labels) {
        QStringList doubled;
        for (const QString &label : labels) {
            if (labels.count(label) > 1 && !doubled.contains(label))
                doubled << label;
        }
        return doubled.join(QStringLiteral(", "));
    };
    LiveValuesModel values(line.bus.get(), device);
    QStringList live;
    for (int row = 0; row < values.rowCount(); ++row)
        live << values.index(row, LiveValuesModel::LabelColumn).data().toString();
    QVERIFY2(twice(live).isEmpty(), qPrintable("live values: " + twice(live)));
    // The Controls tab: every writable entry with a control but the parameter editor's
    // and the program's.
    QStringList controls;
    for (const RegisterEntry &e : map->entries()) {
        if (e.isWritable() && !e.reserved && !e.control.isEmpty() && e.control != QLatin1String("parameter")
            && e.control != QLatin1String("program"))
            controls << e.label;
    }
    QVERIFY2(twice(controls).isEmpty(), qPrintable("controls: " + twice(controls)));
    ParameterEditModel parameters(line.bus.get(), device);
    QStringList editable;
    for (const QString &id : parameters.entryIds())
        editable << map->entry(id)->label;
    QVERIFY2(twice(editable).isEmpty(), qPrintable("parameters: " + twice(editable)));
}

// 26.15: "0,4 s" in German, as every other number.
void tst_Models::agesInTheLanguagesWay()
{
    Line line({{"ipc300", 7}});
    QVERIFY(line.bus->open());
    const DeviceId device = line.bus->addDevice(families().family("ipc300"), 7);
    LiveValuesModel values(line.bus.get(), device);
    const QModelIndex age = values.index(values.rowOf("load_voltage"), LiveValuesModel::AgeColumn);
    QVERIFY(line.runUntil([&] { return !age.data().toString().isEmpty(); }, 20000));
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    const auto restore = qScopeGuard([before] { QLocale::setDefault(before); });
    QVERIFY2(QRegularExpression("^\\d+,\\d s$").match(age.data().toString()).hasMatch(), qPrintable(age.data().toString()));
    QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    QVERIFY2(QRegularExpression("^\\d+\\.\\d s$").match(age.data().toString()).hasMatch(), qPrintable(age.data().toString()));
}

#include "tst_models.moc"
