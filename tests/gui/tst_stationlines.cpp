// Several lines in one HMI window, with real parts: two simulators on two socat pty pairs.
// Both lines' faceplates show live values, grouped under a header per line with its state
// in words; the list groups the devices under their line; the status bar counts the
// lines. A line whose socat dies says "Line lost" on its header and faceplates while the
// other line stays live. The lines and their devices survive a restart (and the settings
// of a one-line version become "line1"); removing a line asks, names how many devices go,
// and takes them along. The journal names a device with its line while there are several.
#include "devicetile.h"
#include "elidedlabel.h"
#include "lineheader.h"
#include "logs/eventlog.h"
#include "logrecords.h"
#include "mainwindow.h"
#include "navigationlist.h"
#include "overviewpage.h"
#include "stationline.h"
#include "sim/simulatorserver.h"
#include "testpeers.h"

#include <QAction>
#include <QApplication>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTest>

#include <csignal>

using namespace jumo;
using namespace jumo::test;

namespace {

BusSettings lineSettings(const QString &port)
{
    BusSettings s;
    s.portName = port;
    s.format = testFormat();
    return s;
}

// Answers the next message box with Yes and returns its text.
QString answerYes(const std::function<void()> &action)
{
    QString text;
    QTimer answer;
    QObject::connect(&answer, &QTimer::timeout, [&text] {
        for (QWidget *w : QApplication::topLevelWidgets()) {
            auto *box = qobject_cast<QMessageBox *>(w);
            if (box && box->isVisible() && text.isEmpty()) {
                text = box->text();
                box->button(QMessageBox::Yes)->click();
            }
        }
    });
    answer.start(20);
    action();
    answer.stop();
    return text;
}

} // namespace

class tst_StationLines : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void bothLinesLiveGroupedUnderTheirHeaders();
    void aLostLineShowsOnItsHeaderOnly();
    void settingsRestoreBothLines();
    void oneLineSettingsBecomeLine1();
    void removingALineAsksAndTakesItsDevices();
    void serialTcpAndRtuOverTcpLinesAtOnce();

private:
    // A window with line1 (IPC 300 @ 1, Quantrol @ 3) and cabinet-b (TYA 200 @ 2, IPC 300 @ 1),
    // both connected.
    std::unique_ptr<MainWindow> twoLineWindow(const QString &settingsName);

    QTemporaryDir m_dir;
    TestLine m_lineA;
    TestLine m_lineB;
    SimulatorPeer m_simA;
    SimulatorPeer m_simB;
};

void tst_StationLines::initTestCase()
{
    QVERIFY(m_lineA.start());
    QVERIFY(m_lineB.start());
    QVERIFY(m_simA.startOneOfEachFamily(m_lineA.deviceEnd()));
    QVERIFY(m_simB.startOneOfEachFamily(m_lineB.deviceEnd()));
}

std::unique_ptr<MainWindow> tst_StationLines::twoLineWindow(const QString &settingsName)
{
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(settingsName + QStringLiteral(".ini"));
    options.logFolder = m_dir.filePath(settingsName + QStringLiteral("-logs"));
    auto window = std::make_unique<MainWindow>(families(), options);
    window->resize(1280, 800);
    window->show();
    StationLine *first = window->lines().value(0);
    if (!first || first->name() != QLatin1String("line1"))
        return nullptr;
    StationLine *second = window->addLine(QStringLiteral("cabinet-b"), lineSettings(m_lineB.masterEnd()));
    if (!second)
        return nullptr;
    window->setCurrentLine(first);
    first->setSettings(lineSettings(m_lineA.masterEnd()));
    if (!window->connectLine(first) || !window->connectLine(second))
        return nullptr;
    window->addDevice(first, families().family("ipc300"), 1);
    window->addDevice(first, families().family("quantrol"), 3);
    window->addDevice(second, families().family("tya200"), 2);
    window->addDevice(second, families().family("ipc300"), 1);
    return window;
}

