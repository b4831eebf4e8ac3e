// What a faceplate shows of values that are not current, against the simulator over a
// pty line: no bar is filled for a stale, unknown or error value, alarm names read from
// aged words say so, a scale that is zero, negative or without a number says why there
// is no bar. And the overview's columns and density settle at every window size, for
// 1 to 62 devices, without a faceplate cut off.
#include "connectionbar.h"
#include "devicepage.h"
#include "devicetile.h"
#include "mainwindow.h"
#include "overviewpage.h"
#include "bus/mirroredline.h"
#include "models/alarmbitsmodel.h"
#include "models/livevaluesmodel.h"
#include "sim/simulateddevice.h"
#include "testpeers.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QScopeGuard>
#include <QScrollArea>
#include <QScrollBar>
#include <QTest>

#include <limits>

using namespace jumo;
using namespace jumo::test;

class tst_Faceplate : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void staleAlarmNamesSaySo();
    void noBarForAValueThatIsNotCurrent();
    void scaleThatGivesNoBarSaysWhy();
    void scaleOfTwoNegativePartsGivesNoBar();
    void tabReachesEveryFaceplateInView();
    void columnsAndDensitySettle_data();
    void columnsAndDensitySettle();
    void noiseAroundZeroIsZero();
    void errorValueRaisesTheState();
    void noEmptyBarsWhileNotHeard();

private:
    // A window on the line with the IPC 300 at address 1 and the dTRON 300 at 4, on the overview.
    std::unique_ptr<MainWindow> connectedWindow(const QString &name);

    QTemporaryDir m_dir;
    TestLine m_line;
    SimulatorPeer m_sim;
};

void tst_Faceplate::initTestCase()
{
    QVERIFY(m_line.start());
    QVERIFY(m_sim.startOneOfEachFamily(m_line.deviceEnd()));
}

std::unique_ptr<MainWindow> tst_Faceplate::connectedWindow(const QString &name)
{
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(name + QStringLiteral(".ini"));
    options.logFolder = m_dir.filePath(name + QStringLiteral("-logs"));
    auto window = std::make_unique<MainWindow>(families(), options);
    window->connectionBar()->setSettings(m_line.masterEnd(), 19200, "8N1");
    if (!window->connectLine() || !window->addDevice(families().family("ipc300"), 1)
        || !window->addDevice(families().family("dtron300"), 4))
        return nullptr;
    window->show();
    window->showOverview();
    return window;
}

void tst_Faceplate::staleAlarmNamesSaySo()
{
    // Polling stops while an alarm is on: the alarm is the last one known, not a live one.
    auto window = connectedWindow("stale");
    QVERIFY(window);
    DeviceTile *tile = window->deviceTile("ipc300", 1);
    SimulatedDevice *sim = m_sim.line().device(1);
    QVERIFY(sim->setFlag("malfunction_signal_1.fuse_failure", true));
    auto off = qScopeGuard([sim] { sim->setFlag("malfunction_signal_1.fuse_failure", false); });
    QTRY_COMPARE_WITH_TIMEOUT(tile->alarmNames(), QString("Fuse failure"), 20000);
    QTRY_COMPARE_WITH_TIMEOUT(tile->barsFilled(), 4, 20000);
    window->bus()->setPolling(false);
    QTRY_COMPARE_WITH_TIMEOUT(tile->alarmNames(), QString("Fuse failure (stale)"), 30000);
    QVERIFY(tile->toolTip().contains("Fuse failure (stale)"));
    // Still the worst known (an alarm), but nothing else reads as live: no bar, no mode.
    QCOMPARE(tile->summary(), DeviceTile::Summary::Alarm);
    QTRY_COMPARE_WITH_TIMEOUT(tile->barsFilled(), 0, 30000);
    QCOMPARE(tile->modeText(), QString("unknown"));
    window->bus()->setPolling(true);
    QTRY_COMPARE_WITH_TIMEOUT(tile->alarmNames(), QString("Fuse failure"), 20000);
}

