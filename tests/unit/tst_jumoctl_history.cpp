// jumoctl history: a station's recorded values as CSV, JSON and text, found through the
// station file or a database URL, and every wrong request refused with a reason.
#include "clirun.h"
#include "history/historydatabase.h"
#include "history/sqlhistorystore.h"
#include "historyjsonwriter.h"
#include "logs/eventlog.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSignalSpy>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

#include <ctime>
#include <sys/resource.h>
#include <sys/stat.h>

using namespace jumo;
using namespace jumo::test;

namespace {

// The process's local time zone (TZ) for one test, its own again after it.
class TimeZone
{
public:
    explicit TimeZone(const QByteArray &zone) : m_was(qgetenv("TZ")), m_wasSet(qEnvironmentVariableIsSet("TZ"))
    {
        qputenv("TZ", zone);
        ::tzset();
    }
    ~TimeZone()
    {
        if (m_wasSet)
            qputenv("TZ", m_was);
        else
            qunsetenv("TZ");
        ::tzset();
    }

private:
    QByteArray m_was;
    bool m_wasSet;
};

} // namespace

class tst_JumoctlHistory : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void csvHasEveryRecord();
    void jsonHasEveryRecord();
    void jsonWriterGivesQJsonDocumentsText_data();
    void jsonWriterGivesQJsonDocumentsText();
    void jsonWriterWritesEachRecordAsItComes();
    void jsonOfALongHistoryInLittleMemory();
    void stationFileFindsItsHistory();
    void deviceTextsKeepTheTerminal();
    void refused_data();
    void refused();
    void refusesWhatIsNoHistory_data();
    void refusesWhatIsNoHistory();
    void damagedFilesAreNamed_data();
    void damagedFilesAreNamed();
    void localTimesTheClocksSkipOrRepeat_data();
    void localTimesTheClocksSkipOrRepeat();
    void textTellsTheRepeatedHourApart();
    void readingLeavesNoFileBeside();
    void readingALiveHistory();
    void unknownStatesAreNotGood();
    void signalEndsAConnectThatHangs_data();
    void signalEndsAConnectThatHangs();
    void signalStopsALongRead();

private:
    // A history of one entry, "long/a/ipc300@1" load_voltage, a sample every stepMs from t0.
    static bool makeLongHistory(const QString &path, int samples, qint64 t0, qint64 stepMs = 1000);
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

void tst_JumoctlHistory::jsonWriterGivesQJsonDocumentsText_data()
{
    QTest::addColumn<QJsonObject>("document");

    const QJsonObject raw{{"time", "2026-12-03T08:00:00.000Z"}, {"state", "ok"}, {"validity", "current"},
                          {"resolution", "raw"}, {"value", 230.5}};
    const QJsonObject gap{{"time", "2026-12-03T08:00:01.000Z"}, {"state", "line_lost"}, {"validity", "unknown"},
                          {"resolution", "raw"}, {"value", QJsonValue()}};
    const QJsonObject minute{{"time", "2026-12-03T07:00:00.000Z"}, {"state", "ok"}, {"validity", "current"},
                             {"resolution", "minute"}, {"value", 1}, {"minimum", -0.25}, {"mean", 1e-7},
                             {"maximum", 12345678.5}};
    const QJsonObject text{{"time", "2026-12-03T08:00:00.000Z"}, {"state", "ok"}, {"validity", "current"},
                           {"resolution", "raw"}, {"value", "IPC300, \"A\"\\\x1b[2J\u00e9\u20ac"}};
    auto entry = [](const QString &name, const QString &unit, const QJsonArray &records) {
        return QJsonObject{{"entry", name}, {"unit", unit}, {"records", records}};
    };
    auto document = [](const QJsonArray &entries) {
        return QJsonObject{{"device", "hall/a/ipc300@1"},
                           {"from", "2026-12-03T07:00:00.000Z"},
                           {"to", "2026-12-03T09:00:00.000Z"},
                           {"entries", entries}};
    };
    QTest::newRow("one record") << document({entry("load_voltage", "V", {raw})});
    QTest::newRow("no records") << document({entry("load_voltage", "V", {})});
    QTest::newRow("a gap's null value") << document({entry("load_voltage", "V", {raw, gap})});
    QTest::newRow("one-minute rows") << document({entry("load_voltage", "V", {minute, raw})});
    QTest::newRow("texts with quotes, escapes and umlauts") << document({entry("device_name", "\"", {text})});
    QTest::newRow("entries with and without records")
            << document({entry("load_voltage", "V", {raw, gap}), entry("power", "W", {}), entry("device_name", "", {text})});
}

