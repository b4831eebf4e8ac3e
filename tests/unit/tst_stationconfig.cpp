// Station files and "--line" specs: what they hold, how they round-trip, what is refused
// and with which words, and that a full disk leaves the old file in place.
#include "bus/stationconfig.h"
#include "protocol/familyregistry.h"
#include "smalldisk.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace jumo;
using jumo::test::SmallDisk;

namespace {

const FamilyRegistry &registry()
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return r;
}

// A station file of these lines (JSON objects without their braces).
QByteArray stationJson(const QByteArrayList &lines, const QByteArray &top = QByteArray())
{
    QByteArray json = "{\"format\": \"jumo-station\", \"version\": 1, " + top + "\"lines\": [";
    for (qsizetype i = 0; i < lines.size(); ++i)
        json += (i ? ", {" : "{") + lines[i] + "}";
    return json + "]}";
}

// A line on a port of its own (two lines cannot share a serial port).
QByteArray line(const QByteArray &name, const QByteArray &rest = QByteArray())
{
    static int ports = 0;
    return "\"name\": \"" + name + "\", \"port\": \"/dev/ttyUSB" + QByteArray::number(ports++) + "\""
            + (rest.isEmpty() ? "" : ", " + rest);
}

const QString nameRule = QStringLiteral("'name' must be 1..32 of the letters A-Z, a-z, digits, '_', '.' and '-', not ");

} // namespace

class tst_StationConfig : public QObject
{
    Q_OBJECT

private slots:
    void exampleFileLoads();
    void defaultsOfAShortFile();
    void sameAddressOnTwoLines();
    void refusesBadFiles_data();
    void refusesBadFiles();
    void namesEveryProblemAtOnce();
    void loadNamesTheFile();
    void loadRefusesWhatIsNoFile();
    void roundTrip();
    void writesKeysInReadingOrder();
    void fullDiskKeepsTheOldFile();
    void lineSpecs_data();
    void lineSpecs();
    void lineSpecRefusals_data();
    void lineSpecRefusals();
    void lineSpecTakesDefaults();
    void fromLinesNamesLinesByPosition();
    void fromLinesRefuses_data();
    void fromLinesRefuses();
    void fromLinesAcceptsDistinctMasters_data();
    void fromLinesAcceptsDistinctMasters();
    void deviceNames();
    void resolveDevice_data();
    void resolveDevice();
};

void tst_StationConfig::exampleFileLoads()
{
    QString error;
    const auto station = StationConfig::load(QStringLiteral(JUMO_TEST_DATA_DIR "/../../resources/stations/hall-3.json"),
                                             registry(), &error);
    QVERIFY2(station, qPrintable(error));
    QCOMPARE(station->name, "hall-3");
    QCOMPARE(station->lines.size(), 3);
    const LineConfig &a = station->lines[0];
    QCOMPARE(a.name, "cabinet-a");
    QCOMPARE(a.settings.portName, "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A10K1ABC-if00-port0");
    QCOMPARE(a.settings.format.baudRate, 19200);
    QCOMPARE(a.devices, (QList<DeviceSpec>{{"ipc300", 1}, {"ipc300", 2}, {"tya200", 3}}));
    QCOMPARE(station->lines[1].settings.portName, "tcp://10.0.0.20:502");
    const LineConfig &b = station->lines[2];
    QCOMPARE(b.settings.format.formatName(), "8E1");
    QCOMPARE(b.settings.format.baudRate, 38400);
    QVERIFY(b.settings.readOnly);
    QVERIFY(!a.settings.readOnly);
    QCOMPARE(station->devices().size(), 6);
}

void tst_StationConfig::defaultsOfAShortFile()
{
    QString error;
    const auto station = StationConfig::fromJson(stationJson({"\"port\": \"/dev/ttyS0\""}), registry(), &error);
    QVERIFY2(station, qPrintable(error));
    QCOMPARE(station->name, StationConfig::defaultName());
    QVERIFY(StationConfig::isLineName(station->name) || station->name.size() > 32);
    const LineConfig &l = station->lines.first();
    QCOMPARE(l.name, "line1");
    QCOMPARE(l.settings.format.baudRate, 9600);
    QCOMPARE(l.settings.format.formatName(), "8N1");
    QCOMPARE(l.settings.timeoutMs, 0);
    QCOMPARE(l.settings.minimumResponseTimeMs, 0);
    QCOMPARE(l.settings.retries, 2);
    QVERIFY(!l.settings.readOnly);
    QVERIFY(l.devices.isEmpty());
}

