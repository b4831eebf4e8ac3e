// jumoctl's map commands, run in-process and as the real executable: the CSV contract
// scripts rely on, --help for every command, non-zero exits with a reason on stderr, the
// port list by by-id names, and the one version of the project.
#include "clirun.h"
#include "commissioning/parameterset.h"
#include "protocol/filesaver.h"
#include "jumoversion.h"
#include "protocol/familyregistry.h"
#include "mapcommands.h"
#include "systemsettings.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

using namespace jumo;
using namespace jumo::test;

namespace {

// Splits one CSV line, honouring quoted fields with commas and doubled quotes.
QStringList splitCsv(const QString &line)
{
    QStringList fields{QString()};
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
            fields.last() += '"';
            ++i;
        } else if (c == '"') {
            quoted = !quoted;
        } else if (c == ',' && !quoted) {
            fields << QString();
        } else {
            fields.last() += c;
        }
    }
    return fields;
}


} // namespace

class tst_Jumoctl : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void mapCsvContract_data();
    void mapCsvContract();
    void mapJson();
    void planListsRequests();
    void decodeShowsErrorValues();
    void helpForEveryCommand_data();
    void helpForEveryCommand();
    void badArguments_data();
    void badArguments();
    void realExecutableExitCodes();
    void helpAllIsHelp_data();
    void helpAllIsHelp();
    void diffOfTwoFilesChecksBoth_data();
    void diffOfTwoFilesChecksBoth();
    void simulatorRefusesBadNumbers();
    void portsByTheirStableNames();
    void versionIsTheProjectVersion();
    void mapShowsTheDefaults();
    void closedOutputIsSaid();
    void noHomeNoWrites();
    void systemSettingsFailClosed_data();
    void systemSettingsFailClosed();
};

void tst_Jumoctl::initTestCase()
{
    qputenv("JUMO_MAP_PATH", "");
    qputenv("XDG_DATA_HOME", QByteArray(QDir::tempPath().toUtf8() + "/jumo-test-no-maps"));
}

void tst_Jumoctl::mapCsvContract_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QString>("row");   // one row that must appear exactly
    QTest::newRow("ipc300 register") << "ipc300" << "0x00B1,,load_current,Load current,float,2,R,,A,5.2.1 RMS measured values,";
    QTest::newRow("ipc300 bit") << "ipc300" << "0x00ED,15,malfunction_signal_1.bus_error,Bus error,bool,1,R,,,5.2.6 Binary signals,alarm";
    QTest::newRow("quantrol activation bit") << "quantrol" << "0x0025,15,binary_output_control.activation,";
    QTest::newRow("dtron300 long") << "dtron300" << "0x005B,,program_run_time,";
    QTest::newRow("tya200 setpoint") << "tya200" << "0x010A,,setpoint,";
    QTest::newRow("ipc300 load voltage: unit and precision")
            << "ipc300" << "0x00AF,,load_voltage,Load voltage,float,2,R,,V,5.2.1 RMS measured values,,decimals:1";
    QTest::newRow("dtron300 process value: unit set on the device")
            << "dtron300" << "0x0043,,filtered_process_value,Filtered process value,float,2,R,,,5.1 Process data,unit configured on the device: process_value,decimals:1";
}

