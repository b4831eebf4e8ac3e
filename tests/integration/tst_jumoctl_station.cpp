// jumoctl with several lines: two simulator lines on two pty pairs, given by --line or a
// station file, read, scanned and monitored in one run; a line that is lost while the
// other goes on, and comes back; and the errors for a bad station file and a device of no clear line.
#include "clirun.h"
#include "testpeers.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QScopeGuard>
#include <QSet>
#include <QTest>

#include <csignal>

using namespace jumo;
using namespace jumo::test;

class tst_JumoctlStation : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void eachDeviceIsReadOnItsLine();
    void aCommandOfOneDeviceOpensOnlyItsLine();
    void monitorPollsTwoLinesAtOnce();
    void monitorCsvNamesTheLines();
    void scanSaysPerLineWhatItFound();
    void stationFileWithTwoLines();
    void readOnlyLineOfAStationFile();
    void badStationFile_data();
    void badStationFile();
    void deviceOfNoClearLine_data();
    void deviceOfNoClearLine();
    void lostLineShowsLineLostWhileTheOtherGoesOn();

private:
    QStringList lines() const
    {
        return {"--line", m_lineA.masterEnd() + ",name=a,baud=19200", "--line", m_lineB.masterEnd() + ",name=b,baud=19200"};
    }
    QString writeFile(const QString &name, const QByteArray &content);
    QString stationFile();

    QTemporaryDir m_dir;
    TestLine m_lineA;
    TestLine m_lineB;
    SimulatorPeer m_simA;
    SimulatorPeer m_simB;
};

void tst_JumoctlStation::initTestCase()
{
    qputenv("JUMO_MAP_PATH", "");
    qputenv("XDG_DATA_HOME", QByteArray(QDir::tempPath().toUtf8() + "/jumo-test-no-maps"));
    qputenv("JUMO_LOG_DIR", m_dir.filePath("logs").toUtf8());
    QVERIFY(m_lineA.start());
    QVERIFY(m_lineB.start());
    // The same address on both lines: only the line tells them apart.
    m_simA.line().addDevice(families().family("ipc300"), 1);
    m_simA.line().addDevice(families().family("tya200"), 2);
    m_simB.line().addDevice(families().family("ipc300"), 1);
    m_simB.line().addDevice(families().family("quantrol"), 3);
    QVERIFY(m_simA.start(m_lineA.deviceEnd(), {}));
    QVERIFY(m_simB.start(m_lineB.deviceEnd(), {}));
    QVERIFY(m_simA.line().device(1)->setNumber("input_setpoint", 11));
    QVERIFY(m_simB.line().device(1)->setNumber("input_setpoint", 22));
}

QString tst_JumoctlStation::writeFile(const QString &name, const QByteArray &content)
{
    QFile file(m_dir.filePath(name));
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size())
        return QString();
    return file.fileName();
}

QString tst_JumoctlStation::stationFile()
{
    return writeFile("hall.json", QStringLiteral(R"({
    "format": "jumo-station", "version": 1, "name": "hall",
    "lines": [
        { "name": "a", "port": "%1", "baud": 19200, "devices": ["ipc300@1", "tya200@2"] },
        { "name": "b", "port": "%2", "baud": 19200, "read_only": true, "devices": ["ipc300@1", "quantrol@3"] }
    ]
})")
                                          .arg(m_lineA.masterEnd(), m_lineB.masterEnd())
                                          .toUtf8());
}

void tst_JumoctlStation::eachDeviceIsReadOnItsLine()
{
    const Run a = run(QStringList{"read"} + lines() + QStringList{"a/ipc300@1", "input_setpoint"});
    QCOMPARE(a.code, 0);
    QVERIFY2(a.out.contains("input_setpoint = 11 "), qPrintable(a.out + a.err));
    const Run b = run(QStringList{"read"} + lines() + QStringList{"b/ipc300@1", "input_setpoint"});
    QCOMPARE(b.code, 0);
    QVERIFY2(b.out.contains("input_setpoint = 22 "), qPrintable(b.out + b.err));
    // A device the other line lacks: the identity check of line a finds no quantrol.
    const Run wrong = run(QStringList{"read"} + lines() + QStringList{"a/quantrol@3", "controller_status"});
    QCOMPARE(wrong.code, 1);
    QVERIFY2(wrong.out.contains("controller_status = no answer"), qPrintable(wrong.out + wrong.err));
}