void tst_StationConfig::sameAddressOnTwoLines()
{
    QString error;
    const auto station = StationConfig::fromJson(stationJson({line("a", "\"devices\": [\"ipc300@1\"]"),
                                                              line("b", "\"devices\": [\"tya200@1\"]")}),
                                                 registry(), &error);
    QVERIFY2(station, qPrintable(error));
    QCOMPARE(station->devices().size(), 2);
}

void tst_StationConfig::refusesBadFiles_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    QTest::newRow("not JSON") << QByteArray("{ nope") << "malformed JSON at byte 3: unterminated object";
    QTest::newRow("another JSON file") << QByteArray("{\"format\": \"jumo-parameters\", \"version\": 1}")
                                       << "not a station file (no \"format\": \"jumo-station\")";
    QTest::newRow("top level an array") << QByteArray("[1]") << "not a station file (no \"format\": \"jumo-station\")";
    QTest::newRow("future version") << QByteArray("{\"format\": \"jumo-station\", \"version\": 2, \"lines\": []}")
                                    << "station file version 2 is not supported (expected 1)";
    QTest::newRow("a key given twice")
            << QByteArray("{\"format\": \"jumo-station\", \"version\": 1, \"lines\": [{\"port\": \"a\", \"port\": \"b\"}]}")
            << "malformed JSON at byte 65: 'port' given twice in one object";
    QTest::newRow("a NUL in a text") << QByteArray("{\"format\": \"jumo-station\", \"name\": \"a") + '\0' + "b\"}"
                                     << "malformed JSON at byte 37: a control character";
    QTest::newRow("unknown top-level key") << stationJson({line("a")}, "\"station\": \"x\", ") << "unknown key 'station'";
    QTest::newRow("bad station name") << stationJson({line("a")}, "\"name\": \"hall 3\", ")
                                      << "'name' must be 1..64 of the letters A-Z, a-z, digits, '_', '.' and '-', not 'hall 3'";
    QTest::newRow("no lines key") << QByteArray("{\"format\": \"jumo-station\", \"version\": 1}")
                                  << "'lines' must be an array of lines";
    QTest::newRow("a line is no object") << stationJson({}).replace("[]", "[\"/dev/ttyUSB0\"]")
                                         << "lines[0]: a line must be an object, not /dev/ttyUSB0";
    QTest::newRow("unknown line key") << stationJson({line("a", "\"bauds\": 9600")}) << "lines[0] (a): unknown key 'bauds'";
    QTest::newRow("missing port") << stationJson({"\"name\": \"a\""})
                                  << "lines[0] (a): 'port' is missing or not a non-empty string";
    QTest::newRow("empty port") << stationJson({"\"name\": \"a\", \"port\": \"\""})
                                << "lines[0] (a): 'port' is missing or not a non-empty string";
    QTest::newRow("blank port") << stationJson({"\"name\": \"a\", \"port\": \"  \""})
                                << "lines[0] (a): 'port': the line address (serial port or URL) is empty";
    QTest::newRow("one port on two lines")
            << stationJson({"\"name\": \"a\", \"port\": \"/dev/ttyS4\"", "\"name\": \"b\", \"port\": \"/dev/ttyS4\""})
            << "lines[1] (b): 'port' /dev/ttyS4 is the port of lines[0] (a) too: a line has one master, so give the "
               "devices of both to one line";
    QTest::newRow("duplicate line names") << stationJson({line("a"), line("b"), line("a")})
                                          << "lines[2] (a): the line name 'a' is used by lines[0] too";
    QTest::newRow("a name equal to a default name") << stationJson({line("line2"), "\"port\": \"/dev/ttyS1\""})
                                                    << "lines[1] (line2): the line name 'line2' is used by lines[0] too";
    QTest::newRow("name with a space") << stationJson({line("cabinet a")}) << "lines[0]: " + nameRule + "'cabinet a'";
    QTest::newRow("name with a slash") << stationJson({line("a/b")}) << "lines[0]: " + nameRule + "'a/b'";
    QTest::newRow("name of 33 characters") << stationJson({line(QByteArray(33, 'x'))})
                                           << "lines[0]: " + nameRule + "'" + QString(33, 'x') + "'";
    QTest::newRow("empty name") << stationJson({line("")}) << "lines[0]: " + nameRule + "''";
    QTest::newRow("name no text") << stationJson({"\"name\": 7, \"port\": \"/dev/ttyS0\""})
                                  << "lines[0]: 'name' must be a string, not 7";
    QTest::newRow("unknown family") << stationJson({line("a", "\"devices\": [\"ipc400@1\"]")})
                                    << "lines[0] (a): 'devices': 'ipc400@1': unknown family 'ipc400' "
                                       "(families: dtron300, ipc300, quantrol, tya200)";
    QTest::newRow("address 0") << stationJson({line("a", "\"devices\": [\"ipc300@0\"]")})
                               << "lines[0] (a): 'devices': 'ipc300@0': the address must be 1..247, not 0";
    QTest::newRow("address 248") << stationJson({line("a", "\"devices\": [\"ipc300@248\"]")})
                                 << "lines[0] (a): 'devices': 'ipc300@248': the address must be 1..247, not 248";
    QTest::newRow("not a device") << stationJson({line("a", "\"devices\": [\"ipc300-1\"]")})
                                  << "lines[0] (a): 'devices': 'ipc300-1' is not a device: use FAMILY@ADDRESS, e.g. ipc300@1";
    QTest::newRow("a line given in a device") << stationJson({line("a", "\"devices\": [\"a/ipc300@1\"]")})
                                              << "lines[0] (a): 'devices': 'a/ipc300@1' is not a device: use "
                                                 "FAMILY@ADDRESS, e.g. ipc300@1";
    QTest::newRow("devices no array") << stationJson({line("a", "\"devices\": \"ipc300@1\"")})
                                      << "lines[0] (a): 'devices' must be an array of \"FAMILY@ADDRESS\" texts, e.g. "
                                         "\"ipc300@1\"";
    QTest::newRow("duplicate address on one line")
            << stationJson({line("a", "\"devices\": [\"ipc300@1\", \"tya200@2\", \"tya200@1\"]")})
            << "lines[0] (a): 'devices': address 1 is used twice on the line (ipc300@1, tya200@1)";
    QTest::newRow("one device twice") << stationJson({line("a", "\"devices\": [\"ipc300@4\", \"ipc300@4\"]")})
                                      << "lines[0] (a): 'devices': address 4 is used twice on the line (ipc300@4, ipc300@4)";
    QTest::newRow("bad baud") << stationJson({line("a", "\"baud\": 1200")})
                              << "lines[0] (a): 'baud' must be 4800, 9600, 19200 or 38400, not 1200";
    QTest::newRow("baud as text") << stationJson({line("a", "\"baud\": \"9600\"")})
                                  << "lines[0] (a): 'baud' must be 4800, 9600, 19200 or 38400, not 9600";
    QTest::newRow("bad format") << stationJson({line("a", "\"format\": \"7E1\"")})
                                << "lines[0] (a): 'format' must be 8N1, 8E1, 8O1 or 8N2, not 7E1";
    QTest::newRow("format no text") << stationJson({line("a", "\"format\": 8")})
                                    << "lines[0] (a): 'format' must be 8N1, 8E1, 8O1 or 8N2, not 8";
    QTest::newRow("timeout below 10 ms") << stationJson({line("a", "\"timeout_ms\": 5")})
                                         << "lines[0] (a): 'timeout_ms' must be 0 (derived from the baud rate and the "
                                            "families) or 10..60000 ms, not 5";
    QTest::newRow("timeout above 60 s") << stationJson({line("a", "\"timeout_ms\": 60001")})
                                        << "lines[0] (a): 'timeout_ms' must be a whole number 0..60000, not 60001";
    QTest::newRow("min response above 500") << stationJson({line("a", "\"min_response_ms\": 501")})
                                            << "lines[0] (a): 'min_response_ms' must be a whole number 0..500, not 501";
    QTest::newRow("retries 11") << stationJson({line("a", "\"retries\": 11")})
                                << "lines[0] (a): 'retries' must be a whole number 0..10, not 11";
    QTest::newRow("retries 1.5") << stationJson({line("a", "\"retries\": 1.5")})
                                 << "lines[0] (a): 'retries' must be a whole number 0..10, not 1.5";
    QTest::newRow("read_only as text") << stationJson({line("a", "\"read_only\": \"yes\"")})
                                       << "lines[0] (a): 'read_only' must be true or false, not yes";
}