void tst_StationLines::bothLinesLiveGroupedUnderTheirHeaders()
{
    auto window = twoLineWindow(QStringLiteral("live"));
    QVERIFY(window);
    window->showOverview();
    // Every faceplate on both lines comes online and shows values; the IPC 300 at address 1
    // is on both lines, each one its own.
    const QList<std::tuple<QString, QString, int>> devices{
            {"line1", "ipc300", 1}, {"line1", "quantrol", 3}, {"cabinet-b", "tya200", 2}, {"cabinet-b", "ipc300", 1}};
    for (const auto &[line, family, address] : devices) {
        DeviceTile *tile = window->deviceTile(line, family, quint8(address));
        QVERIFY2(tile, qPrintable(line + "/" + family));
        QTRY_VERIFY_WITH_TIMEOUT(tile->stateText() == "Online", 20000);
        QTRY_VERIFY_WITH_TIMEOUT(!tile->valuesText().contains(QStringLiteral("\u2014")), 20000);
    }
    QVERIFY(window->deviceTile("line1", "ipc300", 1) != window->deviceTile("cabinet-b", "ipc300", 1));
    // Values move on both lines: a setpoint changed in each simulator reaches its own line's faceplate.
    m_simA.line().device(3)->setNumber("controller_setpoint", 111);
    m_simB.line().device(2)->setNumber("setpoint", 42);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("line1", "quantrol", 3)->valuesText().contains("Setpoint: 111"), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-b", "tya200", 2)->valuesText().contains("Setpoint: 42"), 20000);

    // Grouped: each line's header, then its faceplates, the second line below the first's.
    auto *overview = window->findChild<OverviewPage *>(QStringLiteral("overview"));
    QVERIFY(overview->headersShown());
    LineHeader *headerA = window->lineHeader("line1");
    LineHeader *headerB = window->lineHeader("cabinet-b");
    QVERIFY(headerA && headerB);
    QVERIFY(headerA->isVisible() && headerB->isVisible());
    QCOMPARE(headerA->stateText(), QString("\u25CF Connected"));
    QCOMPARE(headerB->stateText(), QString("\u25CF Connected"));
    QVERIFY(headerA->toolTip().contains(m_lineA.masterEnd()));
    QVERIFY(headerB->toolTip().contains(m_lineB.masterEnd()));
    const auto y = [](QWidget *w) { return w->mapTo(w->window(), QPoint(0, 0)).y(); };
    QVERIFY(y(headerA) < y(window->deviceTile("line1", "ipc300", 1)));
    QVERIFY(y(window->deviceTile("line1", "quantrol", 3)) < y(headerB));
    QVERIFY(y(headerB) < y(window->deviceTile("cabinet-b", "tya200", 2)));

    // The list: a row per line with its state, its devices under it.
    auto *list = window->findChild<NavigationList *>(QStringLiteral("navigation"));
    QStringList rows;
    for (int row = list->pageCount(); row < list->count(); ++row)
        rows << list->item(row)->text().trimmed();
    QCOMPARE(rows, QStringList({"line1 (connected)", "IPC 300 @ 1", "Quantrol @ 3", "cabinet-b (connected)",
                                "TYA 200 @ 2", "IPC 300 @ 1"}));
    // A device's page makes its line the one the connection bar acts on.
    window->showDevice(window->devicePage("cabinet-b", "ipc300", 1));
    QCOMPARE(window->currentLine()->name(), QString("cabinet-b"));
    QVERIFY(window->findChild<QLabel *>("lineState")->text().contains(m_lineB.masterEnd()));
    // The status bar says the lines' states in short.
    auto *status = window->findChild<ElidedLabel *>("lineStatus");
    QTRY_COMPARE(status->fullText(), QString("Lines: 2 connected"));
    QTRY_COMPARE(status->text(), status->fullText());
    QVERIFY2(status->isVisible(), qPrintable(QStringLiteral("%1x%2").arg(status->width()).arg(status->height())));
}

