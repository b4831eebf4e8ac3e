// The connection bar lists adapters by their stable by-id names with what they are, and
// the HMI remembers that name (a device path from older settings becomes the adapter's
// by-id name), so a re-plugged adapter that comes back as another ttyUSBn is still found.
#include "connectionbar.h"
#include "mainwindow.h"
#include "protocol/familyregistry.h"

#include <QComboBox>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

using namespace jumo;

class tst_ConnectionBar : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void listsAdaptersByTheirStableNames();
    void hmiRemembersTheStableName();
    void takesGatewayAddresses_data();
    void takesGatewayAddresses();

private:
    QTemporaryDir m_dir;
    QString m_device;
    QString m_link;
};

void tst_ConnectionBar::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY(QDir(m_dir.path()).mkdir("by-id"));
    m_device = m_dir.filePath("ttyUSB9");   // stands for the adapter's device now
    QVERIFY(QFile(m_device).open(QIODevice::WriteOnly));
    m_link = m_dir.filePath("by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0");
    QVERIFY(QFile::link(m_device, m_link));
    qputenv("JUMO_SERIAL_BY_ID_DIR", QFile::encodeName(m_dir.filePath("by-id")));
}

void tst_ConnectionBar::listsAdaptersByTheirStableNames()
{
    ConnectionBar bar;
    auto *box = bar.findChild<QComboBox *>("portBox");
    QVERIFY(box);
    const int row = box->findData(m_link);
    QVERIFY2(row >= 0, "the by-id name is listed");
    QVERIFY2(box->itemText(row).startsWith(m_link), qPrintable(box->itemText(row)));
    QVERIFY2(box->itemText(row).contains("ttyUSB9"), qPrintable(box->itemText(row)));   // and the device it is now
    QCOMPARE(box->findData(m_device), -1);   // never under its changing name

    box->setCurrentIndex(row);
    QCOMPARE(bar.port(), m_link);
    bar.refreshPorts();   // the choice survives a new listing
    QCOMPARE(bar.port(), m_link);
    // The device name chosen before, as typed or from older settings: the adapter's stable name.
    bar.setSettings(m_device, 19200, "8E1");
    QCOMPARE(bar.port(), m_link);
    // A path that is not listed (a pseudo-terminal) stays as typed.
    bar.setSettings("/tmp/line/master", 19200, "8E1");
    QCOMPARE(bar.port(), "/tmp/line/master");
    QCOMPARE(bar.baud(), 19200);
    QCOMPARE(bar.format(), "8E1");
}

void tst_ConnectionBar::hmiRemembersTheStableName()
{
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath("settings.ini");
    options.logFolder = m_dir.filePath("logs");
    {
        QSettings old(options.settingsFile, QSettings::IniFormat);
        old.setValue("line/port", m_device);   // what an older version kept
    }
    {
        MainWindow window(registry, options);
        QCOMPARE(window.connectionBar()->port(), m_link);
        window.close();
    }
    QCOMPARE(QSettings(options.settingsFile, QSettings::IniFormat).value("line/port").toString(), m_link);
    MainWindow again(registry, options);
    QCOMPARE(again.connectionBar()->port(), m_link);
}

void tst_ConnectionBar::takesGatewayAddresses_data()
{
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("port");
    QTest::newRow("Modbus TCP gateway") << "tcp://10.0.0.20:502" << "tcp://10.0.0.20:502";
    QTest::newRow("Modbus TCP gateway at its default port") << " tcp://gateway-1 " << "tcp://gateway-1";
    QTest::newRow("RTU over TCP") << "rtu+tcp://10.0.0.21:4001" << "rtu+tcp://10.0.0.21:4001";
    QTest::newRow("IPv6 gateway") << "tcp://[::1]:1502" << "tcp://[::1]:1502";
}

void tst_ConnectionBar::takesGatewayAddresses()
{
    QFETCH(QString, typed);
    QFETCH(QString, port);
    ConnectionBar bar;
    auto *box = bar.findChild<QComboBox *>("portBox");
    QVERIFY(box);
    box->setCurrentIndex(-1);
    QTest::keyClicks(box, typed);
    QCOMPARE(bar.port(), port);
    bar.setSettings(port, 38400, "8N1");
    QCOMPARE(bar.port(), port);
    QVERIFY2(box->toolTip().contains("rtu+tcp://"), qPrintable(box->toolTip()));
}

QTEST_MAIN(tst_ConnectionBar)
#include "tst_connectionbar.moc"