void tst_Faceplate::noBarForAValueThatIsNotCurrent()
{
    auto window = connectedWindow("error");
    QVERIFY(window);
    DeviceTile *tile = window->deviceTile("ipc300", 1);
    QTRY_COMPARE_WITH_TIMEOUT(tile->barsFilled(), 4, 20000);
    // An error value is read and current, but it is no number: its track stays empty.
    SimulatedDevice *sim = m_sim.line().device(1);
    QVERIFY(sim->forceStatus("load_current", ValueStatus::Overrange));
    auto ok = qScopeGuard([sim] { sim->forceStatus("load_current", ValueStatus::Ok); });
    QTRY_VERIFY_WITH_TIMEOUT(tile->valuesText().contains("Current: Overrange"), 20000);
    QCOMPARE(tile->barsDrawn(), 4);
    QCOMPARE(tile->barsFilled(), 3);
    QVERIFY(sim->forceStatus("load_current", ValueStatus::Ok));
    QTRY_COMPARE_WITH_TIMEOUT(tile->barsFilled(), 4, 20000);
    // A device that stops answering: no bar, no mode, no program.
    DeviceTile *dtron = window->deviceTile("dtron300", 4);
    QTRY_COMPARE_WITH_TIMEOUT(dtron->barsFilled(), 1, 20000);
    QVERIFY(m_sim.setFault(4, "dead", -1, 0));
    auto alive = qScopeGuard([this] { m_sim.setFault(4, "none", -1, 0); });
    QTRY_COMPARE_WITH_TIMEOUT(dtron->summary(), DeviceTile::Summary::NotAnswering, 30000);
    QCOMPARE(dtron->barsFilled(), 0);
    QCOMPARE(dtron->modeText(), QString("unknown"));
    QCOMPARE(dtron->programText(), QString("unknown"));
    QVERIFY(m_sim.setFault(4, "none", -1, 0));
    QTRY_COMPARE_WITH_TIMEOUT(dtron->barsFilled(), 1, 30000);
}

void tst_Faceplate::scaleThatGivesNoBarSaysWhy()
{
    auto window = connectedWindow("scales");
    QVERIFY(window);
    DeviceTile *tile = window->deviceTile("ipc300", 1);
    QTRY_COMPARE_WITH_TIMEOUT(tile->barsDrawn(), 4, 20000);
    SimulatedDevice *sim = m_sim.line().device(1);
    const double powerLimit = sim->number("power_limit");
    const double voltageLimit = sim->number("load_voltage_limit");
    const quint16 nominalAddress = sim->map().entry("nominal_current")->address;
    const quint16 nominal = sim->word(nominalAddress);
    auto restore = qScopeGuard([=] {
        sim->setNumber("power_limit", powerLimit);
        sim->setNumber("load_voltage_limit", voltageLimit);
        sim->setWords(nominalAddress, {nominal});
    });
    QVERIFY(sim->setNumber("power_limit", 0));
    QVERIFY(sim->setNumber("load_voltage_limit", -5));
    QVERIFY(sim->setWords(nominalAddress, {7}));   // the map knows 0, 1 and 2
    // Scales are settings, read within the minute: one cycle now instead of waiting.
    window->bus()->requestCycle(tile->device());
    QTRY_COMPARE_WITH_TIMEOUT(tile->barsDrawn(), 1, 20000);
    const QString tip = tile->toolTip();
    QVERIFY2(tip.contains("Power – No bar: its scale, 0 W, is not above zero."), qPrintable(tip));
    QVERIFY2(tip.contains("Voltage – No bar: its scale, -5 V, is not above zero."), qPrintable(tip));
    QVERIFY2(tip.contains("Current – No bar: the device reports Nominal current = 7, which the map gives no number."),
             qPrintable(tip));
    restore.dismiss();
    QVERIFY(sim->setNumber("power_limit", powerLimit));
    QVERIFY(sim->setNumber("load_voltage_limit", voltageLimit));
    QVERIFY(sim->setWords(nominalAddress, {nominal}));
    window->bus()->requestCycle(tile->device());
    QTRY_COMPARE_WITH_TIMEOUT(tile->barsDrawn(), 4, 20000);
}