void tst_Jumoctl::mapCsvContract()
{
    QFETCH(QString, family);
    QFETCH(QString, row);
    const Run r = run({"map", family, "--csv"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.err.isEmpty(), qPrintable(r.err));
    const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.first(), QString("address,bit,id,label,type,words,access,storage,unit,group,notes,precision,default"));
    bool found = false;
    for (const QString &line : lines)
        found |= line.startsWith(row);
    QVERIFY2(found, qPrintable(row));

    // One row per register and one per bit, every address in the 0x + 4 hex digit form.
    const auto map = FamilyRegistry::load({}, true).family(family);
    int expected = 1;
    for (const RegisterEntry &e : map->entries())
        expected += 1 + int(e.bits.size());
    QCOMPARE(lines.size(), expected);
    static const QRegularExpression address("^0x[0-9A-F]{4},");
    static const QStringList types{"float", "int16", "uint16", "int32", "uint32", "bool", "enum", "bitfield", "text"};
    for (qsizetype i = 1; i < lines.size(); ++i) {
        QVERIFY2(address.match(lines[i]).hasMatch(), qPrintable(lines[i]));
        const QStringList fields = splitCsv(lines[i]);
        QCOMPARE(fields.size(), 13);
        QVERIFY2(types.contains(fields[4]), qPrintable(lines[i]));
        // Every float shows its display precision, nothing else has one.
        static const QRegularExpression precision("^(decimals:[0-6]|significant:[1-7])$");
        if (fields[4] == "float")
            QVERIFY2(precision.match(fields[11]).hasMatch(), qPrintable(lines[i]));
        else
            QVERIFY2(fields[11].isEmpty(), qPrintable(lines[i]));
        QVERIFY2(QStringList({"R", "W", "RW"}).contains(fields[6]), qPrintable(lines[i]));
    }
}

void tst_Jumoctl::mapJson()
{
    const Run r = run({"map", "tya200", "--json"});
    QCOMPARE(r.code, 0);
    const QJsonObject root = QJsonDocument::fromJson(r.out.toUtf8()).object();
    QCOMPARE(root.value("family").toString(), QString("tya200"));
    QCOMPARE(root.value("protocol").toObject().value("maxReadWords").toInt(), 127);
    QVERIFY(root.value("entries").toArray().size() > 100);
    QCOMPARE(root.value("exceptions").toObject().value("6").toString().isEmpty(), false);
    // Names for lists, units set on the device, and each float's display precision.
    QCOMPARE(root.value("shortName").toString(), QString("TYA 200"));
    QVERIFY(root.value("configuredUnits").toObject().value("monitored").toString().contains("V, A, W"));
    QJsonObject current, alarmLimit;
    for (const QJsonValue &e : root.value("entries").toArray()) {
        if (e.toObject().value("id") == QString("load_current"))
            current = e.toObject();
        if (e.toObject().value("id") == QString("alarm_min_limit"))
            alarmLimit = e.toObject();
    }
    QCOMPARE(current.value("unit").toString(), QString("A"));
    QCOMPARE(current.value("significantDigits").toInt(), 4);
    QVERIFY(!current.contains("decimals"));
    QCOMPARE(alarmLimit.value("configuredUnit").toString(), QString("monitored"));
    QCOMPARE(alarmLimit.value("decimals").toInt(), 1);
}