void tst_StationConfig::refusesBadFiles()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    QString error;
    QVERIFY(!StationConfig::fromJson(json, registry(), &error));
    QCOMPARE(error, message);
}

void tst_StationConfig::namesEveryProblemAtOnce()
{
    QString error;
    QVERIFY(!StationConfig::fromJson(stationJson({line("a", "\"baud\": 1"), line("b", "\"devices\": [\"x@1\"]")}),
                                     registry(), &error));
    QCOMPARE(error.split('\n'),
             (QStringList{"lines[0] (a): 'baud' must be 4800, 9600, 19200 or 38400, not 1",
                          "lines[1] (b): 'devices': 'x@1': unknown family 'x' (families: dtron300, ipc300, quantrol, "
                          "tya200)"}));
}

void tst_StationConfig::loadNamesTheFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("hall.json");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(stationJson({line("a"), line("b", "\"baud\": 1200")}));
    file.close();
    QString error;
    QVERIFY(!StationConfig::load(path, registry(), &error));
    QCOMPARE(error, path + ": lines[1] (b): 'baud' must be 4800, 9600, 19200 or 38400, not 1200");
}

void tst_StationConfig::loadRefusesWhatIsNoFile()
{
    QTemporaryDir dir;
    QString error;
    QVERIFY(!StationConfig::load(dir.filePath("missing.json"), registry(), &error));
    QCOMPARE(error, dir.filePath("missing.json") + ": No such file or directory");
    QVERIFY(!StationConfig::load(dir.path(), registry(), &error));
    QCOMPARE(error, dir.path() + ": not a regular file");
    QFile big(dir.filePath("big.json"));
    QVERIFY(big.open(QIODevice::WriteOnly));
    big.write(QByteArray(StationConfig::maxFileBytes + 1, ' '));
    big.close();
    QVERIFY(!StationConfig::load(big.fileName(), registry(), &error));
    QVERIFY2(error.startsWith(big.fileName() + ": too big"), qPrintable(error));
}