// The streamed document is the one QJsonDocument gave when jumoctl built it whole.
void tst_JumoctlHistory::jsonWriterGivesQJsonDocumentsText()
{
    QFETCH(QJsonObject, document);
    QString written;
    QTextStream out(&written);
    HistoryJsonWriter writer(out);
    writer.begin(document.value("device").toString(), document.value("from").toString(),
                 document.value("to").toString());
    for (const QJsonValue &e : document.value("entries").toArray()) {
        writer.beginEntry(e.toObject().value("entry").toString(), e.toObject().value("unit").toString());
        for (const QJsonValue &r : e.toObject().value("records").toArray())
            writer.record(r.toObject());
        writer.endEntry();
    }
    writer.end();
    out.flush();
    QCOMPARE(written, QString::fromUtf8(QJsonDocument(document).toJson(QJsonDocument::Indented)));
}

void tst_JumoctlHistory::jsonWriterWritesEachRecordAsItComes()
{
    QString written;
    QTextStream out(&written);
    HistoryJsonWriter writer(out);
    writer.begin("hall/a/ipc300@1", iso(m_t0), iso(m_t0 + 60000));
    writer.beginEntry("load_voltage", "V");
    for (int i = 0; i < 3; ++i) {
        writer.record({{"time", iso(m_t0 + i * 1000)}, {"value", 230 + i}});
        out.flush();
        QVERIFY2(written.contains("\"time\": \"" + iso(m_t0 + i * 1000) + '"'), qPrintable(written));
        QVERIFY2(!written.contains(']'), qPrintable(written));
    }
}

// 100000 samples in at most 128 MiB of heap: built whole, the document took 2.2 KB a
// record (2.2 GB for a million); streamed, jumoctl needs under 32 MiB for any number.
void tst_JumoctlHistory::jsonOfALongHistoryInLittleMemory()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("long.sqlite");
    const int samples = 100000;
    QVERIFY(makeLongHistory(path, samples, m_t0));
    QProcess p;
    p.setChildProcessModifier([] {
        const rlimit limit{128 << 20, 128 << 20};
        ::setrlimit(RLIMIT_DATA, &limit);
    });
    p.start(QStringLiteral(JUMOCTL_PATH), {"history", "--db", path, "long/a/ipc300@1", "load_voltage", "--from",
                                          iso(m_t0), "--to", iso(m_t0 + samples * 1000LL), "--json"});
    QVERIFY(p.waitForFinished(300000));
    QCOMPARE(p.readAllStandardError(), QByteArray());
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 0);
    QJsonParseError parsed;
    const QJsonDocument doc = QJsonDocument::fromJson(p.readAllStandardOutput(), &parsed);
    QCOMPARE(parsed.errorString(), QJsonParseError().errorString());
    const QJsonArray records = doc.object().value("entries").toArray().at(0).toObject().value("records").toArray();
    QCOMPARE(records.size(), samples);
    QCOMPARE(records.last().toObject().value("time").toString(), iso(m_t0 + (samples - 1) * 1000LL));
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

void tst_JumoctlHistory::refusesWhatIsNoHistory_data()
{
    QTest::addColumn<bool>("ours");   // starts as a history, else as an empty SQLite database
    QTest::addColumn<QStringList>("statements");
    QTest::addColumn<QString>("error");

    QTest::newRow("an SQLite database of another program")
            << false << QStringList{"CREATE TABLE notes (id INTEGER PRIMARY KEY, text TEXT)"}
            << "is not a JUMO history file: an SQLite database without the history's tables";
    QTest::newRow("a history without its samples") << true << QStringList{"DROP TABLE history_raw"}
                                                   << "is damaged: no table history_raw";
    QTest::newRow("a history's table without a column")
            << true << QStringList{"ALTER TABLE history_series DROP COLUMN is_number"}
            << "is damaged: the table history_series lacks the column(s) is_number";
    QTest::newRow("a history's table of another shape")
            << true
            << QStringList{"DROP TABLE history_minute", "CREATE TABLE history_minute (series BIGINT, t BIGINT, v REAL)"}
            << "is damaged: the table history_minute lacks the column(s) state, value, minimum, maximum, mean, text_value";
    QTest::newRow("a history without its schema version") << true << QStringList{"DELETE FROM history_meta"}
                                                           << "is damaged: it names no schema version";
    QTest::newRow("a schema version that is no number")
            << true << QStringList{"UPDATE history_meta SET value = 'one' WHERE name = 'schema'"}
            << "is damaged: 'one' is no schema version";
}