void tst_Jumoctl::planListsRequests()
{
    const Run r = run({"plan", "ipc300", "load_voltage", "load_current"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("read 0x00AF..0x00B2 (4 words): load_voltage, load_current"), qPrintable(r.out));
    QVERIFY(r.out.contains("1 requests") || r.out.contains("1 request"));
}

void tst_Jumoctl::decodeShowsErrorValues()
{
    Run r = run({"decode", "ipc300", "load_current", "70A3", "4145"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.out.trimmed(), QString("load_current (0x00B1) = 12.34 A [ok]"));
    r = run({"decode", "ipc300", "load_current", "0x0000", "0x7F80"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("= Overrange [overrange]"), qPrintable(r.out));
    QVERIFY2(!r.out.contains("inf"), qPrintable(r.out));
    r = run({"decode", "dtron300", "program_run_time", "0001", "0203"});
    QCOMPARE(r.out.trimmed(), QString("program_run_time (0x005B) = 66051 s [ok]"));
}

void tst_Jumoctl::helpForEveryCommand_data()
{
    QTest::addColumn<QString>("command");
    for (const char *c : {"families", "map", "plan", "decode", "ports", "history"})
        QTest::newRow(c) << c;
}

void tst_Jumoctl::helpForEveryCommand()
{
    QFETCH(QString, command);
    const Run r = run({command, "--help"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.startsWith("Usage: jumoctl " + command), qPrintable(r.out));
}

void tst_Jumoctl::badArguments_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("message");
    QTest::newRow("no command") << QStringList{} << 2 << "Usage: jumoctl";
    QTest::newRow("unknown command") << QStringList{"frobnicate"} << 2 << "unknown command 'frobnicate'";
    QTest::newRow("unknown family") << QStringList{"map", "ipc400", "--csv"} << 1 << "unknown family 'ipc400'";
    QTest::newRow("map without format") << QStringList{"map", "ipc300"} << 2 << "exactly one of --csv and --json";
    QTest::newRow("unknown option") << QStringList{"map", "ipc300", "--xml"} << 2 << "Unknown option 'xml'";
    QTest::newRow("decode wrong word count") << QStringList{"decode", "ipc300", "load_current", "70A3"} << 2
                                             << "takes 2 words, 1 given";
    QTest::newRow("decode not hex") << QStringList{"decode", "ipc300", "load_current", "70A3", "zz"} << 2
                                    << "'zz' is not a 16-bit hex word";
    QTest::newRow("decode unknown id") << QStringList{"decode", "ipc300", "load_currant", "0"} << 1
                                       << "'load_currant' is not an entry of ipc300";
    QTest::newRow("plan of unknown id") << QStringList{"plan", "quantrol", "nothing"} << 1 << "'nothing' is not an entry";
    QTest::newRow("plan of write-only") << QStringList{"plan", "quantrol", "controller_functions"} << 1 << "write-only";
    QTest::newRow("decode hex prefix twice") << QStringList{"decode", "quantrol", "controller_status", "0x0x7F"} << 2
                                             << "'0x0x7F' is not a 16-bit hex word";
    // Refused before any line is opened (the port does not exist).
    const QStringList noLine{"--port", "/nonexistent/tty"};
    QTest::newRow("address outside the family") << QStringList{"read", "dtron300@255", "setpoint"} + noLine << 2
                                                << "a dtron300 cannot have address 255: its addresses are 1..254";
    QTest::newRow("one id written twice") << QStringList{"write", "dtron300@4", "setpoint_w2=1", "setpoint_w2=2"} + noLine
                                          << 2 << "'setpoint_w2' is given twice";
    QTest::newRow("bits of nothing") << QStringList{"write", "dtron300@4", "controller_functions=+"} + noLine << 2
                                     << "is not a bit of";
    QTest::newRow("hex with a sign") << QStringList{"write", "dtron300@4", "manual_output=0x-1"} + noLine << 2
                                     << "'0x-1' is not a whole number";
    QTest::newRow("broadcast without a clear line") << QStringList{"write", "dtron300@0", "setpoint_w2=1", "--verify", "4"}
                                                           + noLine
                                                    << 2 << "give --scan-first";
}

void tst_Jumoctl::badArguments()
{
    QFETCH(QStringList, args);
    QFETCH(int, code);
    QFETCH(QString, message);
    const Run r = run(args);
    QCOMPARE(r.code, code);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
}

void tst_Jumoctl::realExecutableExitCodes()
{
    const QString exe = QStringLiteral(JUMOCTL_PATH);
    QProcess p;
    p.start(exe, {"map", "quantrol", "--csv"});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 0);
    QVERIFY(p.readAllStandardOutput().startsWith("address,bit,id,"));
    p.start(exe, {"map", "nope", "--csv"});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 1);
    QVERIFY(p.readAllStandardError().contains("unknown family 'nope'"));
    // Output into a full disk is a failure, not a short file and exit code 0.
    p.setStandardOutputFile("/dev/full");
    p.start(exe, {"map", "quantrol", "--csv"});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 1);
    const QByteArray err = p.readAllStandardError();
    QVERIFY2(err.contains("jumoctl: the output could not be written: No space left on device"), err.constData());
}

void tst_Jumoctl::helpAllIsHelp_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("start");
    QTest::newRow("jumoctl") << QStringList{"--help-all"} << "Usage: jumoctl COMMAND";
    QTest::newRow("read") << QStringList{"read", "--help-all"} << "Usage: jumoctl read [options]";
    QTest::newRow("map") << QStringList{"map", "--help-all"} << "Usage: jumoctl map [options]";
}