void tst_StationLines::aLostLineShowsOnItsHeaderOnly()
{
    // A line of its own, so the shared ones stay up for the other tests.
    TestLine pulledLine;
    QVERIFY(pulledLine.start());
    SimulatorPeer pulledSim;
    QVERIFY(pulledSim.startOneOfEachFamily(pulledLine.deviceEnd()));
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(QStringLiteral("lost.ini"));
    options.logFolder = m_dir.filePath(QStringLiteral("lost-logs"));
    MainWindow window(families(), options);
    window.resize(1280, 800);
    window.show();
    StationLine *live = window.lines().first();
    live->setSettings(lineSettings(m_lineA.masterEnd()));
    StationLine *pulled = window.addLine(QStringLiteral("pulled"), lineSettings(pulledLine.masterEnd()));
    QVERIFY(pulled);
    QVERIFY(window.connectLine(live));
    QVERIFY(window.connectLine(pulled));
    window.addDevice(live, families().family("quantrol"), 3);
    window.addDevice(pulled, families().family("ipc300"), 1);
    window.addDevice(pulled, families().family("dtron300"), 4);
    DeviceTile *liveTile = window.deviceTile("line1", "quantrol", 3);
    QTRY_VERIFY_WITH_TIMEOUT(liveTile->stateText() == "Online", 20000);
    for (quint8 address : {1, 4}) {
        DeviceTile *tile = window.deviceTile("pulled", address == 1 ? "ipc300" : "dtron300", address);
        QTRY_VERIFY_WITH_TIMEOUT(tile->stateText() == "Online", 20000);
    }
    QTRY_COMPARE(window.linesSummary(), QString("Lines: 2 connected"));

    // socat dies: both ends of the pulled line are gone.
    const qint64 pid = pulledLine.socatPid();
    QVERIFY(pid > 0);
    QCOMPARE(::kill(pid_t(pid), SIGKILL), 0);
    LineHeader *header = window.lineHeader("pulled");
    QTRY_VERIFY_WITH_TIMEOUT(header->stateText().startsWith(QString("\u2716 Line lost")), 20000);
    for (quint8 address : {1, 4}) {
        DeviceTile *tile = window.deviceTile("pulled", address == 1 ? "ipc300" : "dtron300", address);
        QTRY_VERIFY_WITH_TIMEOUT(tile->stateText().startsWith("Line lost since"), 20000);
        QCOMPARE(tile->summaryText(), QString("Line lost"));
    }
    QCOMPARE(pulled->state(), LineState::Lost);
    QTRY_COMPARE(window.linesSummary(), QString("Lines: 1 connected, 1 lost"));
    auto *list = window.findChild<NavigationList *>(QStringLiteral("navigation"));
    QCOMPARE(list->item(list->rowOfLine(pulled))->text(), QString("pulled (lost)"));
    QCOMPARE(list->item(list->rowOfLine(live))->text(), QString("line1 (connected)"));

    // The other line goes on: connected, its faceplate online, its values moving.
    QCOMPARE(window.lineHeader("line1")->stateText(), QString("\u25CF Connected"));
    QCOMPARE(liveTile->stateText(), QString("Online"));
    m_simA.line().device(3)->setNumber("controller_setpoint", 77);
    QTRY_VERIFY_WITH_TIMEOUT(liveTile->valuesText().contains("Setpoint: 77"), 20000);
    QCOMPARE(liveTile->stateText(), QString("Online"));

    // The journal names the devices with their line: there are two.
    bool journalled = false;
    for (const QJsonObject &r : logRecords(window.alarmJournal()->path())) {
        if (r.value("device").toString() == "pulled/ipc300@1" && r.value("state").toString() == "lost: line lost")
            journalled = true;
        QVERIFY2(r.value("device").toString().contains('/'), qPrintable(r.value("device").toString()));
    }
    QVERIFY(journalled);
    window.close();
}

void tst_StationLines::settingsRestoreBothLines()
{
    {
        auto window = twoLineWindow(QStringLiteral("restore"));
        QVERIFY(window);
        window->close();
    }
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(QStringLiteral("restore.ini"));
    options.logFolder = m_dir.filePath(QStringLiteral("restore-logs"));
    MainWindow again(families(), options);
    QCOMPARE(again.lines().size(), 2);
    StationLine *a = again.lines()[0];
    StationLine *b = again.lines()[1];
    QCOMPARE(a->name(), QString("line1"));
    QCOMPARE(a->settings().portName, m_lineA.masterEnd());
    QCOMPARE(b->name(), QString("cabinet-b"));
    QCOMPARE(b->settings().portName, m_lineB.masterEnd());
    QCOMPARE(b->settings().format.baudRate, 19200);
    QVERIFY(again.deviceTile("line1", "ipc300", 1));
    QVERIFY(again.deviceTile("line1", "quantrol", 3));
    QVERIFY(!again.deviceTile("line1", "tya200", 2));
    QVERIFY(again.deviceTile("cabinet-b", "tya200", 2));
    QVERIFY(again.deviceTile("cabinet-b", "ipc300", 1));
    QCOMPARE(a->bus()->devices().size(), 2);
    QCOMPARE(b->bus()->devices().size(), 2);
    // Restored disconnected; connecting all brings both lines' devices online.
    QCOMPARE(again.linesSummary(), QString("Lines: 2 disconnected"));
    again.show();
    again.connectAllLines();
    QCOMPARE(again.linesSummary(), QString("Lines: 2 connected"));
    QTRY_VERIFY_WITH_TIMEOUT(again.deviceTile("cabinet-b", "tya200", 2)->stateText() == "Online", 20000);
    QTRY_VERIFY_WITH_TIMEOUT(again.deviceTile("line1", "quantrol", 3)->stateText() == "Online", 20000);
}