// A file that is an SQLite database but no history of ours, or one with its tables
// changed, is named so, as a wrong input; never an SQL driver's "No query".
void tst_JumoctlHistory::refusesWhatIsNoHistory()
{
    QFETCH(bool, ours);
    QFETCH(QStringList, statements);
    QFETCH(QString, error);
    QTemporaryDir dir;
    const QString path = dir.filePath("h.sqlite");
    if (ours)
        QVERIFY(makeLongHistory(path, 10, m_t0));
    {
        QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "changer");
        db.setDatabaseName(path);
        QVERIFY(db.open());
        for (const QString &statement : std::as_const(statements)) {
            QSqlQuery q(db);
            QVERIFY2(q.exec(statement), qPrintable(statement));
        }
        db.close();
    }
    QSqlDatabase::removeDatabase("changer");
    const Run r = run({"history", "--db", path, "long/a/ipc300@1", "load_voltage", "--from", iso(m_t0)});
    QCOMPARE(r.err, "jumoctl history: " + path + ' ' + error + '\n');
    QCOMPARE(r.code, 2);
    QCOMPARE(r.out, QString());
}

void tst_JumoctlHistory::damagedFilesAreNamed_data()
{
    QTest::addColumn<QString>("damage");
    QTest::addColumn<QString>("error");

    QTest::newRow("cut off at half its size") << "half" << "is damaged: it ends after ";
    QTest::newRow("cut off inside a page") << "inside a page" << "is damaged: it ends inside a page (";
    QTest::newRow("a page overwritten") << "overwritten" << "is damaged: database disk image is malformed";
    QTest::newRow("a text file") << "text" << "is not a JUMO history file: it is not an SQLite database";
    QTest::newRow("an empty file") << "empty" << "is not a JUMO history file: it is empty";
}

// A damaged file is named damaged, a wrong input (2), whether its header or SQLite finds
// the damage: never "holds no history", and never a read that ends early as if it were all.
void tst_JumoctlHistory::damagedFilesAreNamed()
{
    QFETCH(QString, damage);
    QFETCH(QString, error);
    QTemporaryDir dir;
    const QString path = dir.filePath("h.sqlite");
    const int samples = 20000;
    QVERIFY(makeLongHistory(path, samples, m_t0));
    QFile file(path);
    const qint64 size = file.size();
    QVERIFY(size > 50 * 4096);
    if (damage == "half") {
        QVERIFY(file.resize(size / 2 / 4096 * 4096));
    } else if (damage == "inside a page") {
        QVERIFY(file.resize(size / 2 + 100));
    } else if (damage == "overwritten") {
        QVERIFY(file.open(QIODevice::ReadWrite));
        QVERIFY(file.seek(size * 3 / 4 / 4096 * 4096));
        QCOMPARE(file.write(QByteArray(4096, '\xff')), 4096);
        file.close();
    } else {
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        if (damage == "text")
            file.write("time,device,entry,value\n");
        file.close();
    }
    const Run r = run({"history", "--db", path, "long/a/ipc300@1", "load_voltage", "--from", iso(m_t0), "--to",
                       iso(m_t0 + samples * 1000LL)});
    QVERIFY2(r.err.startsWith("jumoctl history: " + path + ' ' + error), qPrintable(r.err));
    QCOMPARE(r.code, 2);
}