void tst_Jumoctl::helpAllIsHelp()
{
    QFETCH(QStringList, args);
    QFETCH(QString, start);
    const Run r = run(args);
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.startsWith(start), qPrintable(r.out + r.err));
}

void tst_Jumoctl::diffOfTwoFilesChecksBoth_data()
{
    QTest::addColumn<QString>("id");
    QTest::addColumn<QString>("value");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("message");
    QTest::newRow("the same") << "setpoint_w2" << "120" << 0 << "no differences";
    QTest::newRow("zero and negative zero") << "setpoint_w3" << "-0" << 0 << "no differences";
    QTest::newRow("a difference") << "setpoint_w2" << "121" << 1 << "1 parameter(s) differ";
    QTest::newRow("unknown id") << "setpoint_w9" << "1" << 2 << "'setpoint_w9' in the file is no parameter of dtron300";
    QTest::newRow("not a parameter") << "filtered_process_value" << "1" << 2
                                     << "'filtered_process_value' in the file is no parameter of dtron300";
    QTest::newRow("not a value") << "setpoint_w2" << "abc" << 2 << "'setpoint_w2' in the file: 'abc' is not a number";
    QTest::newRow("largest float") << "setpoint_w2" << "3.40282347e+38" << 1 << "1 parameter(s) differ";
}

void tst_Jumoctl::diffOfTwoFilesChecksBoth()
{
    QFETCH(QString, id);
    QFETCH(QString, value);
    QFETCH(int, code);
    QFETCH(QString, message);
    // A file name with an '@' in it is still a file.
    QTemporaryDir dir;
    const QString first = dir.filePath("oven@line1.json");
    const QString second = dir.filePath("oven@line2.json");
    ParameterSet set;
    set.family = "dtron300";
    set.address = 4;
    set.values = {{"setpoint_w2", "120"}, {"setpoint_w3", "0"}};
    QString error;
    QVERIFY(FileSaver::save(first, set.toJson(), &error));
    set.values.insert(id, value);
    QVERIFY(FileSaver::save(second, set.toJson(), &error));
    for (const QStringList &order : {QStringList{first, second}, QStringList{second, first}}) {
        const Run r = run(QStringList{"diff"} + order);
        QCOMPARE(r.code, code);
        QVERIFY2((r.out + r.err).contains(message), qPrintable(r.out + r.err));
    }
}

void tst_Jumoctl::simulatorRefusesBadNumbers()
{
    QProcess p;
    p.start(QStringLiteral(JUMO_SIM_PATH), {"--delay", "abc", "--pty", QDir::tempPath(), "ipc300@1"});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 2);
    QVERIFY(p.readAllStandardError().contains("--delay must be 0..10000 ms"));
    // A setting the family's devices cannot have: a real one would never answer.
    QTemporaryDir dir;
    for (const QStringList &args : {QStringList{"--baud", "38400", "quantrol@3"},
                                     QStringList{"--baud", "19200", "--format", "8E1", "ipc300@1", "quantrol@3"}}) {
        p.start(QStringLiteral(JUMO_SIM_PATH), QStringList{"--pty", dir.path()} + args);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 2);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.contains("'quantrol@3': Quantrol devices cannot be set to ") && err.contains("(they support 9600, 19200 baud, 8N1)"),
                 qPrintable(err));
        QVERIFY(!QFile::exists(dir.filePath("master")));
    }
}

