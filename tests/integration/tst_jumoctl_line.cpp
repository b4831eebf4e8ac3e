// jumoctl on a real line: the commands run in-process (as the executable would) against
// the simulator over a pty pair, and the script contracts are checked field by field.
#include "clirun.h"
#include "testpeers.h"

#include <QFile>
#include <QJsonArray>
#include <QProcess>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QStandardPaths>
#include <QTest>

#include <csignal>
#include <sys/stat.h>

using namespace jumo;
using namespace jumo::test;

class tst_JumoctlLine : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void scanFindsEveryFamily();
    void quickScanFindsLateDevices();
    void thoroughScanSaysWhatItCosts();
    void dumpJsonContract();
    void writeIsConfirmed();
    void readOnlyWriteSendsNothing();
    void monitorJsonl();
    void monitorCsv();
    void monitorIntoAFullDiskStops();
    void monitorGoesOnWithoutASilentDevice();
    void monitorConfirmsADeviceThatAnswersLater();
    void monitorNamesAWrongDeviceAndGoesOn();
    void dumpStatusesAreTheDocumentedOnes();
    void diffOfAFileThatCannotBeComparedIsAProblem_data();
    void diffOfAFileThatCannotBeComparedIsAProblem();
    void absentDeviceIsATimeout();
    void badPortIsAClearError();
    void backupChangeDiffRestore();
    void restoreRefusesOtherFamilyAndVersion();
    void reportAsHtmlAndPdf();
    void reportIsADocumentToSign();
    void wrongFamilyIsRefused_data();
    void wrongFamilyIsRefused();
    void noIdentifyIsAudited();
    void broadcastNeedsALineOfOneFamily();
    void fullDiskKeepsThePreviousFiles();
    void auditFailureIsAFailure();
    void signalEndsWithASummary_data();
    void signalEndsWithASummary();
    void closedOutputEndsARestoreWithItsRecords();
    void largestFloatRoundTrips();
    void deviceTextsCannotDriveTheTerminal();
    void alwaysAnsweringAddressIsNoDevice();
    void relativePortIsAPath();

private:
    QTemporaryDir m_logs;
    TestLine m_line;
    SimulatorPeer m_sim;
    QList<QJsonObject> auditRecords() const;
    // A backup of the dTRON at 4 into file, then three of its parameters changed on the
    // device, so that a restore writes three.
    bool backupThreeApart(const QString &file);
    QStringList port() const { return {"--port", m_line.masterEnd(), "--baud", "19200"}; }
};

void tst_JumoctlLine::initTestCase()
{
    qputenv("JUMO_MAP_PATH", "");
    qputenv("XDG_DATA_HOME", QByteArray(QDir::tempPath().toUtf8() + "/jumo-test-no-maps"));
    qputenv("JUMO_LOG_DIR", m_logs.path().toUtf8());
    QVERIFY(m_line.start());
    QVERIFY(m_sim.startOneOfEachFamily(m_line.deviceEnd()));
}

QList<QJsonObject> tst_JumoctlLine::auditRecords() const
{
    QList<QJsonObject> records;
    QFile file(m_logs.filePath("write-audit.jsonl"));
    if (file.open(QIODevice::ReadOnly)) {
        for (const QByteArray &line : file.readAll().split('\n')) {
            if (!line.isEmpty())
                records << QJsonDocument::fromJson(line).object();
        }
    }
    return records;
}

bool tst_JumoctlLine::backupThreeApart(const QString &file)
{
    SimulatedDevice *dtron = m_sim.line().device(4);
    const QList<std::pair<const char *, double>> saved{{"setpoint_w2", 120}, {"setpoint_w3", 60}, {"ps1_pb1", 10}};
    for (const auto &[id, value] : saved)
        dtron->setNumber(id, value);
    if (run(QStringList{"backup"} + port() + QStringList{"dtron300@4", file}).code != 0)
        return false;
    for (const auto &[id, value] : saved)
        dtron->setNumber(id, value + 1);
    return true;
}

void tst_JumoctlLine::scanFindsEveryFamily()
{
    const Run r = run(QStringList{"scan"} + port() + QStringList{"--from", "1", "--to", "6"});
    QCOMPARE(r.code, 0);
    const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 4);
    QVERIFY(lines[0].startsWith("ipc300@1\t"));
    QVERIFY(lines[1].startsWith("tya200@2\t"));
    QVERIFY(lines[2].startsWith("quantrol@3\t"));
    QVERIFY(lines[3].startsWith("dtron300@4\t"));
    QVERIFY2(r.err.contains("4 device(s) found"), qPrintable(r.err));   // progress goes to stderr
}

void tst_JumoctlLine::quickScanFindsLateDevices()
{
    // Every device answers 200 ms late: after the quick probe's timeout, while the next
    // addresses are probed. Their answers are heard, and taken for nothing else.
    m_sim.line().setProcessingDelayMs(200);
    const auto restoreDelay = qScopeGuard([&] { m_sim.line().setProcessingDelayMs(2); });
    const Run r = run(QStringList{"scan"} + port() + QStringList{"--from", "1", "--to", "30"});
    QCOMPARE(r.code, 0);
    const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 4);
    for (const char *device : {"ipc300@1\t", "tya200@2\t", "quantrol@3\t", "dtron300@4\t"})
        QVERIFY2(r.out.contains(device), qPrintable(r.out));
    QVERIFY2(r.err.contains("quick scan of addresses 1..30: each probed once at "), qPrintable(r.err));
    static const QRegularExpression summary("4 device\\(s\\) found in [0-9.]+ s; ([0-9]+) address\\(es\\) probed again");
    const QRegularExpressionMatch m = summary.match(r.err);
    QVERIFY2(m.hasMatch(), qPrintable(r.err));
    QVERIFY(m.captured(1).toInt() >= 4);
}

