// jumoctl history: a station's recorded values as CSV, JSON and text, found through the
// station file or a database URL, and every wrong request refused with a reason.
#include "clirun.h"
#include "history/sqlhistorystore.h"
#include "logs/eventlog.h"

#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace jumo;
using namespace jumo::test;

class tst_JumoctlHistory : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void csvHasEveryRecord();
    void jsonHasEveryRecord();
    void stationFileFindsItsHistory();
    void deviceTextsKeepTheTerminal();
    void refused_data();
    void refused();

private:
    QString iso(qint64 ms) const { return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs); }

    QTemporaryDir m_dir;
    QString m_db;
    QString m_station;
    qint64 m_t0 = 0;
};

void tst_JumoctlHistory::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_t0 = (QDateTime::currentMSecsSinceEpoch() / 60000 - 60) * 60000;
    m_station = m_dir.filePath("hall.json");
    QFile station(m_station);
    QVERIFY(station.open(QIODevice::WriteOnly));
    station.write(R"({"format": "jumo-station", "version": 1, "name": "hall", "lines": [
        {"name": "a", "port": "/dev/ttyUSB0", "devices": ["ipc300@1"]},
        {"name": "b", "port": "/dev/ttyUSB1", "devices": ["ipc300@1"]}]})");
    station.close();

    // The station's history where --station looks for it: in the log folder.
    const QString folder = EventLog::defaultFolder();
    QVERIFY(!folder.isEmpty());
    m_db = HistoryLocation::defaultFile(folder, "hall");
    QFile::remove(m_db);
    HistorySettings settings;
    settings.batchIntervalMs = 20;
    SqlHistoryStore store(HistoryLocation::file(m_db), "hall", settings);
    QSignalSpy written(&store, &SqlHistoryStore::written);
    store.start();
    const int voltage = store.series({{"hall", "a", "ipc300@1"}, "load_voltage", true, "V"});
    const int name = store.series({{"hall", "a", "ipc300@1"}, "device_name", false, ""});
    const int other = store.series({{"hall", "b", "ipc300@1"}, "load_voltage", true, "V"});
    HistorySample s;
    s.series = voltage;
    s.timeMs = m_t0;
    s.state = SampleState::Ok;
    s.value = 230.5;
    store.record(s);
    s.timeMs = m_t0 + 1000;
    s.state = SampleState::LineLost;
    s.value = qQNaN();
    store.record(s);
    s.series = name;
    s.timeMs = m_t0;
    s.state = SampleState::Ok;
    s.text = "IPC300, \"A\"";
    store.record(s);
    s.series = other;
    s.text.clear();
    s.value = 1;
    store.record(s);
    // A device text that would clear the terminal and turn it red.
    s.series = store.series({{"hall", "b", "ipc300@1"}, "device_name", false, ""});
    s.text = "\x1b[2J\x1b[31mEVIL\aline";
    store.record(s);
    store.flush();
    QTRY_VERIFY_WITH_TIMEOUT(!written.isEmpty(), 20000);
}

void tst_JumoctlHistory::csvHasEveryRecord()
{
    const Run r = run({"history", "--db", m_db, "a/ipc300@1", "load_voltage", "device_name", "--from", iso(m_t0 - 1000),
                       "--to", iso(m_t0 + 60000), "--csv"});
    QCOMPARE(r.err, QString());
    QCOMPARE(r.code, 0);
    const QString expected = "time,device,entry,value,unit,state,validity,resolution,minimum,mean,maximum\n"
            + iso(m_t0) + ",hall/a/ipc300@1,load_voltage,230.5,V,ok,current,raw,,,\n"
            + iso(m_t0 + 1000) + ",hall/a/ipc300@1,load_voltage,,V,line_lost,unknown,raw,,,\n"
            + iso(m_t0) + ",hall/a/ipc300@1,device_name,\"IPC300, \"\"A\"\"\",,ok,current,raw,,,\n";
    QCOMPARE(r.out, expected);
}

void tst_JumoctlHistory::jsonHasEveryRecord()
{
    const Run r = run({"history", "--db", m_db, "hall/a/ipc300@1", "load_voltage", "--from", iso(m_t0),
                       "--to", iso(m_t0 + 1000), "--json"});
    QCOMPARE(r.code, 0);
    const QJsonObject doc = QJsonDocument::fromJson(r.out.toUtf8()).object();
    QCOMPARE(doc.value("device").toString(), QString("hall/a/ipc300@1"));
    const QJsonArray entries = doc.value("entries").toArray();
    QCOMPARE(entries.size(), 1);
    QCOMPARE(entries[0].toObject().value("unit").toString(), QString("V"));
    const QJsonArray records = entries[0].toObject().value("records").toArray();
    QCOMPARE(records.size(), 1);   // [from, to): the line loss lies at --to
    QCOMPARE(records[0].toObject().value("time").toString(), iso(m_t0));
    QCOMPARE(records[0].toObject().value("value").toDouble(), 230.5);
    QCOMPARE(records[0].toObject().value("state").toString(), QString("ok"));
    QCOMPARE(records[0].toObject().value("validity").toString(), QString("current"));
}

