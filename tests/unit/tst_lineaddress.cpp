// Line addresses: serial paths stay paths; tcp:// and rtu+tcp:// URLs are taken apart or
// refused with a message that names what is wrong.
#include "bus/lineaddress.h"

#include <QTest>

using namespace jumo;

class tst_LineAddress : public QObject
{
    Q_OBJECT

private slots:
    void parses_data();
    void parses();
    void refuses_data();
    void refuses();
    void kindNames();
    void shareMaster_data();
    void shareMaster();
};

void tst_LineAddress::parses_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("host");
    QTest::addColumn<int>("port");
    QTest::addColumn<QString>("endpoint");
    const int serial = int(LineAddress::Kind::Serial);
    const int tcp = int(LineAddress::Kind::ModbusTcp);
    const int rtuTcp = int(LineAddress::Kind::RtuOverTcp);
    QTest::newRow("a device path is a serial port") << "/dev/ttyUSB0" << serial << "" << 0 << "";
    QTest::newRow("a by-id link is a serial port")
            << "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A1-if00-port0" << serial << "" << 0 << "";
    QTest::newRow("a relative pty link is a serial port") << "line/master" << serial << "" << 0 << "";
    QTest::newRow("a Windows-style name is a serial port") << "COM3" << serial << "" << 0 << "";
    QTest::newRow("a path with a colon is a serial port") << "/tmp/a:b" << serial << "" << 0 << "";
    QTest::newRow("tcp with a port") << "tcp://10.0.0.20:502" << tcp << "10.0.0.20" << 502 << "10.0.0.20:502";
    QTest::newRow("tcp without a port is 502") << "tcp://gateway-1" << tcp << "gateway-1" << 502 << "gateway-1:502";
    QTest::newRow("tcp with another port") << "tcp://gw.example.org:1502" << tcp << "gw.example.org" << 1502
                                           << "gw.example.org:1502";
    QTest::newRow("tcp to IPv6 in brackets") << "tcp://[::1]:5020" << tcp << "::1" << 5020 << "[::1]:5020";
    QTest::newRow("tcp to IPv6 without a port") << "tcp://[fe80::1%eth0]" << tcp << "fe80::1%eth0" << 502
                                                << "[fe80::1%eth0]:502";
    QTest::newRow("the scheme in capitals") << "TCP://10.0.0.1" << tcp << "10.0.0.1" << 502 << "10.0.0.1:502";
    QTest::newRow("rtu+tcp with a port") << "rtu+tcp://10.0.0.21:4001" << rtuTcp << "10.0.0.21" << 4001
                                         << "10.0.0.21:4001";
    QTest::newRow("rtu+tcp to IPv6") << "rtu+tcp://[2001:db8::7]:950" << rtuTcp << "2001:db8::7" << 950
                                     << "[2001:db8::7]:950";
    QTest::newRow("the highest port") << "rtu+tcp://localhost:65535" << rtuTcp << "localhost" << 65535
                                      << "localhost:65535";
}

void tst_LineAddress::parses()
{
    QFETCH(QString, text);
    QFETCH(int, kind);
    QFETCH(QString, host);
    QFETCH(int, port);
    QFETCH(QString, endpoint);
    QString error;
    const std::optional<LineAddress> address = LineAddress::parse(text, &error);
    QVERIFY2(address, qPrintable(error));
    QCOMPARE(int(address->kind), kind);
    QCOMPARE(address->text, text);
    QCOMPARE(address->host, host);
    QCOMPARE(int(address->port), port);
    QCOMPARE(address->isNetwork(), kind != int(LineAddress::Kind::Serial));
    if (address->isNetwork())
        QCOMPARE(address->endpoint(), endpoint);
}

void tst_LineAddress::refuses_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("says");
    QTest::newRow("nothing") << "" << "no line address";
    QTest::newRow("only blanks") << "   " << "no line address";
    QTest::newRow("an unknown scheme") << "udp://10.0.0.1:502" << "unknown line address scheme 'udp://'";
    QTest::newRow("a web address") << "http://10.0.0.1" << "unknown line address scheme";
    QTest::newRow("tcp without a host") << "tcp://" << "names no host";
    QTest::newRow("tcp with only a port") << "tcp://:502" << "names no host";
    QTest::newRow("rtu+tcp without a port") << "rtu+tcp://10.0.0.21" << "names no port";
    QTest::newRow("a colon without a port") << "tcp://10.0.0.1:" << "no port after it";
    QTest::newRow("port 0") << "tcp://10.0.0.1:0" << "1..65535, not '0'";
    QTest::newRow("a port above 65535") << "rtu+tcp://10.0.0.1:65536" << "1..65535, not '65536'";
    QTest::newRow("a port that is no number") << "tcp://10.0.0.1:modbus" << "1..65535, not 'modbus'";
    QTest::newRow("a negative port") << "tcp://10.0.0.1:-5" << "1..65535";
    QTest::newRow("a trailing path") << "tcp://10.0.0.1:502/unit/1" << "'/unit/1' after the port";
    QTest::newRow("a trailing slash") << "tcp://10.0.0.1/" << "after the port";
    QTest::newRow("a query") << "rtu+tcp://10.0.0.1:4001?baud=9600" << "'?baud=9600' after the port";
    QTest::newRow("a user name") << "tcp://admin@10.0.0.1" << "user names";
    QTest::newRow("IPv6 without brackets") << "tcp://::1:502" << "in brackets";
    QTest::newRow("IPv6 with an open bracket") << "tcp://[::1:502" << "lacks its ']'";
    QTest::newRow("junk after the bracket") << "tcp://[::1]x" << "only ':PORT'";
    QTest::newRow("a blank in the host") << "tcp://my gateway:502" << "not a host name";
}

