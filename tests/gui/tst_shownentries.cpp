// What an operator has on screen is read sooner (issue 22 item 2): the open device page's
// values and an open trend's chosen entries move up a poll class while shown, and back when
// the page or the tab is left. The real window, offscreen, against the simulator on a pty.
#include "connectionbar.h"
#include "devicepage.h"
#include "livevaluesview.h"
#include "mainwindow.h"
#include "testpeers.h"
#include "trendview.h"

#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

class tst_ShownEntries : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void openPageAndTrendAreReadSooner();

private:
    QTemporaryDir m_dir;
    TestLine m_line;
    SimulatorPeer m_sim;
};

void tst_ShownEntries::initTestCase()
{
    qputenv("JUMO_MAP_PATH", "");
    QVERIFY(m_line.start());
    QVERIFY(m_sim.startOneOfEachFamily(m_line.deviceEnd()));
}

void tst_ShownEntries::openPageAndTrendAreReadSooner()
{
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath("shown.ini");
    options.logFolder = m_dir.filePath("logs");
    MainWindow window(families(), options);
    window.resize(1280, 800);
    window.show();
    window.connectionBar()->setSettings(m_line.masterEnd(), 19200, "8N1");
    QVERIFY(window.connectLine());
    QVERIFY(window.addDevice(families().family("dtron300"), 4));
    DevicePage *page = window.devicePage("dtron300", 4);
    QVERIFY(page);
    const DeviceId id = page->device();
    const auto map = families().family("dtron300");
    // A setting that neither the faceplate nor the trend shows at first.
    QString setting;
    for (const RegisterEntry &e : map->entries()) {
        if (e.isReadable() && window.bus()->pollClass(id, e.id) == PollClass::Setting
            && !map->faceplateEntries().contains(e.id)) {
            setting = e.id;
            break;
        }
    }
    QVERIFY(!setting.isEmpty());

    // The overview: the setting is read as a setting.
    QCOMPARE(window.bus()->pollClass(id, setting), PollClass::Setting);
    // The device page's values on screen: read as a live value.
    window.showDevice(page);
    page->tabs()->setCurrentWidget(page->valuesView());
    QTRY_VERIFY(page->valuesView()->isVisible());
    QCOMPARE(window.bus()->pollClass(id, setting), PollClass::Live);
    // Another tab: the values are off screen, the setting a setting again.
    page->tabs()->setCurrentWidget(page->trend());
    QTRY_VERIFY(page->trend()->isVisible());
    QCOMPARE(window.bus()->pollClass(id, setting), PollClass::Setting);
    // Chosen in the open trend: live while the trend shows it.
    page->trend()->select(setting, true);
    QCOMPARE(window.bus()->pollClass(id, setting), PollClass::Live);
    page->trend()->select(setting, false);
    QCOMPARE(window.bus()->pollClass(id, setting), PollClass::Setting);
    page->trend()->select(setting, true);
    // The page left for the overview: nothing of it is shown any more.
    window.showOverview();
    QTRY_VERIFY(!page->trend()->isVisible());
    QCOMPARE(window.bus()->pollClass(id, setting), PollClass::Setting);
}

QTEST_MAIN(tst_ShownEntries)
#include "tst_shownentries.moc"