void tst_Jumoctl::portsByTheirStableNames()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir("by-id"));
    const QString device = dir.filePath("ttyUSB4");
    QVERIFY(QFile(device).open(QIODevice::WriteOnly));
    const QString link = dir.filePath("by-id/usb-Silicon_Labs_CP2102_0001-if00-port0");
    QVERIFY(QFile::link(device, link));
    qputenv("JUMO_SERIAL_BY_ID_DIR", QFile::encodeName(dir.filePath("by-id")));

    const Run json = run({"ports", "--json"});
    const Run text = run({"ports"});
    qunsetenv("JUMO_SERIAL_BY_ID_DIR");
    QCOMPARE(json.code, 0);
    QJsonObject port;
    for (const QJsonValue &value : QJsonDocument::fromJson(json.out.toUtf8()).array()) {
        if (value.toObject().value("port").toString() == link)
            port = value.toObject();
    }
    QVERIFY2(!port.isEmpty(), qPrintable(json.out));
    QCOMPARE(port.value("device").toString(), device);
    QCOMPARE(port.value("stable").toBool(), true);
    QCOMPARE(port.value("access").toString(), "ok");
    QVERIFY(port.value("message").isNull());
    QVERIFY(port.value("holders").toArray().isEmpty());
    for (const char *key : {"description", "manufacturer", "serial_number", "vendor_id", "product_id", "group"})
        QVERIFY2(port.contains(key), key);

    QCOMPARE(text.code, 0);
    QVERIFY2(text.out.contains(link + "\n  device now: " + device + "\n  access: ok\n"), qPrintable(text.out));
}

void tst_Jumoctl::versionIsTheProjectVersion()
{
    // The executable, as a user runs it: the version CMake's project() gives.
    QProcess p;
    p.start(QStringLiteral(JUMOCTL_PATH), {"--version"});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.readAllStandardOutput(), QByteArray("jumoctl " JUMO_VERSION "\n"));
    QVERIFY(QByteArray(JUMO_VERSION).count('.') == 2);
}

void tst_Jumoctl::mapShowsTheDefaults()
{
    // The manual's defaults, as the maps give them: a number, an enum's value, a boolean.
    Run r = run({"map", "ipc300", "--csv"});
    QCOMPARE(r.code, 0);
    QHash<QString, QStringList> rows;
    for (const QString &line : r.out.split('\n', Qt::SkipEmptyParts))
        rows.insert(splitCsv(line).value(2), splitCsv(line));
    const auto map = FamilyRegistry::load({}, true).family("ipc300");
    int withDefault = 0;
    for (const RegisterEntry &e : map->entries()) {
        const QString shown = rows.value(e.id).value(12);
        if (!e.defaultValue) {
            QVERIFY2(shown.isEmpty(), qPrintable(e.id));
            continue;
        }
        ++withDefault;
        if (e.type == ValueType::Bool)
            QCOMPARE(shown, QString(*e.defaultValue ? "true" : "false"));
        else
            QCOMPARE(shown.toDouble(), *e.defaultValue);
    }
    QVERIFY(withDefault >= 3);
    r = run({"map", "ipc300", "--json"});
    QCOMPARE(r.code, 0);
    int inJson = 0;
    for (const QJsonValue &v : QJsonDocument::fromJson(r.out.toUtf8()).object().value("entries").toArray()) {
        const QJsonObject o = v.toObject();
        const RegisterEntry *e = map->entry(o.value("id").toString());
        QCOMPARE(o.contains("default"), bool(e->defaultValue));
        if (!e->defaultValue)
            continue;
        ++inJson;
        if (e->type == ValueType::Bool)
            QCOMPARE(o.value("default").toBool(), *e->defaultValue != 0);
        else
            QCOMPARE(o.value("default").toDouble(), *e->defaultValue);
    }
    QCOMPARE(inJson, withDefault);
}

void tst_Jumoctl::closedOutputIsSaid()
{
    // jumoctl map ... | head, with head gone before anything is written: stdout is a
    // pipe without a reader. Said, and the exit code says so; no death by SIGPIPE.
    int ends[2];
    QCOMPARE(::pipe(ends), 0);
    ::close(ends[0]);
    const int writeEnd = ends[1];
    QProcess map;
    map.setChildProcessModifier([writeEnd] { ::dup2(writeEnd, STDOUT_FILENO); });
    map.start(QStringLiteral(JUMOCTL_PATH), {"map", "quantrol", "--csv"});
    QVERIFY(map.waitForFinished(30000));
    ::close(writeEnd);
    QCOMPARE(map.exitStatus(), QProcess::NormalExit);
    QCOMPARE(map.exitCode(), 141);
    const QByteArray err = map.readAllStandardError();
    QVERIFY2(err.contains("jumoctl: the output could not be written"), err.constData());
}