void tst_LineAddress::refuses()
{
    QFETCH(QString, text);
    QFETCH(QString, says);
    QString error;
    QVERIFY(!LineAddress::parse(text, &error));
    QVERIFY2(error.contains(says), qPrintable(error));
    QVERIFY(!LineAddress::parse(text, nullptr));   // no error text wanted: still refused
}

void tst_LineAddress::kindNames()
{
    QCOMPARE(LineAddress::parse("/dev/ttyUSB0", nullptr)->kindName(), QString("rtu"));
    QCOMPARE(LineAddress::parse("tcp://h", nullptr)->kindName(), QString("tcp"));
    QCOMPARE(LineAddress::parse("rtu+tcp://h:1", nullptr)->kindName(), QString("rtu+tcp"));
}

void tst_LineAddress::shareMaster_data()
{
    QTest::addColumn<QString>("a");
    QTest::addColumn<QString>("b");
    QTest::addColumn<bool>("shared");   // with names looked up
    QTest::addColumn<bool>("literally");   // without a look-up
    QTest::newRow("one address") << "rtu+tcp://10.0.0.21:4001" << "rtu+tcp://10.0.0.21:4001" << true << true;
    QTest::newRow("another port") << "rtu+tcp://10.0.0.21:4001" << "rtu+tcp://10.0.0.21:4002" << false << false;
    QTest::newRow("another address") << "rtu+tcp://10.0.0.21:4001" << "rtu+tcp://10.0.0.22:4001" << false << false;
    QTest::newRow("IPv4-mapped") << "rtu+tcp://10.0.0.21:4001" << "rtu+tcp://[::ffff:10.0.0.21]:4001" << true << true;
    QTest::newRow("IPv4-mapped in hex") << "rtu+tcp://10.0.0.21:4001" << "rtu+tcp://[::ffff:a00:15]:4001" << true << true;
    QTest::newRow("localhost") << "rtu+tcp://localhost:4001" << "rtu+tcp://127.0.0.1:4001" << true << true;
    QTest::newRow("a subdomain of localhost") << "rtu+tcp://nport.localhost:4001" << "rtu+tcp://[::1]:4001" << true
                                              << true;
    QTest::newRow("a name and the address it has") << "rtu+tcp://cabinet-7:4001" << "rtu+tcp://10.0.0.21:4001" << true
                                                   << false;
    QTest::newRow("two names of one address") << "rtu+tcp://cabinet-7:4001" << "rtu+tcp://NPORT-7.plant:4001" << true
                                              << false;
    QTest::newRow("a name that does not resolve") << "rtu+tcp://nowhere:4001" << "rtu+tcp://10.0.0.21:4001" << false
                                                  << false;
    QTest::newRow("one name in two cases") << "rtu+tcp://Nowhere:4001" << "rtu+tcp://nowhere:4001" << true << true;
    QTest::newRow("one gateway") << "tcp://10.0.0.20" << "tcp://10.0.0.20" << false << false;
    QTest::newRow("a gateway and a device server") << "tcp://10.0.0.20:4001" << "rtu+tcp://10.0.0.20:4001" << false
                                                   << false;
}

void tst_LineAddress::shareMaster()
{
    QFETCH(QString, a);
    QFETCH(QString, b);
    QFETCH(bool, shared);
    QFETCH(bool, literally);
    int lookUps = 0;
    // A resolver of this test's own: no name service is asked.
    const auto resolve = [&lookUps](const QString &name) -> QStringList {
        ++lookUps;
        if (name == "cabinet-7" || name == "nport-7.plant")
            return {"10.0.0.21", "::ffff:10.0.0.21"};
        return {};
    };
    const LineAddress first = *LineAddress::parse(a, nullptr);
    const LineAddress second = *LineAddress::parse(b, nullptr);
    QCOMPARE(LineAddress::shareMaster(first, second, resolve), shared);
    QCOMPARE(LineAddress::shareMaster(second, first, resolve), shared);
    QCOMPARE(LineAddress::shareMaster(first, second), literally);
    if (literally)
        QCOMPARE(lookUps, 0);   // nothing is looked up that the addresses decide
}

QTEST_APPLESS_MAIN(tst_LineAddress)
#include "tst_lineaddress.moc"