void tst_StationLines::oneLineSettingsBecomeLine1()
{
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(QStringLiteral("old.ini"));
    options.logFolder = m_dir.filePath(QStringLiteral("old-logs"));
    {
        QSettings old(options.settingsFile, QSettings::IniFormat);
        old.setValue("line/port", m_lineA.masterEnd());
        old.setValue("line/baud", 19200);
        old.setValue("line/format", "8E1");
        old.setValue("devices", QStringList{"ipc300@1", "dtron300@4"});
    }
    {
        MainWindow window(families(), options);
        QCOMPARE(window.lines().size(), 1);
        StationLine *line = window.lines().first();
        QCOMPARE(line->name(), QString("line1"));
        QCOMPARE(line->settings().portName, m_lineA.masterEnd());
        QCOMPARE(line->settings().format.formatName(), QString("8E1"));
        QVERIFY(window.deviceTile("line1", "ipc300", 1));
        QVERIFY(window.deviceTile("line1", "dtron300", 4));
        // One line: no headers, no line rows, and the journal names devices as before.
        QVERIFY(!window.findChild<OverviewPage *>(QStringLiteral("overview"))->headersShown());
        auto *list = window.findChild<NavigationList *>(QStringLiteral("navigation"));
        QCOMPARE(list->rowOfLine(line), -1);
        QCOMPARE(line->deviceName(line->bus()->devices().first()), QString("ipc300@1"));
        window.close();
    }
    const QSettings kept(options.settingsFile, QSettings::IniFormat);
    QVERIFY(!kept.contains("line/port"));
    QCOMPARE(kept.value("lines/size").toInt(), 1);
    QCOMPARE(kept.value("lines/1/name").toString(), QString("line1"));
    QCOMPARE(kept.value("lines/1/devices").toStringList(), QStringList({"ipc300@1", "dtron300@4"}));
}

void tst_StationLines::removingALineAsksAndTakesItsDevices()
{
    auto window = twoLineWindow(QStringLiteral("remove"));
    QVERIFY(window);
    StationLine *b = window->line("cabinet-b");
    const QList<DeviceId> gone = b->bus()->devices();
    QCOMPARE(gone.size(), 2);
    window->setCurrentLine(b);
    auto *remove = window->findChild<QAction *>(QStringLiteral("removeLine"));
    QVERIFY(remove);
    const QString question = answerYes([remove] { remove->trigger(); });
    QCOMPARE(question, QString("Remove line cabinet-b from the station?\nDevices removed with it: 2 (TYA 200 @ 2, IPC 300 @ 1)."));
    QCOMPARE(window->lines().size(), 1);
    QVERIFY(!window->line("cabinet-b"));
    QVERIFY(!window->deviceTile("cabinet-b", "tya200", 2));
    QVERIFY(!window->deviceTile("tya200", 2));
    // The other line's devices stay; the overview and the list are one line's again.
    QVERIFY(window->deviceTile("line1", "ipc300", 1));
    QVERIFY(window->deviceTile("line1", "quantrol", 3));
    auto *overview = window->findChild<OverviewPage *>(QStringLiteral("overview"));
    QVERIFY(!overview->headersShown());
    QCOMPARE(overview->findChildren<DeviceTile *>().size(), 2);
    auto *list = window->findChild<NavigationList *>(QStringLiteral("navigation"));
    QCOMPARE(list->count(), list->pageCount() + 2);
    for (DeviceId id : gone)
        QCOMPARE(list->rowOf(id), -1);
    QCOMPARE(window->currentLine()->name(), QString("line1"));
    // The last line stays: removing it is refused.
    QVERIFY(!window->removeLine(window->lines().first()));
    window->close();
    const QSettings kept(m_dir.filePath(QStringLiteral("remove.ini")), QSettings::IniFormat);
    QCOMPARE(kept.value("lines/size").toInt(), 1);
}