namespace {

StationConfig threeLines()
{
    StationConfig station;
    station.name = "hall-3";
    LineConfig a;
    a.name = "cabinet-a";
    a.settings.portName = "/dev/serial/by-id/usb-FTDI-if00-port0";
    a.settings.format = *LineFormat::parse(19200, "8E1");
    a.settings.timeoutMs = 250;
    a.settings.minimumResponseTimeMs = 20;
    a.settings.retries = 0;
    a.devices = {{"ipc300", 1}, {"tya200", 2}};
    LineConfig b;
    b.name = "gateway.1";
    b.settings.portName = "tcp://[::1]:1502";
    b.settings.format = *LineFormat::parse(4800, "8N2");
    b.settings.readOnly = true;
    b.devices = {{"dtron300", 5}, {"ipc300", 1}};
    LineConfig c;
    c.name = "hall_b";
    c.settings.portName = "rtu+tcp://10.0.0.21:4001";
    c.settings.format = *LineFormat::parse(38400, "8O1");
    station.lines = {a, b, c};
    return station;
}

void compareStations(const StationConfig &back, const StationConfig &station)
{
    QCOMPARE(back.name, station.name);
    QCOMPARE(back.lines.size(), station.lines.size());
    for (qsizetype i = 0; i < station.lines.size(); ++i) {
        const LineConfig &x = back.lines[i];
        const LineConfig &y = station.lines[i];
        QCOMPARE(x.name, y.name);
        QCOMPARE(x.settings.portName, y.settings.portName);
        QCOMPARE(x.settings.format.baudRate, y.settings.format.baudRate);
        QCOMPARE(x.settings.format.parity, y.settings.format.parity);
        QCOMPARE(x.settings.format.stopBits, y.settings.format.stopBits);
        QCOMPARE(x.settings.timeoutMs, y.settings.timeoutMs);
        QCOMPARE(x.settings.minimumResponseTimeMs, y.settings.minimumResponseTimeMs);
        QCOMPARE(x.settings.retries, y.settings.retries);
        QCOMPARE(x.settings.readOnly, y.settings.readOnly);
        QCOMPARE(x.devices, y.devices);
    }
}

} // namespace

void tst_StationConfig::roundTrip()
{
    const StationConfig station = threeLines();
    QTemporaryDir dir;
    const QString path = dir.filePath("station.json");
    QString error;
    QVERIFY2(station.save(path, &error), qPrintable(error));
    const auto back = StationConfig::load(path, registry(), &error);
    QVERIFY2(back, qPrintable(error));
    compareStations(*back, station);
    QCOMPARE(back->toJson(), station.toJson());
}

