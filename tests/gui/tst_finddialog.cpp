// Devices > Find on an unknown line, on the offscreen platform: a TYA 200 set to 19200 8E1
// at address 4 on a simulated line that answers only at its own settings (the simulator
// watches the client's end of the pty pair); the HMI's line is at 9600 8N1 and hears
// nothing until the search has found the device and its settings are taken over.
#include "connectionbar.h"
#include "devicetile.h"
#include "finddialog.h"
#include "mainwindow.h"
#include "testpeers.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>

using namespace jumo;
using namespace jumo::test;

class tst_FindDialog : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void findsTheDeviceAndTakesItsSettings();
    void offersASettingWhereOnlyAddress255Answered();

private:
    QTemporaryDir m_dir;
    TestLine m_line;
    SimulatorLine m_sim;
};

void tst_FindDialog::initTestCase()
{
    qputenv("JUMO_MAP_PATH", "");
    QVERIFY(m_line.start());
    m_sim.addDevice(families().family("tya200"), 4);
    m_sim.setPacing(true);
    QVERIFY(m_sim.watchClientEnd(m_line.masterEnd()));
    QVERIFY(m_sim.open(m_line.deviceEnd(), *LineFormat::parse(19200, "8E1")));
}

void tst_FindDialog::findsTheDeviceAndTakesItsSettings()
{
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath("find.ini");
    options.logFolder = m_dir.filePath("logs");
    MainWindow window(families(), options);
    window.resize(1280, 800);
    window.show();
    window.connectionBar()->setSettings(m_line.masterEnd(), 9600, "8N1");
    // Connected at the wrong settings: the search asks to disconnect the line first.
    QVERIFY(window.connectLine());
    QTRY_COMPARE(window.bus()->state(), LineState::Connected);
    auto *find = window.findChild<QAction *>("findDevices");
    QVERIFY(find);
    QTimer::singleShot(200, this, [] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        QVERIFY(box && box->text().contains("disconnect the line now?"));
        box->button(QMessageBox::Yes)->click();
    });
    find->trigger();
    QTRY_COMPARE(window.bus()->state(), LineState::Disconnected);
    auto *dialog = window.findChild<FindDialog *>("findDialog");
    QVERIFY(dialog);
    dialog->findChild<QSpinBox *>("findTo")->setValue(6);
    auto *plan = dialog->findChild<QLabel *>("findPlan");
    QVERIFY2(plan->text().startsWith("16 setting(s) to try: about "), qPrintable(plan->text()));
    QTest::mouseClick(dialog->findChild<QPushButton *>("startFind"), Qt::LeftButton);
    QVERIFY(dialog->isSearching());
    QVERIFY(!dialog->findChild<QSpinBox *>("findTo")->isEnabled());
    auto *progress = dialog->findChild<QProgressBar *>("findProgress");
    const QString screenshots = qEnvironmentVariable("JUMO_SCREENSHOT_DIR");
    QTRY_VERIFY_WITH_TIMEOUT(progress->format().contains("left"), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(!dialog->isSearching(), 180000);
    QVERIFY2(progress->format().startsWith("done in "), qPrintable(progress->format()));
    if (!screenshots.isEmpty())
        dialog->grab().save(screenshots + QStringLiteral("/find-done.png"));

    // Found at 19200 baud only: 8E1, and 8N1, which a pty cannot tell from it (said).
    auto *results = dialog->findChild<QTreeWidget *>("findResults");
    QStringList rows;
    for (int i = 0; i < results->topLevelItemCount(); ++i)
        rows << QStringLiteral("%1|%2|%3").arg(results->topLevelItem(i)->text(0), results->topLevelItem(i)->text(1),
                                               results->topLevelItem(i)->text(2));
    QCOMPARE(rows, QStringList({"19200 baud 8N1|4|JUMO TYA 200 thyristor power units", "19200 baud 8E1|4|JUMO TYA 200 thyristor power units"}));
    QVERIFY(dialog->findChild<QLabel *>("findNote")->isVisible());
    auto *setting = dialog->findChild<QComboBox *>("findSetting");
    QCOMPARE(setting->count(), 2);
    setting->setCurrentText("19200 baud 8E1");
    QCOMPARE(dialog->chosen().size(), 1);

    // Taken over: the line at the device's settings, the device added and online.
    dialog->findChild<QPushButton *>("useFound")->click();
    QCOMPARE(window.bus()->settings().format, *LineFormat::parse(19200, "8E1"));
    QTRY_COMPARE(window.bus()->state(), LineState::Connected);
    DeviceTile *tile = window.deviceTile("tya200", 4);
    QVERIFY(tile);
    QTRY_COMPARE_WITH_TIMEOUT(tile->stateText(), QString("Online"), 30000);
}

void tst_FindDialog::offersASettingWhereOnlyAddress255Answered()
{
    // The TYA's own address (4) is outside 5..10: it is heard at 255 only, and that is
    // still a setting to take over for the line.
    BusSettings line;
    line.portName = m_line.masterEnd();
    FindDialog dialog(line, families());
    dialog.show();
    dialog.findChild<QSpinBox *>("findFrom")->setValue(5);
    dialog.findChild<QSpinBox *>("findTo")->setValue(10);
    QTest::mouseClick(dialog.findChild<QPushButton *>("startFind"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!dialog.isSearching(), 180000);
    auto *results = dialog.findChild<QTreeWidget *>("findResults");
    QStringList rows;
    for (int i = 0; i < results->topLevelItemCount(); ++i)
        rows << QStringLiteral("%1|%2|%3").arg(results->topLevelItem(i)->text(0), results->topLevelItem(i)->text(1),
                                               results->topLevelItem(i)->text(2));
    const QString outside = "JUMO TYA 200 thyristor power units answers here, as every one does; its own address is outside 5..10";
    QCOMPARE(rows, QStringList({"19200 baud 8N1|255|" + outside, "19200 baud 8E1|255|" + outside}));
    auto *setting = dialog.findChild<QComboBox *>("findSetting");
    QCOMPARE(setting->count(), 2);
    QVERIFY(setting->isEnabled());
    QVERIFY(dialog.findChild<QPushButton *>("useFound")->isEnabled());
    setting->setCurrentText("19200 baud 8E1");
    QCOMPARE(dialog.chosenFormat(), LineFormat::parse(19200, "8E1"));
    QVERIFY(dialog.chosen().isEmpty());   // no device to add: its address is not known
}

QTEST_MAIN(tst_FindDialog)
#include "tst_finddialog.moc"