void tst_StationLines::serialTcpAndRtuOverTcpLinesAtOnce()
{
    // One window, three kinds of line: the serial pty line, a Modbus TCP gateway (the unit
    // id is the device's address) and a serial device server passing RTU frames through
    // TCP, each with a simulated line behind it.
    SimulatorLine gatewayLine;
    gatewayLine.setFormat(testFormat());
    gatewayLine.setTickInterval(100);
    gatewayLine.addDevice(families().family("tya200"), 5);
    SimulatorServer gateway(&gatewayLine, SimulatorServer::Mode::ModbusTcp);
    QVERIFY(gateway.listen(QHostAddress::LocalHost, 0));
    SimulatorLine serverLine;
    serverLine.setFormat(testFormat());
    serverLine.setTickInterval(100);
    serverLine.addDevice(families().family("dtron300"), 7);
    SimulatorServer deviceServer(&serverLine, SimulatorServer::Mode::RtuOverTcp);
    QVERIFY(deviceServer.listen(QHostAddress::LocalHost, 0));

    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(QStringLiteral("kinds.ini"));
    options.logFolder = m_dir.filePath(QStringLiteral("kinds-logs"));
    MainWindow window(families(), options);
    window.resize(1280, 800);
    window.show();
    StationLine *serial = window.lines().value(0);
    QVERIFY(serial);
    serial->setSettings(lineSettings(m_lineA.masterEnd()));
    const QString gatewayAddress = QStringLiteral("tcp://127.0.0.1:%1").arg(gateway.port());
    const QString serverAddress = QStringLiteral("rtu+tcp://127.0.0.1:%1").arg(deviceServer.port());
    StationLine *tcp = window.addLine(QStringLiteral("gateway"), lineSettings(gatewayAddress));
    StationLine *rtuTcp = window.addLine(QStringLiteral("devserver"), lineSettings(serverAddress));
    QVERIFY(tcp && rtuTcp);
    QVERIFY(window.connectLine(serial));
    QVERIFY(window.connectLine(tcp));
    QVERIFY(window.connectLine(rtuTcp));
    window.addDevice(serial, families().family("ipc300"), 1);
    window.addDevice(tcp, families().family("tya200"), 5);
    window.addDevice(rtuTcp, families().family("dtron300"), 7);
    window.showOverview();

    const QList<std::tuple<QString, QString, int, QString>> devices{{"line1", "ipc300", 1, m_lineA.masterEnd()},
                                                                    {"gateway", "tya200", 5, gatewayAddress},
                                                                    {"devserver", "dtron300", 7, serverAddress}};
    for (const auto &[line, family, address, where] : devices) {
        DeviceTile *tile = window.deviceTile(line, family, quint8(address));
        QVERIFY2(tile, qPrintable(line + "/" + family));
        QTRY_VERIFY_WITH_TIMEOUT(tile->stateText() == "Online", 20000);
        QTRY_VERIFY_WITH_TIMEOUT(!tile->valuesText().contains(QStringLiteral("\u2014")), 20000);
        LineHeader *header = window.lineHeader(line);
        QVERIFY2(header && header->isVisible(), qPrintable(line));
        QCOMPARE(header->stateText(), QString("\u25CF Connected"));
        QVERIFY2(header->toolTip().contains(where), qPrintable(header->toolTip()));
    }
    // A setpoint changed behind each kind of line reaches its own faceplate.
    m_simA.line().device(1)->setNumber("input_setpoint", 33);
    gatewayLine.device(5)->setNumber("setpoint", 44);
    serverLine.device(7)->setNumber("setpoint", 155);
    QTRY_VERIFY_WITH_TIMEOUT(window.deviceTile("line1", "ipc300", 1)->valuesText().contains("Setpoint: 33"), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(window.deviceTile("gateway", "tya200", 5)->valuesText().contains("Setpoint: 44"), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(window.deviceTile("devserver", "dtron300", 7)->valuesText().contains("Setpoint: 155"),
                             20000);
    auto *status = window.findChild<ElidedLabel *>("lineStatus");
    QTRY_COMPARE(status->fullText(), QString("Lines: 3 connected"));

    // The gateway gone: its line is lost, the other two stay live.
    gateway.close();
    gateway.dropConnections();
    QTRY_VERIFY_WITH_TIMEOUT(window.deviceTile("gateway", "tya200", 5)->stateText() != "Online", 20000);
    QCOMPARE(window.deviceTile("line1", "ipc300", 1)->stateText(), QString("Online"));
    QCOMPARE(window.deviceTile("devserver", "dtron300", 7)->stateText(), QString("Online"));
}

QTEST_MAIN(tst_StationLines)
#include "tst_stationlines.moc"