void tst_StationConfig::writesKeysInReadingOrder()
{
    StationConfig station;
    station.name = "s";
    LineConfig a;
    a.name = "a";
    a.settings.portName = "/dev/ttyS0";
    a.settings.format = *LineFormat::parse(9600, "8N1");
    a.devices = {{"ipc300", 1}, {"tya200", 2}};
    station.lines = {a};
    QCOMPARE(station.toJson(), QByteArray("{\n"
                                          "    \"format\": \"jumo-station\",\n"
                                          "    \"version\": 1,\n"
                                          "    \"name\": \"s\",\n"
                                          "    \"lines\": [\n"
                                          "        {\n"
                                          "            \"name\": \"a\",\n"
                                          "            \"port\": \"/dev/ttyS0\",\n"
                                          "            \"baud\": 9600,\n"
                                          "            \"format\": \"8N1\",\n"
                                          "            \"timeout_ms\": 0,\n"
                                          "            \"min_response_ms\": 0,\n"
                                          "            \"retries\": 2,\n"
                                          "            \"read_only\": false,\n"
                                          "            \"devices\": [\"ipc300@1\",\"tya200@2\"]\n"
                                          "        }\n"
                                          "    ]\n"
                                          "}\n"));
    station.lines.clear();
    QString error;
    const auto empty = StationConfig::fromJson(station.toJson(), registry(), &error);
    QVERIFY2(empty, qPrintable(error));
    QVERIFY(empty->lines.isEmpty());
}

void tst_StationConfig::fullDiskKeepsTheOldFile()
{
    SmallDisk disk;
    if (!disk.mount(64))
        QSKIP("no small tmpfs can be mounted here (needs root)");
    const QString path = disk.filePath("station.json");
    StationConfig station = threeLines();
    QString error;
    QVERIFY2(station.save(path, &error), qPrintable(error));
    const QByteArray before = station.toJson();
    disk.fill();
    station.lines.removeLast();
    station.name = "changed";
    QVERIFY(!station.save(path, &error));
    QCOMPARE(error, "cannot write " + path + ": No space left on device");
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), before);
    QCOMPARE(QDir(disk.path()).entryList(QDir::Files), (QStringList{"filler", "station.json"}));   // no temporary left
    disk.free();
    QVERIFY2(station.save(path, &error), qPrintable(error));
    const auto back = StationConfig::load(path, registry(), &error);
    QVERIFY2(back, qPrintable(error));
    QCOMPARE(back->name, "changed");
}

void tst_StationConfig::lineSpecs_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("port");
    QTest::addColumn<int>("baud");
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("timeout");
    QTest::addColumn<int>("minResponse");
    QTest::addColumn<int>("retries");
    QTest::addColumn<bool>("readOnly");
    QTest::newRow("a port alone takes the defaults") << "/dev/ttyUSB0" << "" << "/dev/ttyUSB0" << 9600 << "8N1" << 0 << 0
                                                     << 2 << false;
    QTest::newRow("every option") << "/dev/ttyUSB1,name=cab-a,baud=19200,format=8E1,timeout=250,min-response=20,"
                                     "retries=0,read-only"
                                  << "cab-a" << "/dev/ttyUSB1" << 19200 << "8E1" << 250 << 20 << 0 << true;
    QTest::newRow("a gateway URL") << "tcp://[::1]:1502,name=gw" << "gw" << "tcp://[::1]:1502" << 9600 << "8N1" << 0 << 0
                                   << 2 << false;
    QTest::newRow("format in lower case") << "/dev/ttyS0,format=8o1" << "" << "/dev/ttyS0" << 9600 << "8O1" << 0 << 0 << 2
                                          << false;
    QTest::newRow("timeout 0 is derived") << "/dev/ttyS0,timeout=0" << "" << "/dev/ttyS0" << 9600 << "8N1" << 0 << 0 << 2
                                          << false;
}

void tst_StationConfig::lineSpecs()
{
    QFETCH(QString, spec);
    QString error;
    const auto line = StationConfig::parseLineSpec(spec, &error);
    QVERIFY2(line, qPrintable(error));
    QTEST(line->name, "name");
    QTEST(line->settings.portName, "port");
    QTEST(line->settings.format.baudRate, "baud");
    QTEST(line->settings.format.formatName(), "format");
    QTEST(line->settings.timeoutMs, "timeout");
    QTEST(line->settings.minimumResponseTimeMs, "minResponse");
    QTEST(line->settings.retries, "retries");
    QTEST(line->settings.readOnly, "readOnly");
}

