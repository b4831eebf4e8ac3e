// Serial ports as users know them: by-id links resolved against a folder of symlinks,
// the system's list renamed by them, the device a name leads to now, the list's labels.
#include "bus/serialportlist.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace jumo;

class tst_SerialPortList : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void byIdLinksLeadToExistingDevices();
    void systemPortsTakeTheirStableNames();
    void currentDeviceFollowsALink();
    void labels_data();
    void labels();

private:
    bool makeDevice(const QString &name) { return QFile(m_dir->filePath(name)).open(QIODevice::WriteOnly); }
    bool makeLink(const QString &name, const QString &target)
    {
        return QFile::link(m_dir->filePath(target), m_dir->filePath("by-id/" + name));
    }

    std::unique_ptr<QTemporaryDir> m_dir;
};

void tst_SerialPortList::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    QVERIFY(QDir(m_dir->path()).mkdir("by-id"));
    // Stand-ins for /dev/ttyUSB0 and /dev/ttyUSB1, with udev's kind of links to them.
    QVERIFY(makeDevice("ttyUSB0"));
    QVERIFY(makeDevice("ttyUSB1"));
    QVERIFY(makeLink("usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0", "ttyUSB1"));
    QVERIFY(makeLink("usb-1a86_USB_Serial-if00-port0", "ttyUSB0"));
    QVERIFY(makeLink("usb-1a86_USB_Serial-if00-port0-copy", "ttyUSB0"));   // a second link: the first by name wins
    QVERIFY(makeLink("usb-Prolific_unplugged-if00-port0", "ttyUSB7"));     // leads nowhere
    QVERIFY(QFile(m_dir->filePath("by-id/not-a-link")).open(QIODevice::WriteOnly));
}

void tst_SerialPortList::byIdLinksLeadToExistingDevices()
{
    const QHash<QString, QString> links = SerialPortList::byIdLinks(m_dir->filePath("by-id"));
    const QHash<QString, QString> expected{
            {m_dir->filePath("ttyUSB0"), m_dir->filePath("by-id/usb-1a86_USB_Serial-if00-port0")},
            {m_dir->filePath("ttyUSB1"), m_dir->filePath("by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0")}};
    QCOMPARE(links, expected);
    QVERIFY(SerialPortList::byIdLinks(m_dir->filePath("no-such-folder")).isEmpty());
}

void tst_SerialPortList::systemPortsTakeTheirStableNames()
{
    SerialPort ftdi;
    ftdi.device = ftdi.location = m_dir->filePath("ttyUSB1");
    ftdi.description = "FT232R USB UART";
    ftdi.serialNumber = "A50285BI";
    SerialPort onboard;
    onboard.device = onboard.location = "/dev/ttyS0";
    QHash<QString, QString> links = SerialPortList::byIdLinks(m_dir->filePath("by-id"));
    links.insert("/dev/pts/7", m_dir->filePath("by-id/pty-test-link"));   // a device the system does not list

    const QList<SerialPort> ports = SerialPortList::merge({onboard, ftdi}, links);
    QCOMPARE(ports.size(), 4);
    QCOMPARE(ports[0].location, "/dev/ttyS0");   // sorted by the name to open
    QVERIFY(!ports[0].hasStableName());
    QCOMPARE(ports[1].location, m_dir->filePath("by-id/pty-test-link"));
    QCOMPARE(ports[1].device, "/dev/pts/7");
    // ttyUSB0 is not listed by the system: its link makes it a port of its own.
    QCOMPARE(ports[2].location, m_dir->filePath("by-id/usb-1a86_USB_Serial-if00-port0"));
    QCOMPARE(ports[2].device, m_dir->filePath("ttyUSB0"));
    QVERIFY(ports[2].hasStableName());
    QCOMPARE(ports[3].location, m_dir->filePath("by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0"));
    QCOMPARE(ports[3].device, m_dir->filePath("ttyUSB1"));
    QCOMPARE(ports[3].description, "FT232R USB UART");
    QCOMPARE(ports[3].serialNumber, "A50285BI");
}

void tst_SerialPortList::currentDeviceFollowsALink()
{
    const QString link = m_dir->filePath("by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0");
    QCOMPARE(SerialPortList::currentDevice(link), m_dir->filePath("ttyUSB1"));
    // Re-plugged: udev points the same name at the adapter's new device.
    QVERIFY(QFile::remove(link));
    QVERIFY(makeLink("usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0", "ttyUSB0"));
    QCOMPARE(SerialPortList::currentDevice(link), m_dir->filePath("ttyUSB0"));
    // Unplugged, or a name that never was: the name itself, so the error names it.
    const QString unplugged = m_dir->filePath("by-id/usb-Prolific_unplugged-if00-port0");
    QCOMPARE(SerialPortList::currentDevice(unplugged), unplugged);
}

void tst_SerialPortList::labels_data()
{
    QTest::addColumn<QString>("location");
    QTest::addColumn<QString>("device");
    QTest::addColumn<QString>("description");
    QTest::addColumn<QString>("serial");
    QTest::addColumn<QString>("label");
    QTest::newRow("adapter with by-id name and serial number")
            << "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0" << "/dev/ttyUSB1" << "FT232R USB UART"
            << "A50285BI"
            << "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0 (FT232R USB UART, serial number "
               "A50285BI, ttyUSB1)";
    QTest::newRow("adapter without serial number")
            << "/dev/serial/by-id/usb-1a86_USB_Serial-if00-port0" << "/dev/ttyUSB0" << "USB Serial" << ""
            << "/dev/serial/by-id/usb-1a86_USB_Serial-if00-port0 (USB Serial, ttyUSB0)";
    QTest::newRow("onboard port") << "/dev/ttyS0" << "/dev/ttyS0" << "" << "" << "/dev/ttyS0";
}

void tst_SerialPortList::labels()
{
    QFETCH(QString, location);
    QFETCH(QString, device);
    QFETCH(QString, description);
    QFETCH(QString, serial);
    QFETCH(QString, label);
    SerialPort port;
    port.location = location;
    port.device = device;
    port.description = description;
    port.serialNumber = serial;
    QCOMPARE(SerialPortList::label(port), label);
}

QTEST_GUILESS_MAIN(tst_SerialPortList)
#include "tst_serialportlist.moc"