void tst_JumoctlLine::thoroughScanSaysWhatItCosts()
{
    const Run r = run(QStringList{"scan", "--thorough"} + port() + QStringList{"--from", "3", "--to", "6"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.out.split('\n', Qt::SkipEmptyParts).size(), 2);
    QVERIFY2(r.err.contains("thorough scan of addresses 3..6 (as asked): a silent address costs two probes at "),
             qPrintable(r.err));
    QVERIFY2(r.err.contains("2 device(s) found in "), qPrintable(r.err));
    QVERIFY2(!r.err.contains("probed again"), qPrintable(r.err));
}

void tst_JumoctlLine::dumpJsonContract()
{
    SimulatedDevice *ipc = m_sim.line().device(1);
    ipc->forceStatus("load_current", ValueStatus::Overrange);
    ipc->forceStatus("load_voltage", ValueStatus::Underrange);
    ipc->forceStatus("power", ValueStatus::Invalid);
    const Run r = run(QStringList{"dump"} + port() + QStringList{"ipc300@1", "--json"});
    for (const char *id : {"load_current", "load_voltage", "power"})
        ipc->forceStatus(id, ValueStatus::Ok);
    QCOMPARE(r.code, 0);
    const QJsonArray rows = QJsonDocument::fromJson(r.out.toUtf8()).array();
    QCOMPARE(rows.size(), 111);   // every readable entry of the IPC 300
    static const QRegularExpression registerPattern("^0x[0-9A-F]{4}$");
    static const QStringList statuses{"ok", "underrange", "overrange", "invalid"};
    QHash<QString, QJsonObject> byId;
    for (const QJsonValue &v : rows) {
        const QJsonObject o = v.toObject();
        QCOMPARE(QStringList(o.keys()),
                 QStringList({"address", "family", "id", "label", "register", "status", "unit", "value"}));
        QCOMPARE(o.value("family").toString(), QString("ipc300"));
        QCOMPARE(o.value("address").toInt(), 1);
        QVERIFY(registerPattern.match(o.value("register").toString()).hasMatch());
        QVERIFY2(statuses.contains(o.value("status").toString()), qPrintable(o.value("status").toString()));
        byId.insert(o.value("id").toString(), o);
    }
    QCOMPARE(byId["load_current"]["status"].toString(), QString("overrange"));
    QVERIFY(byId["load_current"]["value"].isNull());
    QCOMPARE(byId["load_voltage"]["status"].toString(), QString("underrange"));
    QCOMPARE(byId["power"]["status"].toString(), QString("invalid"));
    QCOMPARE(byId["device_name"]["value"].toString(), QString("IPC300  "));
    QCOMPARE(byId["load_resistance"]["register"].toString(), QString("0x00BD"));
    QCOMPARE(byId["load_resistance"]["unit"].toString(), QString("Ω"));
    QVERIFY(byId["load_resistance"]["value"].isDouble());
}

void tst_JumoctlLine::writeIsConfirmed()
{
    const Run r = run(QStringList{"write"} + port() + QStringList{"tya200@2", "setpoint=42.5", "alpha_default=90"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("setpoint: confirmed by read-back: 42.5"), qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains("alpha_default: confirmed by read-back: 90"), qPrintable(r.out + r.err));
    QCOMPARE(m_sim.line().device(2)->number("setpoint"), 42.5);
    const Run check = run(QStringList{"read"} + port() + QStringList{"tya200@2", "setpoint", "reserve_00ef"});
    QCOMPARE(check.code, 0);   // an alias (TYA 5.8's reserve word inside a float) reads too
    QVERIFY2(check.out.contains("setpoint = 42.5 %  [ok]"), qPrintable(check.out));
    // Audited: device, entry, the value it replaced, the new one, the result.
    const QList<QJsonObject> audit = auditRecords();
    QVERIFY(audit.size() >= 2);
    const QJsonObject &setpoint = audit.at(audit.size() - 2);
    QCOMPARE(setpoint.value("device").toString(), QString("tya200@2"));
    QCOMPARE(setpoint.value("entry").toString(), QString("setpoint"));
    QCOMPARE(setpoint.value("new").toString(), QString("42.5"));
    QVERIFY(!setpoint.value("old").toString().isEmpty());   // read before the write
    QCOMPARE(setpoint.value("result").toString(), QString("confirmed"));
}

void tst_JumoctlLine::readOnlyWriteSendsNothing()
{
    const int before = m_sim.writeFrames();
    const Run r = run(QStringList{"write", "--read-only"} + port() + QStringList{"ipc300@1", "input_setpoint=10"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("read-only mode"), qPrintable(r.err));
    QCOMPARE(m_sim.writeFrames(), before);
    QCOMPARE(auditRecords().last().value("result").toString(), QString("read_only"));
    QCOMPARE(auditRecords().last().value("entry").toString(), QString("input_setpoint"));
}

void tst_JumoctlLine::monitorJsonl()
{
    const Run r = run(QStringList{"monitor"} + port()
                      + QStringList{"ipc300@1", "quantrol@3", "--ids", "controller_status", "--cycles", "2", "--jsonl"});
    QCOMPARE(r.code, 2);   // controller_status is not an IPC 300 entry
    QVERIFY(r.err.contains("'controller_status' is not a readable entry of ipc300"));

    const Run ok = run(QStringList{"monitor"} + port()
                       + QStringList{"quantrol@3", "dtron300@4", "--ids", "controller_status", "--cycles", "2", "--jsonl"});
    QCOMPARE(ok.code, 0);
    const QStringList lines = ok.out.split('\n', Qt::SkipEmptyParts);
    QVERIFY2(lines.size() >= 4, qPrintable(ok.out));
    for (const QString &line : lines) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        QCOMPARE(QStringList(o.keys()),
                 QStringList({"condition", "cycle_ms", "device", "line", "status", "time", "values"}));
        QCOMPARE(o["line"].toString(), QString("line1"));
        QCOMPARE(o["condition"].toString(), QString("online"));
        QVERIFY(o["device"].toString() == "quantrol@3" || o["device"].toString() == "dtron300@4");
        QCOMPARE(o["status"].toObject()["controller_status"].toString(), QString("ok"));
        QVERIFY(o["values"].toObject()["controller_status"].isDouble());
        QVERIFY(o["cycle_ms"].toDouble() >= 0);
        QVERIFY(QDateTime::fromString(o["time"].toString(), Qt::ISODateWithMs).isValid());
    }
}

void tst_JumoctlLine::monitorCsv()
{
    const Run r = run(QStringList{"monitor"} + port()
                      + QStringList{"ipc300@1", "--ids", "load_current,load_voltage", "--cycles", "3", "--csv"});
    QCOMPARE(r.code, 0);
    const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.first(), QString("time,device,id,value,unit,status"));
    QCOMPARE(lines.size(), 1 + 3 * 2);
    QVERIFY(lines[1].contains(",ipc300@1,load_current,"));
    QVERIFY(lines[1].endsWith(",A,ok"));
}

void tst_JumoctlLine::monitorIntoAFullDiskStops()
{
    // Rows that go nowhere end the monitor with the reason; it does not poll on for ever.
    QProcess p;
    QSignalSpy finished(&p, &QProcess::finished);
    p.setStandardOutputFile("/dev/full");
    p.start(QStringLiteral(JUMOCTL_PATH), QStringList{"monitor"} + port() + QStringList{"ipc300@1", "--csv"});
    QVERIFY(finished.wait(60000));   // the simulator lives in this process: its event loop runs meanwhile
    QCOMPARE(p.exitCode(), 1);
    const QByteArray err = p.readAllStandardError();
    QVERIFY2(err.contains("jumoctl: the output could not be written: No space left on device"), err.constData());
}

void tst_JumoctlLine::monitorGoesOnWithoutASilentDevice()
{
    // Nothing answers at 7: the others are monitored, the silent one said to be so.
    const Run r = run(QStringList{"monitor"} + port()
                      + QStringList{"ipc300@1", "tya200@7", "--ids", "load_voltage", "--cycles", "2", "--retries", "0",
                                    "--jsonl"});
    QCOMPARE(r.code, 1);
    int online = 0;
    int silent = 0;
    for (const QString &line : r.out.split('\n', Qt::SkipEmptyParts)) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        if (o["device"].toString() == "ipc300@1") {
            QCOMPARE(o["condition"].toString(), QString("online"));
            QVERIFY(o["values"].toObject()["load_voltage"].isDouble());
            ++online;
        } else {
            QCOMPARE(o["device"].toString(), QString("tya200@7"));
            QVERIFY2(o["condition"].toString() == "offline", qPrintable(line));
            QVERIFY(o["values"].toObject()["load_voltage"].isNull());
            ++silent;
        }
    }
    QVERIFY2(online >= 2 && silent >= 2, qPrintable(r.out));
    QVERIFY2(r.err.contains("never confirmed: tya200@7 did not answer"), qPrintable(r.err));
    QVERIFY2(!r.err.contains("ipc300@1"), qPrintable(r.err));

    // The other line commands keep refusing a device whose family is not confirmed.
    for (const QStringList &command : {QStringList{"read", "tya200@7", "load_voltage"},
                                       QStringList{"write", "tya200@7", "setpoint=10"}}) {
        const Run refused = run(command + port() + QStringList{"--retries", "0"});
        QCOMPARE(refused.code, 1);
    }
}