void tst_StationConfig::lineSpecRefusals_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << "" << "--line '': the line address (serial port or URL) is empty";
    QTest::newRow("options without an address") << ",baud=9600"
                                                << "--line ',baud=9600': the line address (serial port or URL) is empty";
    QTest::newRow("bad baud") << "/dev/ttyS0,baud=1200"
                              << "--line '/dev/ttyS0,baud=1200': 'baud' must be 4800, 9600, 19200 or 38400, not 1200";
    QTest::newRow("bad format") << "/dev/ttyS0,format=7E1"
                                << "--line '/dev/ttyS0,format=7E1': 'format' must be 8N1, 8E1, 8O1 or 8N2, not 7E1";
    QTest::newRow("bad name") << "/dev/ttyS0,name=a/b" << "--line '/dev/ttyS0,name=a/b': " + nameRule + "'a/b'";
    QTest::newRow("empty name") << "/dev/ttyS0,name=" << "--line '/dev/ttyS0,name=': " + nameRule + "''";
    QTest::newRow("unknown option") << "/dev/ttyS0,parity=E"
                                    << "--line '/dev/ttyS0,parity=E': unknown option 'parity=E' (ADDRESS[,name=NAME]"
                                       "[,baud=N][,format=8N1][,timeout=MS][,min-response=MS][,retries=N][,read-only])";
    QTest::newRow("an option without a value") << "/dev/ttyS0,baud"
                                               << "--line '/dev/ttyS0,baud': unknown option 'baud' (ADDRESS[,name=NAME]"
                                                  "[,baud=N][,format=8N1][,timeout=MS][,min-response=MS][,retries=N]"
                                                  "[,read-only])";
    QTest::newRow("an option twice") << "/dev/ttyS0,baud=9600,baud=19200"
                                     << "--line '/dev/ttyS0,baud=9600,baud=19200': 'baud' is given twice";
    QTest::newRow("retries no number") << "/dev/ttyS0,retries=x"
                                       << "--line '/dev/ttyS0,retries=x': 'retries' must be a whole number 0..10, not 'x'";
    QTest::newRow("timeout below 10 ms") << "/dev/ttyS0,timeout=5"
                                         << "--line '/dev/ttyS0,timeout=5': 'timeout' must be 0 (derived from the baud "
                                            "rate and the families) or 10..60000 ms, not 5";
    QTest::newRow("min-response above 500") << "/dev/ttyS0,min-response=600"
                                            << "--line '/dev/ttyS0,min-response=600': 'min-response' must be a whole "
                                               "number 0..500, not '600'";
    QTest::newRow("read-only with a value") << "/dev/ttyS0,read-only=no"
                                            << "--line '/dev/ttyS0,read-only=no': 'read-only' takes no value";
    QTest::newRow("two problems") << "/dev/ttyS0,baud=1,format=x"
                                  << "--line '/dev/ttyS0,baud=1,format=x': 'baud' must be 4800, 9600, 19200 or 38400, "
                                     "not 1; 'format' must be 8N1, 8E1, 8O1 or 8N2, not x";
}

void tst_StationConfig::lineSpecRefusals()
{
    QFETCH(QString, spec);
    QFETCH(QString, message);
    QString error;
    QVERIFY(!StationConfig::parseLineSpec(spec, &error));
    QCOMPARE(error, message);
}

void tst_StationConfig::lineSpecTakesDefaults()
{
    BusSettings defaults;
    defaults.format = *LineFormat::parse(19200, "8E1");
    defaults.retries = 5;
    defaults.readOnly = true;
    QString error;
    const auto line = StationConfig::parseLineSpec("/dev/ttyS3,format=8N2", defaults, &error);
    QVERIFY2(line, qPrintable(error));
    QCOMPARE(line->settings.format.baudRate, 19200);
    QCOMPARE(line->settings.format.formatName(), "8N2");
    QCOMPARE(line->settings.retries, 5);
    QVERIFY(line->settings.readOnly);
}