void tst_Faceplate::tabReachesEveryFaceplateInView()
{
    // 31 faceplates in a window too small for them: Tab goes from one to the next in
    // their order, the overview scrolls each into view, Space opens the device.
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(QStringLiteral("tab.ini"));
    options.logFolder = m_dir.filePath(QStringLiteral("tab-logs"));
    MainWindow window(families(), options);
    const QStringList order{"ipc300", "tya200", "quantrol", "dtron300"};
    for (int address = 1; address <= 31; ++address)
        QVERIFY(window.addDevice(families().family(order.at(address % 4)), quint8(address)));
    window.resize(1000, 600);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.showOverview();
    QApplication::setActiveWindow(&window);
    auto *overview = window.findChild<OverviewPage *>(QStringLiteral("overview"));
    QVERIFY(overview->scrollArea()->verticalScrollBar()->isVisible());
    QWidget *viewport = overview->scrollArea()->viewport();
    DeviceTile *first = window.deviceTile(order.at(1), 1);
    first->setFocus(Qt::TabFocusReason);
    QTRY_VERIFY(first->hasFocus());
    for (int address = 2; address <= 31; ++address) {
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
        DeviceTile *tile = window.deviceTile(order.at(address % 4), quint8(address));
        QVERIFY2(tile->hasFocus(), qPrintable(QApplication::focusWidget()->objectName()));
        const QRect onScreen(tile->mapTo(viewport, QPoint(0, 0)), tile->size());
        QVERIFY2(viewport->rect().contains(onScreen), qPrintable(tile->objectName()));
    }
    DeviceTile *last = window.deviceTile(order.at(31 % 4), 31);
    QTest::keyClick(last, Qt::Key_Space);
    QTRY_VERIFY(window.devicePage(order.at(31 % 4), 31) && window.devicePage(order.at(31 % 4), 31)->isVisible());
}