void tst_JumoctlLine::monitorConfirmsADeviceThatAnswersLater()
{
    // The TYA 200 is off when the monitor starts, and switched on while it runs: its
    // family is checked when it answers, and its values follow.
    QVERIFY(m_sim.setFault(2, "dead", -1, 0));
    auto alive = qScopeGuard([&] { m_sim.setFault(2, "none", -1, 0); });
    QProcess monitor;
    monitor.start(QStringLiteral(JUMOCTL_PATH),
                  QStringList{"monitor"} + port()
                          + QStringList{"ipc300@1", "tya200@2", "--ids", "load_voltage", "--interval", "100",
                                        "--retries", "0", "--jsonl"});
    auto stop = qScopeGuard([&] {
        if (monitor.state() != QProcess::NotRunning) {
            monitor.kill();
            monitor.waitForFinished(5000);
        }
    });
    QList<QJsonObject> records;
    const auto count = [&](const QString &device, const QString &condition) {
        while (monitor.canReadLine())
            records << QJsonDocument::fromJson(monitor.readLine()).object();
        int n = 0;
        for (const QJsonObject &o : std::as_const(records))
            n += o["device"].toString() == device && o["condition"].toString() == condition;
        return n;
    };
    // The simulator lives in this process: QTRY keeps its event loop running.
    QTRY_VERIFY_WITH_TIMEOUT(count("ipc300@1", "online") >= 3 && count("tya200@2", "offline") >= 1, 60000);
    QCOMPARE(count("tya200@2", "online"), 0);
    m_sim.setFault(2, "none", -1, 0);
    QTRY_VERIFY_WITH_TIMEOUT(count("tya200@2", "online") >= 2, 120000);
    for (const QJsonObject &o : std::as_const(records)) {
        if (o["device"].toString() == "tya200@2" && o["condition"].toString() == "online")
            QVERIFY(o["values"].toObject()["load_voltage"].isDouble());
        else if (o["device"].toString() == "tya200@2")
            QVERIFY(o["values"].toObject()["load_voltage"].isNull());   // nothing of it before it was confirmed
    }
    ::kill(pid_t(monitor.processId()), SIGTERM);
    QTRY_VERIFY_WITH_TIMEOUT(monitor.state() == QProcess::NotRunning, 30000);
    QCOMPARE(monitor.exitCode(), 143);
    const QString err = QString::fromLocal8Bit(monitor.readAllStandardError());
    QVERIFY2(!err.contains("never confirmed"), qPrintable(err));
}

void tst_JumoctlLine::monitorNamesAWrongDeviceAndGoesOn()
{
    // A dTRON answers at 4, the command names a Quantrol there: the other device is
    // monitored, the wrong one named, nothing of it shown as a Quantrol's, exit code 4.
    const int writesBefore = m_sim.writeFrames();
    const Run r = run(QStringList{"monitor"} + port()
                      + QStringList{"quantrol@3", "quantrol@4", "--ids", "controller_status", "--cycles", "1", "--jsonl"});
    QCOMPARE(r.code, 4);
    QVERIFY2(r.err.contains("quantrol@4 refused: the device at address 4 is a dtron300"), qPrintable(r.err));
    QVERIFY2(r.err.contains("never confirmed: quantrol@4 refused"), qPrintable(r.err));
    bool wrong = false;
    bool good = false;
    for (const QString &line : r.out.split('\n', Qt::SkipEmptyParts)) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        if (o["device"].toString() == "quantrol@4") {
            QCOMPARE(o["condition"].toString(), QString("wrong_device"));
            QVERIFY(o["values"].toObject()["controller_status"].isNull());
            QCOMPARE(o["status"].toObject()["controller_status"].toString(), QString("wrong_device"));
            wrong = true;
        } else {
            QCOMPARE(o["condition"].toString(), QString("online"));
            good = true;
        }
    }
    QVERIFY2(wrong && good, qPrintable(r.out));
    QCOMPARE(m_sim.writeFrames(), writesBefore);
}