void tst_JumoctlStation::aCommandOfOneDeviceOpensOnlyItsLine()
{
    const QStringList missingA{"--line", "/nonexistent/ttyUSB9,name=a", "--line", m_lineB.masterEnd() + ",name=b,baud=19200"};
    const Run b = run(QStringList{"read"} + missingA + QStringList{"b/ipc300@1", "input_setpoint"});
    QCOMPARE(b.code, 0);
    QVERIFY2(b.out.contains("input_setpoint = 22 "), qPrintable(b.out + b.err));
    QVERIFY2(b.err.isEmpty(), qPrintable(b.err));
    const Run a = run(QStringList{"read"} + missingA + QStringList{"a/ipc300@1", "input_setpoint"});
    QCOMPARE(a.code, 1);
    QVERIFY2(a.err.startsWith("line a: cannot open /nonexistent/ttyUSB9"), qPrintable(a.err));
}

void tst_JumoctlStation::monitorPollsTwoLinesAtOnce()
{
    const Run r = run(QStringList{"monitor"} + lines()
                      + QStringList{"a/ipc300@1", "b/ipc300@1", "b/quantrol@3", "--ids", "load_current", "--cycles", "2",
                                    "--jsonl"});
    QCOMPARE(r.code, 2);   // load_current is no quantrol entry
    QVERIFY2(r.err.contains("'load_current' is not a readable entry of quantrol"), qPrintable(r.err));

    const Run ok = run(QStringList{"monitor"} + lines()
                       + QStringList{"a/ipc300@1", "b/ipc300@1", "b/quantrol@3", "--cycles", "2", "--jsonl"});
    QCOMPARE(ok.code, 0);
    QHash<QString, int> records;
    for (const QString &line : ok.out.split('\n', Qt::SkipEmptyParts)) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        QCOMPARE(QStringList(o.keys()),
                 QStringList({"condition", "cycle_ms", "device", "line", "status", "time", "values"}));
        const QString device = o["device"].toString();
        QCOMPARE(o["line"].toString(), device.section('/', 0, 0));
        QCOMPARE(o["condition"].toString(), QString("online"));
        const QString id = device.endsWith("ipc300@1") ? "input_setpoint" : "controller_status";
        QCOMPARE(o["status"].toObject()[id].toString(), QString("ok"));
        if (device == "a/ipc300@1")
            QCOMPARE(o["values"].toObject()[id].toDouble(), 11.0);
        else if (device == "b/ipc300@1")
            QCOMPARE(o["values"].toObject()[id].toDouble(), 22.0);
        else
            QCOMPARE(device, QString("b/quantrol@3"));
        ++records[device];
    }
    QCOMPARE(records.size(), 3);
    for (auto it = records.cbegin(); it != records.cend(); ++it)
        QVERIFY2(it.value() >= 2, qPrintable(it.key()));
}

void tst_JumoctlStation::monitorCsvNamesTheLines()
{
    const Run r = run(QStringList{"monitor"} + lines()
                      + QStringList{"a/ipc300@1", "b/ipc300@1", "--ids", "input_setpoint", "--cycles", "1", "--csv"});
    QCOMPARE(r.code, 0);
    const QStringList rows = r.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(rows.first(), QString("time,device,id,value,unit,status"));
    QVERIFY2(rows.filter(",a/ipc300@1,input_setpoint,11,").size() >= 1, qPrintable(r.out));
    QVERIFY2(rows.filter(",b/ipc300@1,input_setpoint,22,").size() >= 1, qPrintable(r.out));
}

void tst_JumoctlStation::scanSaysPerLineWhatItFound()
{
    const Run r = run(QStringList{"scan"} + lines() + QStringList{"--from", "1", "--to", "4"});
    QCOMPARE(r.code, 0);
    QStringList found = r.out.split('\n', Qt::SkipEmptyParts);
    for (QString &line : found)
        line = line.section('\t', 0, 0);
    found.sort();
    QCOMPARE(found, QStringList({"a/ipc300@1", "a/tya200@2", "b/ipc300@1", "b/quantrol@3"}));
    QVERIFY2(r.err.contains("a: 2 device(s) found in ") && r.err.contains("b: 2 device(s) found in "), qPrintable(r.err));
    QVERIFY2(r.err.contains("4 device(s) found\n"), qPrintable(r.err));

    // A line where nothing answers is said and is a failure; the others are still listed.
    TestLine empty;
    QVERIFY(empty.start());
    const Run none = run(QStringList{"scan"} + lines()
                         + QStringList{"--line", empty.masterEnd() + ",name=c,baud=19200,retries=0", "--from", "1", "--to",
                                       "2"});
    QCOMPARE(none.code, 1);
    QVERIFY2(none.err.contains("c: 0 device(s) found in "), qPrintable(none.err));
    QVERIFY2(none.out.contains("a/ipc300@1\t") && none.out.contains("b/ipc300@1\t"), qPrintable(none.out));
}