void tst_JumoctlHistory::localTimesTheClocksSkipOrRepeat_data()
{
    QTest::addColumn<QString>("from");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("start");   // the span's start in UTC, as the JSON gives it
    QTest::addColumn<QString>("error");

    // Europe/Berlin: on 2026-03-29 the clocks go from 02:00 to 03:00, on 2026-10-25 from
    // 03:00 (+02:00) back to 02:00 (+01:00).
    QTest::newRow("a time the clocks skip")
            << "2026-03-29T02:30" << 2 << QString()
            << "jumoctl history: --from: 2026-03-29T02:30 does not exist in local time (Europe/Berlin): the clocks "
               "skip it; give it with its offset, such as 2026-03-29T02:30+01:00, or in UTC, such as "
               "2026-03-29T01:30:00Z\n";
    QTest::newRow("a time the clocks show twice is the first")
            << "2026-10-25T02:30" << 0 << "2026-10-25T00:30:00.000Z"
            << "jumoctl history: --from: 2026-10-25T02:30 is twice in local time (Europe/Berlin), the clocks go back: "
               "taken as the first, 2026-10-25T02:30+02:00; the second is 2026-10-25T02:30+01:00\n";
    QTest::newRow("the second, by its offset") << "2026-10-25T02:30+01:00" << 0 << "2026-10-25T01:30:00.000Z"
                                               << QString();
    QTest::newRow("in UTC") << "2026-03-29T01:30Z" << 0 << "2026-03-29T01:30:00.000Z" << QString();
    QTest::newRow("a local time before the change") << "2026-03-29T01:30" << 0 << "2026-03-29T00:30:00.000Z"
                                                    << QString();
    QTest::newRow("a local time after the change") << "2026-03-29T03:30" << 0 << "2026-03-29T01:30:00.000Z"
                                                   << QString();
    QTest::newRow("a date") << "2026-10-25" << 0 << "2026-10-24T22:00:00.000Z" << QString();
}

void tst_JumoctlHistory::localTimesTheClocksSkipOrRepeat()
{
    QFETCH(QString, from);
    QFETCH(int, code);
    QFETCH(QString, start);
    QFETCH(QString, error);
    const TimeZone berlin("Europe/Berlin");
    const Run r = run({"history", "--db", m_db, "a/ipc300@1", "load_voltage", "--from", from, "--to",
                       "2026-12-31T00:00Z", "--json"});
    QCOMPARE(r.err, error);
    QCOMPARE(r.code, code);
    if (code == 0)
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object().value("from").toString(), start);
}

// The text shows local time with its offset: the two 02:30 of the night the clocks go
// back are two different times, and CSV and JSON give UTC.
void tst_JumoctlHistory::textTellsTheRepeatedHourApart()
{
    const TimeZone berlin("Europe/Berlin");
    QTemporaryDir dir;
    const QString path = dir.filePath("h.sqlite");
    const qint64 first = QDateTime::fromString("2026-10-25T00:30:00Z", Qt::ISODate).toMSecsSinceEpoch();
    QVERIFY(makeLongHistory(path, 2, first, 3600 * 1000));
    QStringList arguments{"history", "--db", path, "long/a/ipc300@1", "load_voltage", "--from", "2026-10-25T00:00Z",
                          "--to", "2026-10-25T03:00Z"};
    Run r = run(arguments);
    QCOMPARE(r.err, QString());
    QCOMPARE(r.code, 0);
    QCOMPARE(r.out, QString("2026-10-25 02:30:00.000+02:00  load_voltage  200 V  ok\n"
                            "2026-10-25 02:30:00.000+01:00  load_voltage  200.1 V  ok\n"));
    r = run(arguments << "--csv");
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("\n2026-10-25T00:30:00.000Z,") && r.out.contains("\n2026-10-25T01:30:00.000Z,"),
             qPrintable(r.out));
}

static QStringList filesIn(const QTemporaryDir &dir)
{
    return QDir(dir.path()).entryList(QDir::Files, QDir::Name);
}