void tst_JumoctlLine::dumpStatusesAreTheDocumentedOnes()
{
    // Nothing answers at 9 and its identity is not checked: every block times out, and
    // the device goes offline halfway. README's statuses for dump --json are these.
    const Run r = run(QStringList{"dump", "--no-identify"} + port() + QStringList{"ipc300@9", "--retries", "0", "--json"});
    QCOMPARE(r.code, 1);
    static const QRegularExpression documented("^(ok|underrange|overrange|invalid|timeout|unavailable|exception:[0-9]+)$");
    const QJsonArray rows = QJsonDocument::fromJson(r.out.toUtf8()).array();
    QCOMPARE(rows.size(), 111);
    for (const QJsonValue &row : rows) {
        const QString status = row.toObject()["status"].toString();
        QVERIFY2(documented.match(status).hasMatch(), qPrintable(status));
        QCOMPARE(status, QString("timeout"));
    }
}

void tst_JumoctlLine::diffOfAFileThatCannotBeComparedIsAProblem_data()
{
    QTest::addColumn<QString>("device");    // in a good backup of this device,
    QTest::addColumn<QString>("from");      // this text replaced
    QTest::addColumn<QString>("to");        // by this one,
    QTest::addColumn<QString>("problem");   // and what stderr says
    QTest::newRow("another family") << "dtron300@4" << "\"family\": \"dtron300\"" << "\"family\": \"quantrol\""
                                    << "the file is for the family quantrol, the device is dtron300";
    QTest::newRow("an unknown id") << "dtron300@4" << "\"setpoint_w2\":" << "\"setpoint_w9\":"
                                   << "'setpoint_w9' in the file is no parameter of dtron300";
    QTest::newRow("an invalid value") << "dtron300@4" << "\"setpoint_w2\": \"120\"" << "\"setpoint_w2\": \"warm\""
                                      << "'setpoint_w2' in the file:";
    // Known only once the device has told its version.
    QTest::newRow("another software version") << "ipc300@1" << "\"softwareVersion\": \""
                                              << "\"softwareVersion\": \"9" << "the file is from software version 9";
}

void tst_JumoctlLine::diffOfAFileThatCannotBeComparedIsAProblem()
{
    QFETCH(QString, device);
    QFETCH(QString, from);
    QFETCH(QString, to);
    QFETCH(QString, problem);
    QTemporaryDir dir;
    const QString file = dir.filePath("backup.json");
    SimulatedDevice *dtron = m_sim.line().device(4);
    const double w2 = dtron->number("setpoint_w2");
    const auto back = qScopeGuard([&] { dtron->setNumber("setpoint_w2", w2); });
    QVERIFY(dtron->setNumber("setpoint_w2", 120));
    QCOMPARE(run(QStringList{"backup"} + port() + QStringList{device, file}).code, 0);
    QFile f(file);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QString json = QString::fromUtf8(f.readAll());
    f.close();
    QVERIFY2(json.contains(from), qPrintable(json.left(400)));
    json.replace(from, to);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(json.toUtf8());
    f.close();
    // diff(1): 1 would say "they differ"; a file that cannot be compared is trouble, 2.
    const Run r = run(QStringList{"diff"} + port() + QStringList{device, file});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(problem), qPrintable(r.err));
    QVERIFY2(!r.out.contains("differ"), qPrintable(r.out));
}

void tst_JumoctlLine::absentDeviceIsATimeout()
{
    Run r = run(QStringList{"read"} + port() + QStringList{"ipc300@9", "load_current", "--retries", "0", "--json"});
    QCOMPARE(r.code, 1);
    const QJsonArray rows = QJsonDocument::fromJson(r.out.toUtf8()).array();
    QCOMPARE(rows.size(), 1);
    QCOMPARE(rows[0].toObject()["status"].toString(), QString("timeout"));
    QVERIFY(rows[0].toObject()["value"].isNull());
    QVERIFY(r.err.contains("could not be read"));

    // A device that answers with an exception: the status says which. (The faults are
    // meant for the read itself, not for the identity probes before it.)
    m_sim.setFault(3, "exception", 1, 1);
    r = run(QStringList{"read", "--no-identify"} + port() + QStringList{"quantrol@3", "controller_status", "--retries", "0"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.out.contains("exception 1: Invalid function") && r.out.contains("[exception:1]"), qPrintable(r.out));

    // Exception 02 twice for the one entry: the device does not have it.
    m_sim.setFault(3, "exception", 2, 2);
    r = run(QStringList{"read", "--no-identify"} + port() + QStringList{"quantrol@3", "controller_status", "--retries", "0"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.out.contains("not available on this device") && r.out.contains("[unavailable]"), qPrintable(r.out));
}

void tst_JumoctlLine::badPortIsAClearError()
{
    const Run r = run({"read", "--port", "/nonexistent/ttyUSB9", "ipc300@1", "load_current"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("cannot open /nonexistent/ttyUSB9"), qPrintable(r.err));
    const Run bad = run(QStringList{"read"} + port() + QStringList{"ipc300@1", "load_current", "--format", "7N1"});
    QCOMPARE(bad.code, 2);
    QVERIFY(bad.err.contains("unsupported baud rate or data format"));
    const Run noDevice = run(QStringList{"read"} + port() + QStringList{"ipc300-1", "load_current"});
    QCOMPARE(noDevice.code, 2);
    QVERIFY(noDevice.err.contains("use FAMILY@ADDRESS"));
}

void tst_JumoctlLine::backupChangeDiffRestore()
{
    QTemporaryDir dir;
    const QString file = dir.filePath("dtron.json");
    Run r = run(QStringList{"backup"} + port() + QStringList{"dtron300@4", file});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("saved to"), qPrintable(r.out + r.err));
    SimulatedDevice *dtron = m_sim.line().device(4);
    const double pb1 = dtron->number("ps1_pb1");
    const double w2 = dtron->number("setpoint_w2");

    // Someone changes two parameters on the device.
    r = run(QStringList{"write"} + port() + QStringList{"dtron300@4", "ps1_pb1=77.7", "setpoint_w2=12.34"});
    QCOMPARE(r.code, 0);
    r = run(QStringList{"diff"} + port() + QStringList{"dtron300@4", file});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.out.contains("2 parameter(s) differ"), qPrintable(r.out));
    QVERIFY2(r.out.contains("ps1_pb1") && r.out.contains("77.7 -> "), qPrintable(r.out));
    QVERIFY2(r.out.contains("setpoint_w2") && r.out.contains("12.34 -> "), qPrintable(r.out));

    // Restore writes only what differs, each verified; the device is back.
    const int writesBefore = m_sim.writeFrames();
    r = run(QStringList{"restore", "--yes"} + port() + QStringList{"dtron300@4", file});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("2 parameter(s) restored and verified"), qPrintable(r.out + r.err));
    QCOMPARE(m_sim.writeFrames() - writesBefore, 2);
    QCOMPARE(dtron->number("ps1_pb1"), pb1);
    QCOMPARE(dtron->number("setpoint_w2"), w2);
    r = run(QStringList{"diff"} + port() + QStringList{"dtron300@4", file});
    QCOMPARE(r.code, 0);
    QVERIFY(r.out.contains("no differences"));
}