void tst_Jumoctl::noHomeNoWrites()
{
    // Without HOME (a service, a cron job) the audit log has no folder: a write is refused
    // before the line is opened, never kept in /.local/share/jumo.
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"HOME", "XDG_DATA_HOME", "JUMO_LOG_DIR"})
        env.remove(name);
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(JUMOCTL_PATH), {"write", "--port", "/nonexistent/ttyUSB9", "ipc300@1", "input_setpoint=10"});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 1);
    const QString err = QString::fromLocal8Bit(p.readAllStandardError());
    QVERIFY2(err.contains("no folder for the logs: neither JUMO_LOG_DIR, XDG_DATA_HOME nor HOME is set"), qPrintable(err));
    QVERIFY2(err.contains("nothing is written"), qPrintable(err));
    QVERIFY2(!err.contains("/nonexistent/ttyUSB9"), qPrintable(err));   // the line was never opened
    QVERIFY(!QFileInfo::exists("/.local/share/jumo"));
}

void tst_Jumoctl::systemSettingsFailClosed_data()
{
    QTest::addColumn<QByteArray>("file");       // jumo/jumo-hmi.conf; "FOLDER": a folder there
    QTest::addColumn<bool>("readOnly");
    QTest::addColumn<QString>("warning");       // empty: none
    QTest::newRow("no file") << QByteArray() << false << QString();
    QTest::newRow("readOnly=true") << QByteArray("[General]\nreadOnly=true\n") << true << QString();
    QTest::newRow("readOnly=false") << QByteArray("[General]\nreadOnly=false\n") << false << QString();
    QTest::newRow("lower case key") << QByteArray("[General]\nreadonly=true\n") << true << "'readonly' is taken as readOnly";
    QTest::newRow("capitalised key") << QByteArray("[General]\nReadOnly=true\n") << true << "'ReadOnly' is taken as readOnly";
    QTest::newRow("key with an underscore") << QByteArray("read_only=yes\n") << true << "'read_only' is taken as readOnly";
    QTest::newRow("value no boolean") << QByteArray("readOnly=ture\n") << true << "'readOnly=ture' is no true or false";
    QTest::newRow("in a section") << QByteArray("[hmi]\nreadOnly=1\n") << true << "'hmi/readOnly' is taken as readOnly";
    QTest::newRow("unknown key") << QByteArray("readOnly=false\ncolour=red\n") << false << "unknown key 'colour'";
    QTest::newRow("log rotation") << QByteArray("[logs]\nmaxFileMiB=8\nkeepFiles=3\n") << false << QString();
    QTest::newRow("a folder") << QByteArray("FOLDER") << true << "cannot be read (it is a folder)";
}

void tst_Jumoctl::systemSettingsFailClosed()
{
    QFETCH(QByteArray, file);
    QFETCH(bool, readOnly);
    QFETCH(QString, warning);
    QTemporaryDir config;
    // In-process, as XDG_CONFIG_DIRS is for a new process (QSettings reads it once).
    QSettings::setPath(QSettings::NativeFormat, QSettings::SystemScope, config.path());
    const QString path = config.filePath("jumo/jumo-hmi.conf");
    QCOMPARE(SystemSettings::fileName(), path);
    QVERIFY(QDir(config.path()).mkpath("jumo"));
    if (file == "FOLDER") {
        QVERIFY(QDir().mkpath(path));
    } else if (!file.isEmpty()) {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(file);
    }
    QCOMPARE(SystemSettings::readOnly(), readOnly);
    const QString warnings = SystemSettings::warnings().join('\n');
    if (warning.isEmpty())
        QVERIFY2(warnings.isEmpty(), qPrintable(warnings));
    else
        QVERIFY2(warnings.contains(warning) && warnings.contains(path), qPrintable(warnings));
}

QTEST_GUILESS_MAIN(tst_Jumoctl)
#include "tst_jumoctl.moc"