void tst_JumoctlStation::stationFileWithTwoLines()
{
    const QString file = stationFile();
    QVERIFY(!file.isEmpty());
    const Run listed = run({"station", file});
    QCOMPARE(listed.code, 0);
    QVERIFY2(listed.out.startsWith("station hall: 2 line(s), 4 device(s)\n"), qPrintable(listed.out));
    QVERIFY2(listed.out.contains("line b: " + m_lineB.masterEnd() + " (19200 8N1, timeout from the families, 2 retry(s), "
                                                                    "read-only)\n"),
             qPrintable(listed.out));
    QVERIFY2(listed.out.contains("  b/quantrol@3\t"), qPrintable(listed.out));
    const Run checked = run({"station", "--check", file});
    QCOMPARE(checked.code, 0);
    QCOMPARE(checked.out, file + ": a good station file (2 line(s), 4 device(s))\n");

    // Without devices named, monitor polls every device of the file, on both lines.
    const Run r = run({"monitor", "--station", file, "--ids", "load_current", "--cycles", "1", "--jsonl"});
    QCOMPARE(r.code, 2);   // the file's quantrol has no load_current
    QVERIFY2(r.err.contains("'load_current' is not a readable entry of quantrol"), qPrintable(r.err));
    const Run all = run({"monitor", "--station", file, "--cycles", "1", "--jsonl"});
    QCOMPARE(all.code, 0);
    QSet<QString> devices;
    for (const QString &line : all.out.split('\n', Qt::SkipEmptyParts))
        devices.insert(QJsonDocument::fromJson(line.toUtf8()).object()["device"].toString());
    QCOMPARE(devices, (QSet<QString>{"a/ipc300@1", "a/tya200@2", "b/ipc300@1", "b/quantrol@3"}));

    const Run read = run({"read", "--station", file, "b/ipc300@1", "input_setpoint"});
    QCOMPARE(read.code, 0);
    QVERIFY2(read.out.contains("input_setpoint = 22 "), qPrintable(read.out + read.err));

    // A relative port path in a station file is meant from the file's folder, wherever
    // jumoctl is started.
    const QString relative = QDir(m_dir.path()).relativeFilePath(m_lineA.masterEnd());
    QVERIFY(relative.startsWith("../"));
    const QString moved = writeFile("relative.json", QStringLiteral(R"({"format": "jumo-station", "version": 1,
        "lines": [{"name": "a", "port": "%1", "baud": 19200}]})")
                                                             .arg(relative)
                                                             .toUtf8());
    const QString cwd = QDir::currentPath();
    QVERIFY(QDir::setCurrent(QDir::rootPath()));
    const Run relativeRead = run({"read", "--station", moved, "ipc300@1", "input_setpoint"});
    QVERIFY(QDir::setCurrent(cwd));
    QCOMPARE(relativeRead.code, 0);
    QVERIFY2(relativeRead.out.contains("input_setpoint = 11 "), qPrintable(relativeRead.out + relativeRead.err));
}

void tst_JumoctlStation::readOnlyLineOfAStationFile()
{
    const QString file = stationFile();
    const int framesB = m_simB.writeFrames();
    const Run refused = run({"write", "--station", file, "b/ipc300@1", "input_setpoint=33"});
    QCOMPARE(refused.code, 1);
    QVERIFY2(refused.err.contains("the line b is read-only (station file): nothing is written to the devices"),
             qPrintable(refused.err));
    QCOMPARE(m_simB.writeFrames(), framesB);
    QCOMPARE(m_simB.line().device(1)->number("input_setpoint"), 22.0);
    // The other line of the file writes.
    const Run written = run({"write", "--station", file, "a/ipc300@1", "input_setpoint=12"});
    QCOMPARE(written.code, 0);
    QCOMPARE(m_simA.line().device(1)->number("input_setpoint"), 12.0);
    QVERIFY(m_simA.line().device(1)->setNumber("input_setpoint", 11));
    // --read-only makes every line read-only.
    const int framesA = m_simA.writeFrames();
    const Run all = run(QStringList{"write", "--read-only"} + lines() + QStringList{"a/ipc300@1", "input_setpoint=13"});
    QCOMPARE(all.code, 1);
    QCOMPARE(m_simA.writeFrames(), framesA);
}