void tst_JumoctlLine::restoreRefusesOtherFamilyAndVersion()
{
    QTemporaryDir dir;
    const QString file = dir.filePath("ipc.json");
    QCOMPARE(run(QStringList{"backup"} + port() + QStringList{"ipc300@1", file}).code, 0);
    const int writesBefore = m_sim.writeFrames();
    Run r = run(QStringList{"restore", "--yes"} + port() + QStringList{"tya200@2", file});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("refused: the file is for the family ipc300, the device is tya200"), qPrintable(r.err));

    QFile f(file);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QByteArray json = f.readAll();
    f.close();
    QVERIFY(json.contains("\"softwareVersion\": \"123.01.01\""));
    json.replace("\"softwareVersion\": \"123.01.01\"", "\"softwareVersion\": \"124.00.00\"");
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(json);
    f.close();
    r = run(QStringList{"restore", "--yes"} + port() + QStringList{"ipc300@1", file});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("software version 124.00.00, the device runs 123.01.01"), qPrintable(r.err));
    QCOMPARE(m_sim.writeFrames(), writesBefore);
}

void tst_JumoctlLine::reportAsHtmlAndPdf()
{
    QTemporaryDir dir;
    QCOMPARE(run(QStringList{"write"} + port() + QStringList{"ipc300@1", "max_alarm_limit=55"}).code, 0);
    m_sim.line().device(1)->setFlag("malfunction_signal_1.igbt_break", true);
    Run r = run(QStringList{"report"} + port() + QStringList{"ipc300@1", dir.filePath("report.html")});
    m_sim.line().device(1)->setFlag("malfunction_signal_1.igbt_break", false);
    QCOMPARE(r.code, 0);
    QFile html(dir.filePath("report.html"));
    QVERIFY(html.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(html.readAll());
    QVERIFY(text.contains("Commissioning report"));
    QVERIFY(text.contains("SIM-0000001"));                 // identity: fabrication number
    // A parameter by its label, in the unit of what the alarm monitors (set on the device).
    QVERIFY2(text.contains("<td>Limit value for max. alarm</td><td>55.0</td>"), qPrintable(text));
    QVERIFY(text.contains("<td>230.0 V</td>") || text.contains(" V</td>"));   // a live value with its unit
    QVERIFY(text.contains("IGBT break"));                  // an active alarm
    QVERIFY(text.contains("<td>Limit value for max. alarm</td><td>"));   // the write of today...
    QVERIFY(text.contains("<td>55.0</td><td>confirmed by read-back</td>"));
    QVERIFY(text.contains("<td width=\"33%\">19200 baud, 8N1, port "));   // the line in the title block
    QVERIFY(text.contains("<td width=\"33%\">jumoctl "));

    // PDF needs QtGui: the test process is GUI-less, so the real executable makes it.
    QProcess p;
    p.start(QStringLiteral(JUMOCTL_PATH), QStringList{"report"} + port() + QStringList{"ipc300@1", dir.filePath("report.pdf")});
    // The simulator lives in this process: keep its event loop running meanwhile.
    QTRY_VERIFY_WITH_TIMEOUT(p.state() == QProcess::NotRunning, 60000);
    QCOMPARE(p.exitCode(), 0);
    QFile pdf(dir.filePath("report.pdf"));
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    QVERIFY(pdf.read(5) == "%PDF-");
    QVERIFY(pdf.size() > 10000);
}

void tst_JumoctlLine::reportIsADocumentToSign()
{
    const QString pdftotext = QStandardPaths::findExecutable("pdftotext");
    if (pdftotext.isEmpty())
        QSKIP("pdftotext (poppler-utils) is not installed: the PDF's text cannot be read");
    QTemporaryDir dir;
    const QString path = dir.filePath("dtron.pdf");
    QProcess p;   // PDF needs QtGui: the real executable makes it
    p.start(QStringLiteral(JUMOCTL_PATH), QStringList{"report", "--site", "Plant <North> & Co", "--tag", "TIC-101",
                                                      "--engineer", "Erika Mustermann", "--cabinet", "=A1+B2"}
                                                  + port() + QStringList{"dtron300@4", path});
    QTRY_VERIFY_WITH_TIMEOUT(p.state() == QProcess::NotRunning, 60000);
    QCOMPARE(p.exitCode(), 0);
    QProcess text;
    text.start(pdftotext, {"-layout", path, "-"});
    QVERIFY(text.waitForFinished(30000));
    QCOMPARE(text.exitCode(), 0);
    const QString t = QString::fromUtf8(text.readAllStandardOutput());
    for (const char *expected : {"Plant <North> & Co", "TIC-101", "Erika Mustermann", "=A1+B2", "Page 1 of ",
                                 "19200 baud, 8N1", "Commissioning engineer", "Customer", "Signature",
                                 "5.3 Controller parameters"})
        QVERIFY2(t.contains(QString::fromUtf8(expected)), expected);
    // A value with its unit (the sampling cycle in ms, a delay in s) and the last page numbered as such.
    QVERIFY2(t.contains(QRegularExpression(" [0-9]+(\\.[0-9]+)? (ms|s|%)\\b")), qPrintable(t));
    const QRegularExpression of("Page 1 of ([0-9]+)");
    const int pages = of.match(t).captured(1).toInt();
    QVERIFY(pages >= 2);
    QVERIFY(t.contains(QStringLiteral("Page %1 of %1").arg(pages)));
    QCOMPARE(t.count("Page "), pages);   // one number on every page
    // The signature lines come last.
    QVERIFY(t.lastIndexOf("Signature") > t.lastIndexOf("Writes since"));
}

void tst_JumoctlLine::wrongFamilyIsRefused_data()
{
    QTest::addColumn<QStringList>("arguments");   // FILE: a quantrol parameter file
    QTest::newRow("read") << QStringList{"read", "quantrol@4", "controller_setpoint"};
    QTest::newRow("dump") << QStringList{"dump", "quantrol@4", "--json"};
    QTest::newRow("write") << QStringList{"write", "quantrol@4", "controller_setpoint=50"};
    QTest::newRow("broadcast read-back") << QStringList{"write", "quantrol@0", "controller_setpoint=50", "--verify", "3,4",
                                                    "--line-has-only", "quantrol"};
    QTest::newRow("backup") << QStringList{"backup", "quantrol@4", "NEW"};
    QTest::newRow("diff") << QStringList{"diff", "quantrol@4", "FILE"};
    QTest::newRow("restore") << QStringList{"restore", "--yes", "quantrol@4", "FILE"};
    QTest::newRow("report") << QStringList{"report", "quantrol@4", "NEW"};
}

void tst_JumoctlLine::wrongFamilyIsRefused()
{
    QFETCH(QStringList, arguments);
    // A dTRON answers at 4; the command names a Quantrol there.
    QTemporaryDir dir;
    const QString file = dir.filePath("quantrol.json");
    QCOMPARE(run(QStringList{"backup"} + port() + QStringList{"quantrol@3", file}).code, 0);
    m_sim.line().device(3)->setNumber("controller_setpoint", 77);   // so a restore would write
    arguments.replaceInStrings(QRegularExpression("^FILE$"), file);
    arguments.replaceInStrings(QRegularExpression("^NEW$"), dir.filePath("new.out"));
    const int writesBefore = m_sim.writeFrames();
    const int auditBefore = int(auditRecords().size());
    const Run r = run(arguments + port());
    QCOMPARE(r.code, 4);
    QVERIFY2(r.err.contains("quantrol@4 refused: the device at address 4 is a dtron300"), qPrintable(r.err));
    QVERIFY2(r.out.isEmpty(), qPrintable(r.out));   // no value, no difference, no "saved"
    QCOMPARE(m_sim.writeFrames(), writesBefore);
    if (!arguments.contains("--line-has-only"))   // an acknowledgement is recorded as given
        QCOMPARE(auditRecords().size(), auditBefore);
    QVERIFY(!QFile::exists(dir.filePath("new.out")));
}

void tst_JumoctlLine::noIdentifyIsAudited()
{
    const Run r = run(QStringList{"write", "--no-identify"} + port() + QStringList{"dtron300@4", "setpoint_w3=61"});
    QCOMPARE(r.code, 0);
    const QList<QJsonObject> audit = auditRecords();
    QVERIFY(audit.size() >= 2);
    QCOMPARE(audit.at(audit.size() - 2).value("device").toString(), QString("dtron300@4"));
    QCOMPARE(audit.at(audit.size() - 2).value("result").toString(), QString("identity_not_checked"));
    QCOMPARE(audit.last().value("entry").toString(), QString("setpoint_w3"));
    QCOMPARE(audit.last().value("result").toString(), QString("confirmed"));
}

void tst_JumoctlLine::broadcastNeedsALineOfOneFamily()
{
    // dTRON's segment_setpoint_3 is at the IPC 300's load_voltage_limit (0x0099).
    SimulatedDevice *ipc = m_sim.line().device(1);
    const double limit = ipc->number("load_voltage_limit");
    const int writesBefore = m_sim.writeFrames();
    const QStringList broadcast = QStringList{"write"} + port() + QStringList{"dtron300@0", "segment_setpoint_3=500"};

    Run r = run(broadcast + QStringList{"--verify", "4"});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("give --scan-first") && r.err.contains("--line-has-only dtron300"), qPrintable(r.err));
    r = run(broadcast + QStringList{"--verify", "4", "--line-has-only", "ipc300"});
    QCOMPARE(r.code, 2);
    // The scan of the line meets the IPC 300 at address 1 and stops there.
    r = run(broadcast + QStringList{"--scan-first"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("not broadcast: address 1 answers as ipc300"), qPrintable(r.err));
    QCOMPARE(m_sim.writeFrames(), writesBefore);
    QCOMPARE(ipc->number("load_voltage_limit"), limit);

    // The user's word is taken, and recorded: then the frame goes out, once.
    r = run(broadcast + QStringList{"--verify", "4", "--line-has-only", "dtron300"});
    QCOMPARE(r.code, 0);
    QCOMPARE(m_sim.writeFrames(), writesBefore + 1);
    const QList<QJsonObject> audit = auditRecords();
    QCOMPARE(audit.at(audit.size() - 2).value("device").toString(), QString("dtron300@0"));
    QCOMPARE(audit.at(audit.size() - 2).value("result").toString(), QString("broadcast_acknowledged"));
    QCOMPARE(audit.last().value("result").toString(), QString("confirmed"));
    QCOMPARE(ipc->number("load_voltage_limit"), 500.0);   // what the acknowledgement was wrong about
    ipc->setNumber("load_voltage_limit", limit);
}

void tst_JumoctlLine::fullDiskKeepsThePreviousFiles()
{
    QTemporaryDir dir;
    const QString disk = dir.filePath("disk");
    QVERIFY(QDir().mkpath(disk));
    QProcess mount;
    mount.start("mount", {"-t", "tmpfs", "-o", "size=256k", "tmpfs", disk});
    if (!mount.waitForFinished(10000) || mount.exitStatus() != QProcess::NormalExit || mount.exitCode() != 0)
        QSKIP("no small tmpfs can be mounted here (needs root); tst_files makes a disk full with a file size limit");
    const auto unmount = qScopeGuard([&] { QProcess::execute("umount", {disk}); });
    const QString backup = QDir(disk).filePath("dtron.json");
    const QString html = QDir(disk).filePath("report.html");
    const QString pdf = QDir(disk).filePath("report.pdf");
    auto pdfReport = [&] {
        QProcess p;   // PDF needs QtGui: the real executable makes it
        QSignalSpy finished(&p, &QProcess::finished);
        p.start(QStringLiteral(JUMOCTL_PATH), QStringList{"report"} + port() + QStringList{"dtron300@4", pdf});
        // The simulator lives in this process: keep its event loop running meanwhile.
        const bool ended = finished.wait(60000);
        return std::make_pair(ended ? p.exitCode() : -1, QString::fromLocal8Bit(p.readAllStandardError()));
    };
    QCOMPARE(run(QStringList{"backup"} + port() + QStringList{"dtron300@4", backup}).code, 0);
    QCOMPARE(run(QStringList{"report"} + port() + QStringList{"dtron300@4", html}).code, 0);
    QCOMPARE(pdfReport().first, 0);
    QHash<QString, QByteArray> before;
    for (const QString &path : {backup, html, pdf}) {
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        before.insert(path, f.readAll());
        QVERIFY(!before[path].isEmpty());
    }
    // Fill the disk to the last byte.
    QFile filler(QDir(disk).filePath("filler"));
    QVERIFY(filler.open(QIODevice::WriteOnly | QIODevice::Unbuffered));
    while (filler.write(QByteArray(512, 'x')) > 0) { }
    while (filler.write("x", 1) > 0) { }
    filler.close();
    m_sim.line().device(4)->setNumber("setpoint_w2", 99);   // the new files would differ

    Run r = run(QStringList{"backup"} + port() + QStringList{"dtron300@4", backup});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("cannot write " + backup + ": No space left on device"), qPrintable(r.err));
    QVERIFY2(!r.out.contains("saved"), qPrintable(r.out));
    r = run(QStringList{"report"} + port() + QStringList{"dtron300@4", html});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("cannot write " + html + ": No space left on device"), qPrintable(r.err));
    const auto [pdfCode, pdfError] = pdfReport();
    QCOMPARE(pdfCode, 1);
    QVERIFY2(pdfError.contains("cannot write " + pdf + ": No space left on device"), qPrintable(pdfError));
    for (const QString &path : {backup, html, pdf}) {
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY2(f.readAll() == before[path], qPrintable(path));   // byte for byte
    }
}