// A history nobody writes (a copy, a station stopped) is read without a -wal or -shm
// file made beside it: SQLite's read-only connection to a file in WAL mode left both.
void tst_JumoctlHistory::readingLeavesNoFileBeside()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("h.sqlite");
    QVERIFY(makeLongHistory(path, 100, m_t0));
    QCOMPARE(filesIn(dir), QStringList{"h.sqlite"});
    const QFileInfo before(path);
    for (const QString format : {"--csv", "--json", "--csv"}) {
        const Run r = run({"history", "--db", path, "long/a/ipc300@1", "load_voltage", "--from", iso(m_t0), "--to",
                           iso(m_t0 + 100000), format});
        QCOMPARE(r.err, QString());
        QCOMPARE(r.code, 0);
        if (format == "--csv")
            QCOMPARE(r.out.count('\n'), 101);
        else
            QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8())["entries"][0]["records"].toArray().size(), 100);
        QCOMPARE(filesIn(dir), QStringList{"h.sqlite"});
    }
    QCOMPARE(QFileInfo(path).lastModified(), before.lastModified());
}

// A station's history while its recorder writes it: jumoctl reads what was committed
// last (through the writer's -wal file), and when the recorder stops no file is left.
void tst_JumoctlHistory::readingALiveHistory()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("history-live.sqlite");
    const QStringList arguments{"history", "--db", path, "live/a/ipc300@1", "load_voltage", "--from", iso(m_t0),
                                "--to", iso(m_t0 + 60000), "--csv"};
    {
        HistorySettings settings;
        settings.batchIntervalMs = 20;
        SqlHistoryStore store(HistoryLocation::file(path), "live", settings);
        QSignalSpy written(&store, &SqlHistoryStore::written);
        store.start();
        HistorySample s;
        s.series = store.series({{"live", "a", "ipc300@1"}, "load_voltage", true, "V"});
        s.state = SampleState::Ok;
        for (int i = 0; i < 3; ++i) {
            s.timeMs = m_t0 + i * 1000;
            s.value = 230 + i;
            store.record(s);
            store.flush();
            QVERIFY(written.wait(20000));
            const Run r = run(arguments);
            QCOMPARE(r.err, QString());
            QCOMPARE(r.code, 0);
            QCOMPARE(r.out.count('\n'), 1 + i + 1);   // the header and every sample so far
            QVERIFY2(r.out.contains(QString(",live/a/ipc300@1,load_voltage,%1,V,ok,").arg(230 + i)), qPrintable(r.out));
        }
    }
    QCOMPARE(filesIn(dir), QStringList{"history-live.sqlite"});
    // The recorder's stop (marked at the time it stopped), read from the file it left.
    const Run r = run(QStringList(arguments.mid(0, 7)) << "--to" << "now" << "--csv");
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains(",not_recorded,"), qPrintable(r.out));
    QCOMPARE(filesIn(dir), QStringList{"history-live.sqlite"});
}

// A state column's value that this version does not know (a newer version's number, a
// hand-made file's text, a fraction) is shown as unknown_state, said so on stderr, and
// never read as ok (a text was 0) or as a state it is not (2.5 was invalid, 99 not_recorded).
void tst_JumoctlHistory::unknownStatesAreNotGood()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("h.sqlite");
    QVERIFY(makeLongHistory(path, 6, m_t0));
    {
        QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "changer");
        db.setDatabaseName(path);
        QVERIFY(db.open());
        const QStringList states{"99", "'ok'", "''", "2.5", "-1", "4"};
        for (int i = 0; i < states.size(); ++i) {
            QSqlQuery q(db);
            QVERIFY(q.exec(QString("UPDATE history_raw SET state = %1 WHERE t = %2").arg(states[i]).arg(m_t0 + i * 1000)));
        }
        db.close();
    }
    QSqlDatabase::removeDatabase("changer");
    const Run r = run({"history", "--db", path, "long/a/ipc300@1", "load_voltage", "--from", iso(m_t0), "--to",
                       iso(m_t0 + 6000), "--csv"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.err, QString("jumoctl history: load_voltage: 5 record(s) with a state this version does not know, "
                            "shown as unknown_state (validity unknown)\n"));
    const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 7);
    for (int i = 1; i <= 5; ++i)
        QVERIFY2(lines[i].endsWith(",V,unknown_state,unknown,raw,,,"), qPrintable(lines[i]));
    QVERIFY2(lines[6].endsWith(",V,stale,stale,raw,,,"), qPrintable(lines[6]));   // 4, as it should be
}