void tst_StationConfig::fromLinesNamesLinesByPosition()
{
    QString error;
    QList<LineConfig> lines;
    for (const QString &spec : QStringList{"/dev/ttyS0", "/dev/ttyS1,name=b", "/dev/ttyS2"})
        lines << *StationConfig::parseLineSpec(spec, &error);
    const auto station = StationConfig::fromLines(lines, &error);
    QVERIFY2(station, qPrintable(error));
    QCOMPARE(station->lines[0].name, "line1");
    QCOMPARE(station->lines[1].name, "b");
    QCOMPARE(station->lines[2].name, "line3");
    QCOMPARE(station->lineIndex("line3"), 2);
    QCOMPARE(station->lineIndex("line2"), -1);
}

void tst_StationConfig::fromLinesRefuses_data()
{
    QTest::addColumn<QStringList>("specs");
    QTest::addColumn<QString>("message");
    QTest::newRow("a name twice") << QStringList{"/dev/ttyS0,name=a", "/dev/ttyS1,name=a"}
                                  << "lines[1] (a): the line name 'a' is used by lines[0] too";
    QTest::newRow("a name that is another's default") << QStringList{"/dev/ttyS0", "/dev/ttyS1,name=line1"}
                                                      << "lines[1] (line1): the line name 'line1' is used by lines[0] too";
    QTest::newRow("one serial port twice")
            << QStringList{"/dev/ttyS0,name=a", "/dev/ttyS1,name=b", "/dev/../dev/ttyS0,name=c"}
            << "lines[2] (c): 'port' /dev/../dev/ttyS0 is the port of lines[0] (a) too: a line has one master, so "
               "give the devices of both to one line";
    QTest::newRow("one device server twice")
            << QStringList{"rtu+tcp://Server.local:4001,name=a", "rtu+tcp://server.local:4001,name=b"}
            << "lines[1] (b): 'port' rtu+tcp://server.local:4001 is the port of lines[0] (a) too: a line has one "
               "master, so give the devices of both to one line";
    // The same device server in other words: compared by what the addresses mean.
    QTest::newRow("one device server by address and as localhost")
            << QStringList{"rtu+tcp://127.0.0.1:4001,name=a", "rtu+tcp://localhost:4001,name=b"}
            << "lines[1] (b): 'port' rtu+tcp://localhost:4001 is the port of lines[0] (a) too: a line has one "
               "master, so give the devices of both to one line";
    QTest::newRow("one device server as an IPv4-mapped IPv6 address")
            << QStringList{"rtu+tcp://127.0.0.1:4001,name=a", "rtu+tcp://[::ffff:127.0.0.1]:4001,name=b"}
            << "lines[1] (b): 'port' rtu+tcp://[::ffff:127.0.0.1]:4001 is the port of lines[0] (a) too: a line has "
               "one master, so give the devices of both to one line";
    QTest::newRow("one device server in two IPv6 spellings")
            << QStringList{"rtu+tcp://[2001:db8::7]:950,name=a", "rtu+tcp://[2001:DB8:0:0:0:0:0:7]:950,name=b"}
            << "lines[1] (b): 'port' rtu+tcp://[2001:DB8:0:0:0:0:0:7]:950 is the port of lines[0] (a) too: a line has "
               "one master, so give the devices of both to one line";
    QTest::newRow("localhost and the IPv6 loopback")
            << QStringList{"rtu+tcp://[::1]:4001,name=a", "/dev/ttyS0,name=b", "rtu+tcp://LOCALHOST:4001,name=c"}
            << "lines[2] (c): 'port' rtu+tcp://LOCALHOST:4001 is the port of lines[0] (a) too: a line has one "
               "master, so give the devices of both to one line";
}

void tst_StationConfig::fromLinesAcceptsDistinctMasters_data()
{
    QTest::addColumn<QStringList>("specs");
    QTest::newRow("one device server, two ports") << QStringList{"rtu+tcp://127.0.0.1:4001", "rtu+tcp://127.0.0.1:4002"};
    QTest::newRow("two loopback addresses") << QStringList{"rtu+tcp://127.0.0.1:4001", "rtu+tcp://127.0.0.2:4001"};
    QTest::newRow("IPv4 and IPv6 loopback") << QStringList{"rtu+tcp://127.0.0.1:4001", "rtu+tcp://[::1]:4001"};
    // A gateway orders the connections it has.
    QTest::newRow("one gateway twice") << QStringList{"tcp://127.0.0.1:1502", "tcp://localhost:1502"};
    QTest::newRow("a gateway and a device server on one port")
            << QStringList{"tcp://127.0.0.1:1502", "rtu+tcp://127.0.0.1:1502"};
}

