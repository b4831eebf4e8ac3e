// The history's parts without a bus: where it is kept, the one-minute rows, the steps a
// trend is drawn from, and the SQLite store (batches from its own thread, steps and gaps
// read back, the resolution following the span, a crash, thinning, a full disk).
#include "history/historydatabase.h"
#include "history/historylocation.h"
#include "history/historyreader.h"
#include "history/historyrecorder.h"
#include "history/minuterollup.h"
#include "history/sqlhistorystore.h"
#include "history/tracebuilder.h"
#include "smalldisk.h"

#include <QDateTime>
#include <QFile>
#include <QSignalSpy>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

namespace {

constexpr qint64 minute = 60000;

HistoryPoint point(qint64 timeMs, SampleState state, double value = qQNaN())
{
    HistoryPoint p;
    p.timeMs = timeMs;
    p.state = state;
    p.value = p.minimum = p.maximum = p.mean = value;
    return p;
}

HistorySample sample(int series, qint64 timeMs, SampleState state, double value = qQNaN())
{
    HistorySample s;
    s.series = series;
    s.timeMs = timeMs;
    s.state = state;
    s.value = value;
    return s;
}

HistorySettings fastSettings()
{
    HistorySettings settings;
    settings.batchIntervalMs = 50;
    settings.retryIntervalMs = 200;
    settings.maintenanceIntervalMs = 3600 * 1000;   // the tests say when
    return settings;
}

const HistoryKey key{QStringLiteral("hall-3"), QStringLiteral("line1"), QStringLiteral("ipc300@1")};

HistorySeriesInfo info(const QString &entry)
{
    // A map entry without a unit has a null QString, which is no NULL in the store.
    return HistorySeriesInfo{key, entry, true, entry == "load_voltage" ? QStringLiteral("V") : QString()};
}

// A whole minute some time ago, so that everything recorded lies in the past.
qint64 minutesAgo(int minutes)
{
    return (QDateTime::currentMSecsSinceEpoch() / minute - minutes) * minute;
}

// Waits until the store has written this many samples in all.
bool waitWritten(SqlHistoryStore &store, QSignalSpy &written, int samples)
{
    store.flush();
    auto total = [&] {
        int n = 0;
        for (const QList<QVariant> &args : std::as_const(written))
            n += args.at(0).toInt();
        return n;
    };
    for (int i = 0; i < 100 && total() < samples; ++i)
        written.wait(200);
    return total() >= samples;
}

} // namespace

class tst_History : public QObject
{
    Q_OBJECT

private slots:
    void locationParses_data();
    void locationParses();
    void passwordComesFromAFile();
    void changesBeyondPrecision_data();
    void changesBeyondPrecision();
    void minuteRowsKeepOnlyChanges();
    void minuteRowsEndAValueHeldTooLong();
    void traceDrawsStepsAndGaps();
    void traceJoinsLongSpansIntoBuckets();
    void storeGivesBackStepsAndGaps();
    void longSpansReadMinuteRows();
    void crashIsAGapAfterTheLastSample();
    void oldRawSamplesAreThinned();
    void fullDiskStopsRecordingAndKeepsWhatIsStored();
};

void tst_History::locationParses_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("shown");   // empty: refused
    QTest::addColumn<QString>("error");

    QTest::newRow("a file") << "/var/lib/jumo/history-hall.sqlite" << "/var/lib/jumo/history-hall.sqlite" << "";
    QTest::newRow("postgresql with user and port") << "postgresql://jumo@db.plant:5433/history"
                                                   << "postgresql://jumo@db.plant:5433/history" << "";
    QTest::newRow("postgres scheme, default port") << "postgres://db/history" << "postgresql://db:5432/history" << "";
    QTest::newRow("password refused") << "postgresql://jumo:secret@db/history" << ""
                                      << "'postgresql://jumo:***@db/history' is no history database";
    QTest::newRow("unknown scheme") << "mysql://db/history" << "" << "unknown scheme 'mysql'";
    QTest::newRow("no database") << "postgresql://db/" << "" << "name one database";
    QTest::newRow("empty") << "" << "" << "empty";
}