void tst_JumoctlLine::auditFailureIsAFailure()
{
    QTemporaryDir logs;
    qputenv("JUMO_LOG_DIR", logs.path().toUtf8());
    const auto restore = qScopeGuard([&] { qputenv("JUMO_LOG_DIR", m_logs.path().toUtf8()); });
    const QString audit = logs.filePath("write-audit.jsonl");

    // The log is a folder: the write is done and confirmed, but its record is lost.
    QVERIFY(QDir().mkpath(audit));
    Run r = run(QStringList{"write"} + port() + QStringList{"dtron300@4", "setpoint_w3=62"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.out.contains("confirmed"), qPrintable(r.out));
    QVERIFY2(r.err.contains("the audit log did not take a record: cannot write " + audit), qPrintable(r.err));

    // The log is a FIFO: a report must not wait for a writer, nor leave out today's writes.
    QVERIFY(QDir(audit).removeRecursively());
    QVERIFY(::mkfifo(QFile::encodeName(audit).constData(), 0600) == 0);
    r = run(QStringList{"report"} + port() + QStringList{"dtron300@4", logs.filePath("report.html")});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("not a regular file"), qPrintable(r.err));
    QVERIFY(!QFile::exists(logs.filePath("report.html")));
}

void tst_JumoctlLine::signalEndsWithASummary_data()
{
    QTest::addColumn<QStringList>("arguments");   // FILE: a dTRON backup, 3 parameters apart
    QTest::addColumn<QString>("waitFor");         // on stdout, before the signal
    QTest::addColumn<int>("signal");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("summary");
    QTest::addColumn<int>("writes");              // write frames that may reach the device
    QTest::newRow("restore prompt, Ctrl-C") << QStringList{"restore", "dtron300@4", "FILE"} << "[y/N]" << SIGINT << 130
                                            << "interrupted: nothing was written" << 0;
    QTest::newRow("restore under way, Ctrl-C") << QStringList{"restore", "--yes", "dtron300@4", "FILE"}
                                               << "confirmed by read-back" << SIGINT << 130
                                               << " of 3 write(s) done (" << 2;
    QTest::newRow("restore under way, SIGHUP") << QStringList{"restore", "--yes", "dtron300@4", "FILE"}
                                               << "confirmed by read-back" << SIGHUP << 129
                                               << "hangup: " << 2;
    QTest::newRow("scan, SIGTERM") << QStringList{"scan", "--from", "1", "--to", "200"} << "dtron300@4" << SIGTERM << 143
                                   << "terminated: 4 device(s) found before the scan stopped" << 0;
    QTest::newRow("monitor, Ctrl-C") << QStringList{"monitor", "ipc300@1", "--jsonl"} << "ipc300@1" << SIGINT << 130
                                     << "poll cycle(s) printed" << 0;
}