void tst_JumoctlHistory::stationFileFindsItsHistory()
{
    const Run r = run({"history", "--station", m_station, "a/ipc300@1", "load_voltage", "--from", "-2h"});
    QCOMPARE(r.err, QString());
    QCOMPARE(r.code, 0);
    const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 2);
    QVERIFY2(lines[0].endsWith("  load_voltage  230.5 V  ok"), qPrintable(lines[0]));
    QVERIFY2(lines[1].endsWith("  load_voltage  -  line_lost"), qPrintable(lines[1]));
}

void tst_JumoctlHistory::deviceTextsKeepTheTerminal()
{
    for (const QString &format : {QString(), QStringLiteral("--csv")}) {
        QStringList arguments{"history", "--db", m_db, "b/ipc300@1", "device_name", "--from", iso(m_t0 - 1000),
                              "--to", iso(m_t0 + 60000)};
        if (!format.isEmpty())
            arguments << format;
        const Run r = run(arguments);
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains("\\x1b[2J\\x1b[31mEVIL\\x07line"), qPrintable(r.out));
        QVERIFY2(!r.out.contains(QChar(0x1b)) && !r.out.contains(QChar(0x07)), qPrintable(format));
    }
}

void tst_JumoctlHistory::refused_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("error");

    QTest::newRow("a device of two lines") << QStringList{"--db", "DB", "ipc300@1", "load_voltage"} << 2
                                           << "ipc300@1 names several devices: hall/a/ipc300@1, hall/b/ipc300@1";
    QTest::newRow("a device never recorded") << QStringList{"--db", "DB", "tya200@2", "setpoint"} << 1
                                             << "nothing of tya200@2 is recorded";
    QTest::newRow("an entry never recorded") << QStringList{"--db", "DB", "a/ipc300@1", "power"} << 2
                                             << "power is not recorded for hall/a/ipc300@1 (recorded: device_name, load_voltage)";
    QTest::newRow("station and database") << QStringList{"--db", "DB", "--station", "S", "a/ipc300@1", "power"} << 2
                                          << "give exactly one of --station FILE and --db URL";
    QTest::newRow("neither station nor database") << QStringList{"a/ipc300@1", "power"} << 2
                                                  << "give exactly one of --station FILE and --db URL";
    QTest::newRow("no time") << QStringList{"--db", "DB", "a/ipc300@1", "power", "--from", "yesterday"} << 2
                             << "--from: 'yesterday' is no time";
    QTest::newRow("end before start") << QStringList{"--db", "DB", "a/ipc300@1", "power", "--from", "-1h", "--to", "-2h"}
                                      << 2 << "--to must be after --from";
    QTest::newRow("csv and json") << QStringList{"--db", "DB", "a/ipc300@1", "power", "--csv", "--json"} << 2
                                  << "give at most one of --csv and --json";
    QTest::newRow("no such file") << QStringList{"--db", "/nonexistent/h.sqlite", "a/ipc300@1", "power"} << 1
                                  << "no history at /nonexistent/h.sqlite";
    QTest::newRow("a password in the URL") << QStringList{"--db", "postgresql://u:pw@db/h", "a/ipc300@1", "power"} << 2
                                           << "a password in the address can be read by every user";
    QTest::newRow("no entry") << QStringList{"--db", "DB", "a/ipc300@1"} << 2 << "wrong number of arguments";
    // SQLite would wait in open() for a writer to the FIFO, for ever.
    QTest::newRow("a FIFO") << QStringList{"--db", "FIFO", "a/ipc300@1", "power"} << 1 << "not a regular file";
    QTest::newRow("a folder") << QStringList{"--db", "FOLDER", "a/ipc300@1", "power"} << 1 << "not a regular file";
}

void tst_JumoctlHistory::refused()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, code);
    QFETCH(QString, error);
    arguments.replaceInStrings(QRegularExpression("^DB$"), m_db);
    arguments.replaceInStrings(QRegularExpression("^S$"), m_station);
    QTemporaryDir dir;
    QVERIFY(::mkfifo(QFile::encodeName(dir.filePath("fifo.sqlite")).constData(), 0600) == 0);
    arguments.replaceInStrings(QRegularExpression("^FIFO$"), dir.filePath("fifo.sqlite"));
    arguments.replaceInStrings(QRegularExpression("^FOLDER$"), dir.path());
    const Run r = run(QStringList{"history"} + arguments);
    QCOMPARE(r.code, code);
    QVERIFY2(r.err.contains(error), qPrintable(r.err));
    QCOMPARE(r.out, QString());
}

QTEST_GUILESS_MAIN(tst_JumoctlHistory)
#include "tst_jumoctl_history.moc"