void tst_StationConfig::fromLinesAcceptsDistinctMasters()
{
    QFETCH(QStringList, specs);
    QString error;
    QList<LineConfig> lines;
    for (const QString &spec : specs)
        lines << *StationConfig::parseLineSpec(spec, &error);
    QVERIFY2(StationConfig::fromLines(lines, &error), qPrintable(error));
}

void tst_StationConfig::fromLinesRefuses()
{
    QFETCH(QStringList, specs);
    QFETCH(QString, message);
    QString error;
    QList<LineConfig> lines;
    for (const QString &spec : specs)
        lines << *StationConfig::parseLineSpec(spec, &error);
    QVERIFY(!StationConfig::fromLines(lines, &error));
    QCOMPARE(error, message);
    // Devices given twice at one address on one line, too.
    lines = {LineConfig{"a", {}, {{"ipc300", 3}, {"tya200", 3}}}};
    QVERIFY(!StationConfig::fromLines(lines, &error));
    QCOMPARE(error, "lines[0] (a): address 3 is used twice on the line (ipc300@3, tya200@3)");
}

void tst_StationConfig::deviceNames()
{
    StationConfig station = threeLines();
    const DeviceSpec device{"ipc300", 1};
    QCOMPARE(device.name(), "ipc300@1");
    QCOMPARE(station.deviceName(1, device), "gateway.1/ipc300@1");
    QCOMPARE(StationConfig::qualifiedName("hall_b", device), "hall_b/ipc300@1");
    station.lines.resize(1);
    QCOMPARE(station.deviceName(0, device), "ipc300@1");
}

void tst_StationConfig::resolveDevice_data()
{
    QTest::addColumn<int>("lineCount");
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("line");   // -1: refused with the message
    QTest::addColumn<QString>("message");
    QTest::newRow("plain name on one line") << 1 << "ipc300@7" << 0 << "";
    QTest::newRow("line named on one line") << 1 << "cabinet-a/ipc300@7" << 0 << "";
    QTest::newRow("line named among three") << 3 << "hall_b/ipc300@1" << 2 << "";
    QTest::newRow("a device not listed in its line") << 3 << "gateway.1/tya200@200" << 1 << "";
    QTest::newRow("ambiguous among three") << 3 << "ipc300@1" << -1
                                           << "'ipc300@1': which line? The station has the lines cabinet-a, gateway.1, "
                                              "hall_b: name it as LINE/ipc300@1, e.g. cabinet-a/ipc300@1";
    QTest::newRow("unknown line") << 3 << "cabinet-b/ipc300@1" << -1
                                  << "'cabinet-b/ipc300@1': there is no line 'cabinet-b' (lines: cabinet-a, gateway.1, "
                                     "hall_b)";
    QTest::newRow("empty line name") << 3 << "/ipc300@1" << -1
                                     << "'/ipc300@1': there is no line '' (lines: cabinet-a, gateway.1, hall_b)";
    QTest::newRow("unknown family") << 3 << "hall_b/foo@1" << -1
                                    << "'foo@1': unknown family 'foo' (families: dtron300, ipc300, quantrol, tya200)";
    QTest::newRow("address out of range") << 1 << "ipc300@255" << -1 << "'ipc300@255': the address must be 1..247, not 255";
    QTest::newRow("two slashes") << 3 << "hall_b/x/ipc300@1" << -1
                                 << "'x/ipc300@1' is not a device: use FAMILY@ADDRESS, e.g. ipc300@1";
}

void tst_StationConfig::resolveDevice()
{
    QFETCH(int, lineCount);
    QFETCH(QString, text);
    QFETCH(int, line);
    QFETCH(QString, message);
    StationConfig station = threeLines();
    station.lines.resize(lineCount);
    QString error;
    const std::optional<StationDevice> found = station.resolveDevice(text, registry(), &error);
    if (line < 0) {
        QVERIFY(!found);
        QCOMPARE(error, message);
        return;
    }
    QVERIFY2(found, qPrintable(error));
    QCOMPARE(found->line, qsizetype(line));
    QCOMPARE(found->device.name(), text.section('/', -1));
}

QTEST_GUILESS_MAIN(tst_StationConfig)
#include "tst_stationconfig.moc"