void tst_Faceplate::scaleOfTwoNegativePartsGivesNoBar()
{
    // A user's map scales the power by the product of two limits: two negative limits
    // make a positive product, and still no scale.
    QFile builtin(QStringLiteral(":/maps/ipc300.json"));
    QVERIFY(builtin.open(QIODevice::ReadOnly));
    QJsonObject map = QJsonDocument::fromJson(builtin.readAll()).object();
    QJsonObject face = map.value("faceplate").toObject();
    QJsonArray values = face.value("values").toArray();
    QJsonObject power = values.at(3).toObject();
    QCOMPARE(power.value("entry").toString(), QString("power"));
    power["from"] = QJsonArray{"power_limit", "load_voltage_limit"};
    values.replace(3, power);
    face["values"] = values;
    map["faceplate"] = face;
    QTemporaryDir folder;
    QFile file(folder.filePath("ipc300.json"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QJsonDocument(map).toJson());
    file.close();
    const FamilyRegistry registry = FamilyRegistry::load({folder.path()}, true);
    QVERIFY2(registry.errors().isEmpty(), qPrintable(registry.errors().join('\n')));

    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(QStringLiteral("product.ini"));
    options.logFolder = m_dir.filePath(QStringLiteral("product-logs"));
    MainWindow window(registry, options);
    window.connectionBar()->setSettings(m_line.masterEnd(), 19200, "8N1");
    QVERIFY(window.connectLine());
    QVERIFY(window.addDevice(registry.family("ipc300"), 1));
    window.show();
    window.showOverview();
    DeviceTile *tile = window.deviceTile("ipc300", 1);
    QTRY_COMPARE_WITH_TIMEOUT(tile->barsDrawn(), 4, 20000);
    SimulatedDevice *sim = m_sim.line().device(1);
    const double powerLimit = sim->number("power_limit");
    const double voltageLimit = sim->number("load_voltage_limit");
    auto restore = qScopeGuard([=] {
        sim->setNumber("power_limit", powerLimit);
        sim->setNumber("load_voltage_limit", voltageLimit);
    });
    QVERIFY(sim->setNumber("power_limit", -20));
    QVERIFY(sim->setNumber("load_voltage_limit", -10));
    window.bus()->requestCycle(tile->device());   // (scales are settings, read within the minute)
    QTRY_COMPARE_WITH_TIMEOUT(tile->barsDrawn(), 2, 20000);
    QVERIFY2(tile->toolTip().contains("Power – No bar: Power limit value = -20, a part of its scale, is not above zero."),
             qPrintable(tile->toolTip()));
}

void tst_Faceplate::columnsAndDensitySettle_data()
{
    QTest::addColumn<int>("devices");
    QTest::addColumn<bool>("compact");
    QTest::newRow("one") << 1 << false;
    QTest::newRow("four") << 4 << false;
    QTest::newRow("a full line") << 31 << false;
    QTest::newRow("two lines") << 62 << false;
    QTest::newRow("two lines, compact chosen") << 62 << true;
}

void tst_Faceplate::columnsAndDensitySettle()
{
    // Widths up and down, at heights around where the comfortable faceplates stop fitting:
    // the layout must come to rest after each (no switching between the densities as the
    // scroll bar comes and goes), never cut a faceplate, never scroll a comfortable one.
    QFETCH(int, devices);
    QFETCH(bool, compact);
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(QStringLiteral("settle-%1-%2.ini").arg(devices).arg(compact));
    options.logFolder = m_dir.filePath(QStringLiteral("settle-logs"));
    MainWindow window(families(), options);
    const QStringList order{"ipc300", "tya200", "quantrol", "dtron300"};
    for (int address = 1; address <= devices; ++address)
        QVERIFY(window.addDevice(families().family(order.at(address % 4)), quint8(address)));
    window.findChild<QAction *>("compactOverview")->setChecked(compact);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.showOverview();
    auto *overview = window.findChild<OverviewPage *>(QStringLiteral("overview"));
    QVERIFY(overview);
    QWidget *viewport = overview->scrollArea()->viewport();
    QList<int> widths;
    for (int width = 800; width <= 3840; width += 23)
        widths << width;
    for (int width = 3840; width >= 800; width -= 29)
        widths << width;
    for (int height : {500, 1040}) {
        for (int width : widths) {
            window.resize(width, height);
            QCoreApplication::processEvents();
            const auto density = overview->density();
            const int columns = overview->columns();
            const int viewportWidth = viewport->width();
            for (int i = 0; i < 4; ++i)
                QCoreApplication::processEvents();
            const QString at = QStringLiteral("%1x%2").arg(window.width()).arg(window.height());
            QVERIFY2(overview->density() == density && overview->columns() == columns && viewport->width() == viewportWidth,
                     qPrintable(at));
            if (compact)
                QCOMPARE(overview->density(), DeviceTile::Density::Compact);
            if (overview->density() == DeviceTile::Density::Comfortable)
                QVERIFY2(!overview->scrollArea()->verticalScrollBar()->isVisible(), qPrintable(at));
            for (DeviceTile *tile : overview->findChildren<DeviceTile *>()) {
                const QRect r(tile->mapTo(viewport, QPoint(0, 0)), tile->size());
                QVERIFY2(r.left() >= 0 && r.right() < viewport->width() && tile->width() >= tile->minimumSizeHint().width(),
                         qPrintable(at + QLatin1Char(' ') + tile->objectName()));
            }
        }
    }
}

namespace {

// One IPC 300 faceplate over a mirrored line whose values the test sets: what a faceplate
// makes of exactly these values, with no poll in between.
struct MirroredFaceplate
{
    MirroredFaceplate()
        : map(families().family("ipc300")), line(QStringLiteral("cabinet-a")), id(line.addDevice(map, 1)),
          values(&line, id), alarms(&line, id), tile(id, *map, 1, &values, &alarms)
    {
        DeviceCondition online;
        online.state = DeviceCondition::State::Online;
        line.setCondition(id, online);
        tile.setCondition(online);
        tile.show();
    }
    EntryState state(const QString &entryId, const QList<quint16> &words) const
    {
        EntryState s;
        s.words = words;
        s.value = ValueCodec::decode(*map->entry(entryId), *map, words);
        s.validity = Validity::Current;
        s.goodMs = s.updatedMs = line.clockMs();
        return s;
    }
    EntryState number(const QString &entryId, float value) const
    {
        return state(entryId, ValueCodec::encodeFloat(value, map->protocol.floatWordOrder));
    }
    // The scales of every bar, the values, and every alarm word clear.
    void setAll(QHash<QString, EntryState> states)
    {
        for (const RegisterEntry &e : map->entries()) {
            if (e.type == ValueType::Bitfield && e.isReadable() && !states.contains(e.id))
                states.insert(e.id, state(e.id, {0}));
        }
        const QHash<QString, EntryState> defaults{{"input_setpoint", number("input_setpoint", 0)},
                                                  {"load_voltage", number("load_voltage", 0.02f)},
                                                  {"load_current", number("load_current", 0.001f)},
                                                  {"power", number("power", 0)},
                                                  {"load_voltage_limit", number("load_voltage_limit", 230)},
                                                  {"power_limit", number("power_limit", 6000)},
                                                  {"nominal_current", state("nominal_current", {1})}};
        for (auto it = defaults.cbegin(); it != defaults.cend(); ++it) {
            if (!states.contains(it.key()))
                states.insert(it.key(), it.value());
        }
        line.setEntries(id, states);
    }

    std::shared_ptr<const RegisterMap> map;
    MirroredLine line;
    DeviceId id;
    LiveValuesModel values;
    AlarmBitsModel alarms;
    DeviceTile tile;
};

} // namespace

// 26.8: the precision first, then the sign: noise around zero reads 0.000 W and draws no
// arrow below the scale, as the text beside the bar says.
void tst_Faceplate::noiseAroundZeroIsZero()
{
    MirroredFaceplate face;
    face.setAll({{"power", face.number("power", -0.00007528f)}});
    QTRY_VERIFY_WITH_TIMEOUT(face.tile.valuesText().contains("Power: 0.000 W"), 5000);
    QTRY_COMPARE(face.tile.barsFilled(), 4);
    QVERIFY2(!face.tile.toolTip().contains("beyond the scale"), qPrintable(face.tile.toolTip()));
    // A value that is below its scale at the precision shown still says so.
    face.setAll({{"power", face.number("power", -2.5f)}});
    QTRY_VERIFY_WITH_TIMEOUT(face.tile.valuesText().contains("Power: -2.500 W"), 5000);
    QVERIFY2(face.tile.toolTip().contains("beyond the scale"), qPrintable(face.tile.toolTip()));
}

// 26.17: an error value (the devices' +Inf: overrange) is no reading: the faceplate's state
// rises above Normal and names it.
void tst_Faceplate::errorValueRaisesTheState()
{
    MirroredFaceplate face;
    face.setAll({});
    QTRY_COMPARE_WITH_TIMEOUT(face.tile.summary(), DeviceTile::Summary::Normal, 5000);
    face.setAll({{"load_current", face.state("load_current", ValueCodec::encodeFloat(std::numeric_limits<float>::infinity(),
                                                                                     face.map->protocol.floatWordOrder))}});
    QTRY_COMPARE_WITH_TIMEOUT(face.tile.summary(), DeviceTile::Summary::Warning, 5000);
    QVERIFY2(face.tile.alarmNames().contains("Current: "), qPrintable(face.tile.alarmNames()));
    QCOMPARE(face.tile.stateRole(), Theme::Role::TileWarning);
    face.setAll({});
    QTRY_COMPARE_WITH_TIMEOUT(face.tile.summary(), DeviceTile::Summary::Normal, 5000);
    QVERIFY(face.tile.alarmNames().isEmpty());
}

// 26.16: a faceplate of a device that is not heard (line lost, not answering) has no bar
// tracks at all, not even the fixed 0..100 % one of the setpoint.
void tst_Faceplate::noEmptyBarsWhileNotHeard()
{
    MirroredFaceplate face;
    face.setAll({});
    QTRY_COMPARE_WITH_TIMEOUT(face.tile.barsDrawn(), 4, 5000);
    for (const auto state : {DeviceCondition::State::LineLost, DeviceCondition::State::Offline}) {
        DeviceCondition condition;
        condition.state = state;
        condition.since = QDateTime::currentDateTime();
        face.tile.setCondition(condition);
        QCOMPARE(face.tile.barsDrawn(), 0);
    }
    DeviceCondition online;
    online.state = DeviceCondition::State::Online;
    face.tile.setCondition(online);
    QCOMPARE(face.tile.barsDrawn(), 4);
}

QTEST_MAIN(tst_Faceplate)
#include "tst_faceplate.moc"