void tst_History::locationParses()
{
    QFETCH(QString, text);
    QFETCH(QString, shown);
    QFETCH(QString, error);
    QString why;
    const std::optional<HistoryLocation> location = HistoryLocation::parse(text, &why);
    QCOMPARE(location.has_value(), !shown.isEmpty());
    if (location)
        QCOMPARE(location->display(), shown);
    else
        QVERIFY2(why.contains(error), qPrintable(why));
    QVERIFY(!why.contains("secret"));
}

void tst_History::passwordComesFromAFile()
{
    QTemporaryDir dir;
    QFile file(dir.filePath("password"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("s3cret/@\r\nsecond line\n");
    file.close();
    QString error;
    const auto location = HistoryLocation::fromOptions({"postgresql://db/history", "jumo", file.fileName()}, &error);
    QVERIFY2(location, qPrintable(error));
    QCOMPARE(location->password, QString("s3cret/@"));
    QCOMPARE(location->username, QString("jumo"));
    QVERIFY(!location->display().contains("s3cret"));

    QVERIFY(!HistoryLocation::fromOptions({"postgresql://db/history", {}, dir.filePath("missing")}, &error));
    QVERIFY2(error.startsWith("cannot read the password file " + dir.filePath("missing") + ": "), qPrintable(error));
    // A password is for a server, not for a file.
    QVERIFY(!HistoryLocation::fromOptions({"history.sqlite", {}, file.fileName()}, &error));
    QVERIFY2(error.contains("not for the file history.sqlite"), qPrintable(error));
}

void tst_History::changesBeyondPrecision_data()
{
    QTest::addColumn<int>("type");
    QTest::addColumn<QString>("precision");
    QTest::addColumn<double>("before");
    QTest::addColumn<double>("after");
    QTest::addColumn<bool>("kept");

    const int f = int(ValueType::Float);
    QTest::newRow("one decimal: noise below it") << f << "decimals:1" << 230.01 << 230.04 << false;
    QTest::newRow("one decimal: a tenth") << f << "decimals:1" << 230.01 << 230.11 << true;
    QTest::newRow("four significant: noise") << f << "significant:4" << 1820.1 << 1820.4 << false;
    QTest::newRow("four significant: a unit") << f << "significant:4" << 1820.1 << 1821.2 << true;
    QTest::newRow("four significant, small values") << f << "significant:4" << 0.012341 << 0.012352 << true;
    QTest::newRow("integer: any change") << int(ValueType::UInt16) << "decimals:0" << 3.0 << 4.0 << true;
    QTest::newRow("integer: the same") << int(ValueType::UInt16) << "decimals:0" << 3.0 << 3.0 << false;
    QTest::newRow("a value after none") << f << "decimals:1" << qQNaN() << 1.0 << true;
}

void tst_History::changesBeyondPrecision()
{
    QFETCH(int, type);
    QFETCH(QString, precision);
    QFETCH(double, before);
    QFETCH(double, after);
    QFETCH(bool, kept);
    RegisterEntry entry;
    entry.type = ValueType(type);
    const QStringList parts = precision.split(':');
    entry.precision = parts[0] == "decimals" ? DisplayPrecision::decimals(parts[1].toInt())
                                             : DisplayPrecision::significant(parts[1].toInt());
    const HistorySample a = sample(0, 0, std::isnan(before) ? SampleState::Timeout : SampleState::Ok, before);
    const HistorySample b = sample(0, 1, SampleState::Ok, after);
    QCOMPARE(HistoryRecorder::differs(entry, a, b), kept);
}

void tst_History::minuteRowsKeepOnlyChanges()
{
    MinuteRollup rollup(11 * minute);
    const qint64 m = 100 * minute;
    const QList<MinuteRollup::Sample> samples{
        {7, m + 0, SampleState::Ok, 10, {}},
        {7, m + 10000, SampleState::Ok, 20, {}},
        {7, m + 40000, SampleState::Ok, 20, {}},     // the same again
        {7, m + minute + 30000, SampleState::Ok, 20, {}},   // a heartbeat in the next minute
    };
    const QList<MinuteRollup::Row> rows = rollup.roll(samples, m + 3 * minute);
    QCOMPARE(rows.size(), 1);
    QCOMPARE(rows[0].series, 7);
    QCOMPARE(rows[0].point.timeMs, m);
    QCOMPARE(rows[0].point.minimum, 10.0);
    QCOMPARE(rows[0].point.maximum, 20.0);
    QCOMPARE(rows[0].point.value, 20.0);
    // 10 for 10 s, 20 for the other 50 s of the minute.
    QCOMPARE(rows[0].point.mean, (10.0 * 10 + 20.0 * 50) / 60);
    rollup.accept();
    // The next pass knows what held: the same value again gives no row.
    QVERIFY(rollup.roll({{7, m + 3 * minute + 5000, SampleState::Ok, 20, {}}}, m + 4 * minute).isEmpty());
}

void tst_History::minuteRowsEndAValueHeldTooLong()
{
    MinuteRollup rollup(3 * minute);
    const qint64 m = 100 * minute;
    const QList<MinuteRollup::Row> rows = rollup.roll({{7, m + 1000, SampleState::Ok, 5, {}}}, m + 10 * minute);
    QCOMPARE(rows.size(), 2);
    QCOMPARE(rows[0].point.state, SampleState::Ok);
    QCOMPARE(rows[1].point.state, SampleState::NotRecorded);
    QCOMPARE(rows[1].point.timeMs, m + 1000 + 3 * minute);
}

void tst_History::traceDrawsStepsAndGaps()
{
    const qint64 from = 1000 * minute;
    const QList<TraceBuilder::Step> steps{
        {point(from - 10000, SampleState::Ok, 5), true},   // what held at the start
        {point(from + 10000, SampleState::Ok, 7), true},
        {point(from + 15000, SampleState::Ok, 7), true},   // a heartbeat: no new step
        {point(from + 20000, SampleState::LineLost), true},
        {point(from + 30000, SampleState::Ok, 8), true},
    };
    qint64 bucket = -1;
    HistoryTrace trace;
    trace.endMs = from + minute;
    trace.points = TraceBuilder::build(steps, from, trace.endMs, 11 * minute, 1000, &bucket);
    QCOMPARE(bucket, 0);
    QCOMPARE(trace.points.size(), 4);
    QCOMPARE(trace.points[0].timeMs, from);
    QCOMPARE(trace.points[0].value, 5.0);
    QCOMPARE(trace.points[1].value, 7.0);
    QCOMPARE(trace.points[2].state, SampleState::LineLost);
    QCOMPARE(trace.points[3].value, 8.0);
    const QList<HistoryGap> gaps = trace.gaps();
    QCOMPARE(gaps.size(), 1);
    QCOMPARE(gaps[0].startMs, from + 20000);
    QCOMPARE(gaps[0].endMs, from + 30000);
    QCOMPARE(gaps[0].state, SampleState::LineLost);
}

void tst_History::traceJoinsLongSpansIntoBuckets()
{
    const qint64 from = 1000 * minute;
    QList<TraceBuilder::Step> steps;
    for (int i = 0; i < 1000; ++i)
        steps.append({point(from + i * 1000, SampleState::Ok, i % 2 ? 1.0 : -1.0), true});
    steps.append({point(from + 1000 * 1000, SampleState::Offline), true});
    qint64 bucket = 0;
    const QList<HistoryPoint> points = TraceBuilder::build(steps, from, from + 1100 * 1000, 11 * minute, 10, &bucket);
    QCOMPARE(bucket, 110 * 1000);
    QVERIFY2(points.size() <= 30, qPrintable(QString::number(points.size())));
    QCOMPARE(points.first().minimum, -1.0);
    QCOMPARE(points.first().maximum, 1.0);
    QCOMPARE(points.last().state, SampleState::Offline);
}

void tst_History::storeGivesBackStepsAndGaps()
{
    QTemporaryDir dir;
    const HistoryLocation location = HistoryLocation::file(HistoryLocation::defaultFile(dir.path(), key.station));
    const qint64 t0 = minutesAgo(30);
    {
        SqlHistoryStore store(location, key.station, fastSettings());
        QSignalSpy written(&store, &SqlHistoryStore::written);
        store.start();
        const int voltage = store.series(info("load_voltage"));
        QCOMPARE(store.series(info("load_voltage")), voltage);
        store.record(sample(voltage, t0, SampleState::Ok, 230));
        store.record(sample(voltage, t0 + 60000, SampleState::Ok, 231));
        store.record(sample(voltage, t0 + 120000, SampleState::Offline));
        store.record(sample(voltage, t0 + 180000, SampleState::Ok, 229));
        store.record(sample(store.series(info("status")), t0, SampleState::Ok, 1));
        QVERIFY(waitWritten(store, written, 5));

        // Answered from the store's reader thread, by signal.
        QSignalSpy answered(&store, &HistorySource::samplesAnswered);
        const quint64 request = store.requestSamples({key, "load_voltage", t0 - minute, t0 + 10 * minute, 1000});
        QVERIFY(answered.wait(10000));
        QCOMPARE(answered.at(0).at(0).value<quint64>(), request);
        const HistoryTrace trace = answered.at(0).at(1).value<HistoryTrace>();
        QVERIFY2(trace.ok(), qPrintable(trace.error));
        QCOMPARE(trace.resolution, HistoryTrace::Resolution::Raw);
        QCOMPARE(trace.points.size(), 4);
        QCOMPARE(trace.gaps().size(), 1);
        QCOMPARE(trace.gaps()[0].startMs, t0 + 120000);
        QCOMPARE(trace.gaps()[0].endMs, t0 + 180000);
    }
    // The store closed: every series ends as "not recorded"; the file reads back as it was.
    HistoryReader reader(location);
    QString error;
    QVERIFY2(reader.open(&error), qPrintable(error));
    const auto series = reader.series(key.station, &error);
    QVERIFY(series);
    QCOMPARE(series->size(), 2);
    QCOMPARE(series->at(1).entry, QString("status"));
    QCOMPARE(series->at(1).unit, QString(""));
    QCOMPARE(series->at(0).entry, QString("load_voltage"));
    QCOMPARE(series->at(0).unit, QString("V"));
    const HistoryTrace trace = reader.samples(key, "load_voltage", t0 + 30000, t0 + 40 * minute, 1000);
    QVERIFY2(trace.ok(), qPrintable(trace.error));
    QCOMPARE(trace.points.size(), 5);
    QCOMPARE(trace.points[0].timeMs, t0 + 30000);   // what held at the start, moved there
    QCOMPARE(trace.points[0].value, 230.0);
    QCOMPARE(trace.points[1].value, 231.0);
    QCOMPARE(trace.points[2].state, SampleState::Offline);
    QCOMPARE(trace.points[3].value, 229.0);
    QCOMPARE(trace.points[4].state, SampleState::NotRecorded);
    // An entry never recorded: nothing, and no error.
    const HistoryTrace none = reader.samples(key, "power", t0, t0 + minute, 100);
    QVERIFY(none.ok());
    QVERIFY(none.points.isEmpty());
}

void tst_History::longSpansReadMinuteRows()
{
    QTemporaryDir dir;
    const HistoryLocation location = HistoryLocation::file(dir.filePath("h.sqlite"));
    const qint64 t0 = minutesAgo(3 * 60 + 5);
    SqlHistoryStore store(location, key.station, fastSettings());
    QSignalSpy written(&store, &SqlHistoryStore::written);
    QSignalSpy maintained(&store, &SqlHistoryStore::maintained);
    store.start();
    const int series = store.series(info("load_voltage"));
    // Three hours, a sample every 10 s, a saw tooth of 0..5 each minute.
    const int count = 3 * 60 * 6;
    for (int i = 0; i < count; ++i)
        store.record(sample(series, t0 + i * 10000, SampleState::Ok, i % 6));
    QVERIFY(waitWritten(store, written, count));
    store.maintainNow();
    QVERIFY(maintained.wait(20000));
    QVERIFY(maintained.last().at(0).toLongLong() >= t0 + 3 * 60 * minute);

    HistoryReader reader(location);
    const HistoryTrace longTrace = reader.samples(key, "load_voltage", t0, t0 + 3 * 60 * minute, 60);
    QVERIFY2(longTrace.ok(), qPrintable(longTrace.error));
    QCOMPARE(longTrace.resolution, HistoryTrace::Resolution::Minute);
    QCOMPARE(longTrace.bucketMs, 3 * minute);
    QVERIFY2(longTrace.points.size() <= 3 * 60, qPrintable(QString::number(longTrace.points.size())));
    for (const HistoryPoint &p : longTrace.points) {
        QCOMPARE(p.minimum, 0.0);
        QCOMPARE(p.maximum, 5.0);
        QCOMPARE(p.mean, 2.5);
    }
    const HistoryTrace shortTrace = reader.samples(key, "load_voltage", t0, t0 + 10 * minute, 1000);
    QCOMPARE(shortTrace.resolution, HistoryTrace::Resolution::Raw);
    QCOMPARE(shortTrace.points.size(), 60);
}

void tst_History::crashIsAGapAfterTheLastSample()
{
    QTemporaryDir dir;
    const HistoryLocation location = HistoryLocation::file(dir.filePath("h.sqlite"));
    const qint64 t0 = minutesAgo(60);
    {
        SqlHistoryStore store(location, key.station, fastSettings());
        QSignalSpy written(&store, &SqlHistoryStore::written);
        store.start();
        const int series = store.series(info("load_voltage"));
        store.record(sample(series, t0, SampleState::Ok, 230));
        QVERIFY(waitWritten(store, written, 1));
    }
    {
        // As if the program had died: the end it wrote on closing is not there.
        HistoryDatabase db(location);
        QString error;
        QVERIFY2(db.open(true, &error), qPrintable(error));
        QVERIFY(db.exec(QString("DELETE FROM history_raw WHERE state = %1").arg(int(SampleState::NotRecorded)), &error));
    }
    {
        HistorySettings settings = fastSettings();
        SqlHistoryStore store(location, key.station, settings);
        QSignalSpy maintained(&store, &SqlHistoryStore::maintained);
        store.start();
        store.maintainNow();   // answered after the start's crash marks
        QVERIFY(maintained.wait(10000));
        HistoryReader reader(location);
        const HistoryTrace trace = reader.samples(key, "load_voltage", t0, t0 + 30 * minute, 1000);
        QCOMPARE(trace.points.size(), 2);
        QCOMPARE(trace.points[1].state, SampleState::NotRecorded);
        QCOMPARE(trace.points[1].timeMs, t0 + settings.heartbeatMs);
    }
}

void tst_History::oldRawSamplesAreThinned()
{
    QTemporaryDir dir;
    const HistoryLocation location = HistoryLocation::file(dir.filePath("h.sqlite"));
    HistorySettings settings = fastSettings();
    settings.rawRetentionMs = 60 * minute;
    const qint64 t0 = minutesAgo(3 * 60);
    SqlHistoryStore store(location, key.station, settings);
    QSignalSpy written(&store, &SqlHistoryStore::written);
    QSignalSpy maintained(&store, &SqlHistoryStore::maintained);
    store.start();
    const int series = store.series(info("load_voltage"));
    const int count = 3 * 60 - 5;
    for (int i = 0; i < count; ++i)
        store.record(sample(series, t0 + i * minute, SampleState::Ok, i));
    QVERIFY(waitWritten(store, written, count));
    store.maintainNow();
    QVERIFY(maintained.wait(20000));

    HistoryReader reader(location);
    QString error;
    int raw = 0;
    int minuteRows = 0;
    qint64 firstRawMs = -1;
    QVERIFY2(reader.records(key, "load_voltage", t0, t0 + 4 * 60 * minute,
                            [&](const HistoryRecord &r) {
                                (r.minute ? minuteRows : raw)++;
                                if (!r.minute && firstRawMs < 0)
                                    firstRawMs = r.point.timeMs;
                                return true;
                            },
                            &error),
             qPrintable(error));
    // Raw samples older than an hour are gone, their one-minute rows stay.
    QVERIFY2(firstRawMs >= QDateTime::currentMSecsSinceEpoch() - 61 * minute, qPrintable(QString::number(firstRawMs)));
    QVERIFY(raw > 50 && raw <= 61);
    QVERIFY(minuteRows >= count - 61);
    // The old hours still read, from the one-minute rows.
    const HistoryTrace old = reader.samples(key, "load_voltage", t0, t0 + 30 * minute, 1000);
    QCOMPARE(old.resolution, HistoryTrace::Resolution::Minute);
    QCOMPARE(old.points.size(), 30);
    QCOMPARE(old.points[10].value, 10.0);
}

void tst_History::fullDiskStopsRecordingAndKeepsWhatIsStored()
{
    SmallDisk disk;
    if (!disk.mount(1024))
        QSKIP("no small tmpfs can be mounted here (needs root)");
    const HistoryLocation location = HistoryLocation::file(disk.filePath("h.sqlite"));
    const qint64 t0 = minutesAgo(30);
    {
        SqlHistoryStore store(location, key.station, fastSettings());
        QSignalSpy written(&store, &SqlHistoryStore::written);
        QSignalSpy stopped(&store, &HistoryStore::recordingStopped);
        QSignalSpy resumed(&store, &HistoryStore::recordingResumed);
        store.start();
        const int series = store.series(info("load_voltage"));
        for (int i = 0; i < 100; ++i)
            store.record(sample(series, t0 + i * 1000, SampleState::Ok, i));
        QVERIFY(waitWritten(store, written, 100));
        disk.fill();
        for (int round = 0; round < 50 && stopped.isEmpty(); ++round) {
            for (int i = 0; i < 500; ++i)
                store.record(sample(series, t0 + 100000 + round * 10000 + i, SampleState::Ok, i));
            store.flush();
            stopped.wait(200);
        }
        QCOMPARE(stopped.size(), 1);
        const QString message = stopped.at(0).at(0).toString();
        QVERIFY2(message.startsWith("History not recorded: cannot write the history " + location.path)
                         && message.contains("full"),
                 qPrintable(message));
        QVERIFY(!store.isRecording());
        disk.free();
        QVERIFY(resumed.wait(10000));
        QVERIFY(store.isRecording());
    }
    HistoryDatabase db(location);
    QString error;
    QVERIFY2(db.open(false, &error), qPrintable(error));
    QSqlQuery check = db.query();
    QVERIFY(check.exec("PRAGMA integrity_check") && check.next());
    QCOMPARE(check.value(0).toString(), QString("ok"));
    db.close();
    HistoryReader reader(location);
    const HistoryTrace trace = reader.samples(key, "load_voltage", t0, t0 + 100000, 1000);
    QVERIFY2(trace.ok(), qPrintable(trace.error));
    QCOMPARE(trace.points.size(), 100);
    QCOMPARE(trace.points[99].value, 99.0);
    // The time the disk was full is a gap: not recorded.
    const HistoryTrace after = reader.samples(key, "load_voltage", t0 + 99000, t0 + 30 * minute, 1000);
    QVERIFY(!after.gaps().isEmpty());
    QCOMPARE(after.gaps().first().state, SampleState::NotRecorded);
}

QTEST_GUILESS_MAIN(tst_History)
#include "tst_history.moc"