void tst_JumoctlHistory::signalEndsAConnectThatHangs_data()
{
    QTest::addColumn<int>("signal");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("word");

    QTest::newRow("Ctrl-C") << SIGINT << 130 << "interrupted";
    QTest::newRow("SIGTERM") << SIGTERM << 143 << "terminated";
    QTest::newRow("a closed terminal") << SIGHUP << 129 << "hangup";
}

// A PostgreSQL server that takes the connection and never answers held jumoctl in Qt's
// connect for its 10 s timeout, deaf to Ctrl-C, and then it exited 1.
void tst_JumoctlHistory::signalEndsAConnectThatHangs()
{
    QFETCH(int, signal);
    QFETCH(int, code);
    QFETCH(QString, word);
    if (!QSqlDatabase::isDriverAvailable("QPSQL"))
        QSKIP("Qt's QPSQL driver is not installed (libqt6sql6-psql)");
    QTcpServer silent;
    QVERIFY(silent.listen(QHostAddress::LocalHost));
    QSignalSpy connected(&silent, &QTcpServer::newConnection);
    QProcess p;
    p.start(QStringLiteral(JUMOCTL_PATH), {"history", "--db", QString("postgresql://127.0.0.1:%1/h").arg(silent.serverPort()),
                                          "ipc300@1", "load_voltage"});
    QVERIFY(p.waitForStarted(30000));
    QVERIFY(connected.wait(30000));   // jumoctl waits in the connect now
    QCOMPARE(::kill(pid_t(p.processId()), signal), 0);
    QVERIFY(p.waitForFinished(60000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(QString::fromUtf8(p.readAllStandardError()),
             QString("jumoctl history: %1: nothing was read (opening postgresql://127.0.0.1:%2/h)\n")
                     .arg(word)
                     .arg(silent.serverPort()));
    QCOMPARE(p.exitCode(), code);
}

// A signal stops a long read before its next record, with what was printed flushed and
// counted, as the line commands stop: jumoctl read on to the end before.
void tst_JumoctlHistory::signalStopsALongRead()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("long.sqlite");
    const int samples = 200000;
    QVERIFY(makeLongHistory(path, samples, m_t0));
    QProcess p;
    p.start(QStringLiteral(JUMOCTL_PATH), {"history", "--db", path, "long/a/ipc300@1", "load_voltage", "--from",
                                          iso(m_t0), "--to", iso(m_t0 + samples * 1000LL), "--csv"});
    // The first records are out; what follows waits for the pipe, which this test does
    // not read until the signal is sent.
    QVERIFY(p.waitForReadyRead(60000));
    QCOMPARE(::kill(pid_t(p.processId()), SIGINT), 0);
    QVERIFY(p.waitForFinished(120000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    const QStringList lines = QString::fromUtf8(p.readAllStandardOutput()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(p.exitCode(), 130);
    QCOMPARE(err, QString("jumoctl history: interrupted: %1 record(s) printed\n").arg(lines.size() - 1));
    QVERIFY2(lines.size() - 1 < samples, qPrintable(err));
    QVERIFY(lines.last().endsWith(",ok,current,raw,,,"));   // whole records only
}

bool tst_JumoctlHistory::makeLongHistory(const QString &path, int samples, qint64 t0, qint64 stepMs)
{
    HistoryDatabase db(HistoryLocation::file(path));
    QString error;
    const bool ok = db.open(true, &error)
            && db.exec("INSERT INTO history_series (id, station, line, device, entry, is_number, unit) "
                       "VALUES (1, 'long', 'a', 'ipc300@1', 'load_voltage', 1, 'V')",
                       &error)
            && db.exec(QString("WITH RECURSIVE n(i) AS (SELECT 0 UNION ALL SELECT i + 1 FROM n WHERE i < %1) "
                               "INSERT INTO history_raw (series, t, state, value) "
                               "SELECT 1, %2 + i * %3, 0, 200 + (i % 1000) * 0.1 FROM n")
                               .arg(samples - 1)
                               .arg(t0)
                               .arg(stepMs),
                       &error);
    if (!ok)
        qWarning() << error;
    return ok;
}

QTEST_GUILESS_MAIN(tst_JumoctlHistory)
#include "tst_jumoctl_history.moc"