void tst_JumoctlLine::signalEndsWithASummary()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, waitFor);
    QFETCH(int, signal);
    QFETCH(int, exitCode);
    QFETCH(QString, summary);
    QFETCH(int, writes);
    QTemporaryDir dir;
    const QString file = dir.filePath("dtron.json");
    QVERIFY(backupThreeApart(file));
    arguments.replaceInStrings(QRegularExpression("^FILE$"), file);
    // Slow replies, so the command is still at work when the signal comes.
    m_sim.line().setProcessingDelayMs(150);
    const auto restoreDelay = qScopeGuard([&] { m_sim.line().setProcessingDelayMs(2); });

    const int writesBefore = m_sim.writeFrames();
    const qsizetype auditBefore = auditRecords().size();
    QProcess p;
    QSignalSpy finished(&p, &QProcess::finished);
    p.start(QStringLiteral(JUMOCTL_PATH), arguments + port());   // stdin stays open: nobody answers
    QString out;
    // The simulator lives in this process: keep its event loop running meanwhile.
    QTRY_VERIFY2_WITH_TIMEOUT((out += QString::fromLocal8Bit(p.readAllStandardOutput())).contains(waitFor),
                              qPrintable(out + p.readAllStandardError()), 30000);
    ::kill(pid_t(p.processId()), signal);
    QVERIFY2(finished.wait(30000), "the command did not end after the signal");
    const QString err = QString::fromLocal8Bit(p.readAllStandardError());
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), exitCode);
    QVERIFY2(err.contains(summary), qPrintable(err));
    QVERIFY2(m_sim.writeFrames() - writesBefore <= writes, qPrintable(QString::number(m_sim.writeFrames() - writesBefore)));
    QTest::qWait(500);   // nothing more goes out after the end
    QVERIFY(m_sim.writeFrames() - writesBefore <= writes);
    // Every write begun has its audit record: those done, and the one under way (unknown).
    static const QRegularExpression done("(\\d+) of \\d+ write\\(s\\) done");
    if (const QRegularExpressionMatch m = done.match(err); m.hasMatch()) {
        const int begun = m.captured(1).toInt() + int(err.contains("was being written"));
        QCOMPARE(auditRecords().size() - auditBefore, qsizetype(begun));
    }
}