void tst_JumoctlStation::badStationFile_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("message");   // after "FILE: "
    QTest::newRow("unknown family") << QByteArray(R"({"format": "jumo-station", "version": 1, "lines": [
        {"name": "a", "port": "/dev/ttyS0", "devices": ["ipc400@1"]}]})")
                                    << "lines[0] (a): 'devices': 'ipc400@1': unknown family 'ipc400' (families: "
                                       "dtron300, ipc300, quantrol, tya200)";
    QTest::newRow("unknown key") << QByteArray(R"({"format": "jumo-station", "version": 1, "lines": [
        {"name": "a", "port": "/dev/ttyS0", "parity": "E"}]})")
                                 << "lines[0] (a): unknown key 'parity'";
    QTest::newRow("two lines of one name") << QByteArray(R"({"format": "jumo-station", "version": 1, "lines": [
        {"name": "a", "port": "/dev/ttyS0"}, {"name": "a", "port": "/dev/ttyS1"}]})")
                                           << "lines[1] (a): the line name 'a' is used by lines[0] too";
    QTest::newRow("no JSON") << QByteArray("lines: a") << "malformed JSON at byte 1: illegal value";
}

void tst_JumoctlStation::badStationFile()
{
    QFETCH(QByteArray, content);
    QFETCH(QString, message);
    const QString file = writeFile("bad.json", content);
    const Run checked = run({"station", file});
    QCOMPARE(checked.code, 2);
    QCOMPARE(checked.err, file + ": " + message + "\n");
    QVERIFY(checked.out.isEmpty());
    const Run read = run({"read", "--station", file, "a/ipc300@1", "input_setpoint"});
    QCOMPARE(read.code, 2);
    QCOMPARE(read.err, file + ": " + message + "\n");
    const Run missing = run({"monitor", "--station", m_dir.filePath("missing.json"), "--jsonl"});
    QCOMPARE(missing.code, 2);
    QCOMPARE(missing.err, m_dir.filePath("missing.json") + ": No such file or directory\n");
}

void tst_JumoctlStation::deviceOfNoClearLine_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("read without the line") << QStringList{"read", "ipc300@1", "input_setpoint"}
                                           << "'ipc300@1': which line? The station has the lines a, b: name it as "
                                              "LINE/ipc300@1, e.g. a/ipc300@1";
    QTest::newRow("monitor of an unknown line") << QStringList{"monitor", "a/ipc300@1", "c/ipc300@1", "--jsonl"}
                                                << "'c/ipc300@1': there is no line 'c' (lines: a, b)";
    QTest::newRow("broadcast without the line") << QStringList{"write", "ipc300@0", "input_setpoint=1", "--scan-first"}
                                                << "'ipc300@0': which line? The station has the lines a, b: name it as "
                                                   "LINE/ipc300@0, e.g. a/ipc300@0";
    QTest::newRow("backup without the line") << QStringList{"backup", "ipc300@1", "x.json"}
                                             << "'ipc300@1': which line? The station has the lines a, b: name it as "
                                                "LINE/ipc300@1, e.g. a/ipc300@1";
    QTest::newRow("two lines of one name") << QStringList{"read", "--line", "/dev/ttyS9,name=a", "a/ipc300@1", "x"}
                                           << "lines[2] (a): the line name 'a' is used by lines[0] too";
    QTest::newRow("a bad line spec") << QStringList{"read", "--line", "/dev/ttyS9,baud=12", "a/ipc300@1", "x"}
                                     << "--line '/dev/ttyS9,baud=12': 'baud' must be 4800, 9600, 19200 or 38400, not 12";
    QTest::newRow("--port with --line") << QStringList{"read", "--port", "/dev/ttyS9", "a/ipc300@1", "x"}
                                        << "give the lines one way: --port, --line or --station";
}

void tst_JumoctlStation::deviceOfNoClearLine()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const int framesA = m_simA.writeFrames();
    const Run r = run(args.mid(0, 1) + lines() + args.mid(1));
    QCOMPARE(r.code, 2);
    QCOMPARE(r.err, message + "\n");
    QCOMPARE(m_simA.writeFrames(), framesA);
}

void tst_JumoctlStation::lostLineShowsLineLostWhileTheOtherGoesOn()
{
    // The real program, so that its records can be read while it runs.
    QProcess monitor;
    monitor.setProcessChannelMode(QProcess::SeparateChannels);
    monitor.start(QStringLiteral(JUMOCTL_PATH),
                  QStringList{"monitor"} + lines()
                          + QStringList{"a/ipc300@1", "b/ipc300@1", "--ids", "input_setpoint", "--interval", "100",
                                        "--jsonl"});
    QVERIFY(monitor.waitForStarted());
    auto guard = qScopeGuard([&] {
        if (monitor.state() != QProcess::NotRunning) {
            monitor.kill();
            monitor.waitForFinished(5000);
        }
    });
    QList<QJsonObject> records;
    const auto readRecords = [&] {
        while (monitor.canReadLine())
            records << QJsonDocument::fromJson(monitor.readLine()).object();
        return records.size();
    };
    const auto count = [&](const QString &device, const QString &condition, qsizetype from = 0) {
        int n = 0;
        for (qsizetype i = from; i < records.size(); ++i)
            n += records[i]["device"].toString() == device && records[i]["condition"].toString() == condition;
        return n;
    };
    QTRY_VERIFY_WITH_TIMEOUT(readRecords() && count("a/ipc300@1", "online") >= 2 && count("b/ipc300@1", "online") >= 2,
                             30000);

    m_lineB.stop();   // socat of line b ends (its process, by its PID): the pty pair is gone
    QTRY_VERIFY_WITH_TIMEOUT(readRecords() && count("b/ipc300@1", "line_lost") == 1, 30000);
    qsizetype lost = 0;
    while (records[lost]["condition"].toString() != "line_lost")
        ++lost;
    const QJsonObject &record = records[lost];
    QCOMPARE(record["line"].toString(), QString("b"));
    QVERIFY(record["values"].toObject()["input_setpoint"].isNull());
    QCOMPARE(record["status"].toObject()["input_setpoint"].toString(), QString("line_lost"));
    QVERIFY(record["cycle_ms"].isNull());
    // Line a keeps going, with current values.
    QTRY_VERIFY_WITH_TIMEOUT(readRecords() && count("a/ipc300@1", "online", lost + 1) >= 3, 30000);
    QCOMPARE(count("b/ipc300@1", "online", lost + 1), 0);
    // (Line b may say more than once that it is lost while it tries to reopen its port.)
    for (qsizetype i = lost + 1; i < records.size(); ++i) {
        if (records[i]["device"].toString() == "a/ipc300@1")
            QCOMPARE(records[i]["values"].toObject()["input_setpoint"].toDouble(), 11.0);
    }
    QVERIFY(monitor.state() == QProcess::Running);

    // The adapter of line b is back: the bus reopens it by itself and its records resume.
    m_simB.stop();
    QVERIFY(m_lineB.restart());
    QVERIFY(m_simB.reopen());
    const qsizetype back = records.size();
    QTRY_VERIFY_WITH_TIMEOUT(readRecords() && count("b/ipc300@1", "online", back) >= 2, 30000);
    for (qsizetype i = back; i < records.size(); ++i) {
        if (records[i]["device"].toString() == "b/ipc300@1" && records[i]["condition"].toString() == "online")
            QCOMPARE(records[i]["values"].toObject()["input_setpoint"].toDouble(), 22.0);
    }

    ::kill(pid_t(monitor.processId()), SIGTERM);
    QTRY_VERIFY_WITH_TIMEOUT(monitor.state() == QProcess::NotRunning, 30000);
    QCOMPARE(monitor.exitCode(), 143);
    const QString err = QString::fromUtf8(monitor.readAllStandardError());
    QVERIFY2(err.contains("line b: line lost: "), qPrintable(err));
    QVERIFY2(err.contains("terminated: "), qPrintable(err));
}

QTEST_GUILESS_MAIN(tst_JumoctlStation)
#include "tst_jumoctl_station.moc"