void tst_JumoctlLine::closedOutputEndsARestoreWithItsRecords()
{
    // jumoctl restore ... | head -n 1: the reader goes after the first line; the restore
    // stops before its next write, says so, and every write it made is audited.
    QTemporaryDir dir;
    const QString file = dir.filePath("dtron.json");
    QVERIFY(backupThreeApart(file));
    m_sim.line().setProcessingDelayMs(150);
    const auto restoreDelay = qScopeGuard([&] { m_sim.line().setProcessingDelayMs(2); });

    const int writesBefore = m_sim.writeFrames();
    const qsizetype auditBefore = auditRecords().size();
    QProcess restore;
    QProcess head;
    restore.setStandardOutputProcess(&head);
    QSignalSpy finished(&restore, &QProcess::finished);
    head.start("head", {"-n", "1"});
    restore.start(QStringLiteral(JUMOCTL_PATH), QStringList{"restore", "--yes", "dtron300@4", file} + port());
    QVERIFY2(finished.wait(60000), "the restore did not end when its output was closed");
    QTRY_VERIFY_WITH_TIMEOUT(head.state() == QProcess::NotRunning, 30000);
    const QString err = QString::fromLocal8Bit(restore.readAllStandardError());
    QCOMPARE(restore.exitStatus(), QProcess::NormalExit);   // not killed by SIGPIPE
    QCOMPARE(restore.exitCode(), 141);
    static const QRegularExpression summary("output closed: (\\d+) of 3 write\\(s\\) done \\((\\d+) restored and verified\\)");
    const QRegularExpressionMatch m = summary.match(err);
    QVERIFY2(m.hasMatch(), qPrintable(err));
    const int done = m.captured(1).toInt();
    QVERIFY2(done < 3 && !err.contains("was being written"), qPrintable(err));   // it stopped between writes
    QCOMPARE(m_sim.writeFrames() - writesBefore, done);
    QCOMPARE(auditRecords().size() - auditBefore, qsizetype(done));
    for (qsizetype i = auditBefore; i < auditRecords().size(); ++i)
        QCOMPARE(auditRecords().at(i).value("result").toString(), QString("confirmed"));
    QTest::qWait(500);   // nothing more goes out after the end
    QCOMPARE(m_sim.writeFrames() - writesBefore, done);
}

void tst_JumoctlLine::largestFloatRoundTrips()
{
    SimulatedDevice *dtron = m_sim.line().device(4);
    const double w2 = dtron->number("setpoint_w2");
    const auto restore = qScopeGuard([&] { dtron->setNumber("setpoint_w2", w2); });
    QVERIFY(dtron->setNumber("setpoint_w2", double(std::numeric_limits<float>::max())));
    QTemporaryDir dir;
    const QString file = dir.filePath("dtron.json");
    QCOMPARE(run(QStringList{"backup"} + port() + QStringList{"dtron300@4", file}).code, 0);
    Run r = run(QStringList{"diff"} + port() + QStringList{"dtron300@4", file});
    QVERIFY2(r.code == 0 && r.out.contains("no differences"), qPrintable(r.out + r.err));
    const int writesBefore = m_sim.writeFrames();
    r = run(QStringList{"restore", "--yes"} + port() + QStringList{"dtron300@4", file});
    QCOMPARE(r.code, 0);
    QCOMPARE(m_sim.writeFrames(), writesBefore);
}

void tst_JumoctlLine::deviceTextsCannotDriveTheTerminal()
{
    SimulatedDevice *ipc = m_sim.line().device(1);
    QVERIFY(ipc->setText("device_name", "IPC\x1b[2J\r"));
    const auto restore = qScopeGuard([&] { ipc->setText("device_name", "IPC300  "); });
    Run r = run(QStringList{"read"} + port() + QStringList{"ipc300@1", "device_name"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("device_name = IPC\\x1b[2J\\x0d  [ok]"), qPrintable(r.out));
    QVERIFY(!r.out.contains(QChar(0x1b)));
    r = run(QStringList{"monitor"} + port() + QStringList{"ipc300@1", "--ids", "device_name", "--cycles", "1", "--csv"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains(",ipc300@1,device_name,\"IPC\x1b[2J\r\","), qPrintable(r.out));   // data as it is, quoted
}

void tst_JumoctlLine::alwaysAnsweringAddressIsNoDevice()
{
    // The IPC 300 at address 1 also answers at 255, as every IPC 300 does.
    const Run r = run(QStringList{"scan"} + port() + QStringList{"--from", "253", "--to", "255"});
    QCOMPARE(r.code, 1);
    QVERIFY2(!r.out.contains("@255"), qPrintable(r.out));
    QVERIFY2(r.err.contains("address 255 answers as ipc300, which every ipc300 does whatever its own address"),
             qPrintable(r.err));
}

void tst_JumoctlLine::relativePortIsAPath()
{
    // "line/master", as a user types it in the folder above: no "./" in front.
    const QFileInfo master(m_line.masterEnd());
    const QString before = QDir::currentPath();
    QVERIFY(QDir::setCurrent(master.dir().absolutePath() + "/.."));
    const auto back = qScopeGuard([&] { QDir::setCurrent(before); });
    const QString relative = master.dir().dirName() + "/" + master.fileName();
    const Run r = run({"read", "--port", relative, "--baud", "19200", "dtron300@4", "setpoint"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
}

QTEST_GUILESS_MAIN(tst_JumoctlLine)
#include "tst_jumoctl_line.moc"
