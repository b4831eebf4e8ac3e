// The table of an event log: newest record first at once, older ones as asked for (across
// rotated files, cut lines passed over), records appended by this program and by
// another on top as they come (through rotations), a filter over the shown texts found
// in every file, CSV export of the whole log. Checked by QAbstractItemModelTester.
#include "logs/eventlog.h"
#include "models/eventlogmodel.h"

#include <QAbstractItemModelTester>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimeZone>
#include <QJsonDocument>

#include <sys/stat.h>

using namespace jumo;

namespace {

const QStringList columns{"time", "device", "id", "state"};

QString timeOf(int n)
{
    return QDateTime(QDate(2024, 3, 1), QTime(0, 0), Qt::UTC).addSecs(n).toString(Qt::ISODateWithMs);
}

QByteArray record(int n, const QString &state = QStringLiteral("set"))
{
    return QJsonDocument(QJsonObject{{"time", timeOf(n)}, {"device", "ipc300@1"}, {"id", QStringLiteral("r%1").arg(n)},
                                     {"state", state}})
                   .toJson(QJsonDocument::Compact)
         + '\n';
}

bool writeFile(const QString &path, const QByteArray &data)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(data) == data.size();
}

// Records first..last, every one whose number is a multiple of `every` in the state
// "fuse failure".
QByteArray records(int first, int last, int every = 0)
{
    QByteArray out;
    for (int n = first; n <= last; ++n)
        out += record(n, every && n % every == 0 ? QStringLiteral("fuse failure") : QStringLiteral("set"));
    return out;
}

QString id(const EventLogModel &model, int row)
{
    return model.index(row, 2).data().toString();
}

// Asks for older records until there are none.
bool loadAll(EventLogModel &model)
{
    for (int round = 0; round < 1000; ++round) {
        if (!QTest::qWaitFor([&] { return !model.isLoading(); }, 20000))
            return false;
        if (!model.canFetchMore({}))
            return true;
        model.fetchMore({});
    }
    return false;
}

} // namespace

class tst_EventLogModel : public QObject
{
    Q_OBJECT

private slots:
    void newestFirstOlderOnDemand();
    void appendedRecordsComeOnTop();
    void anotherWritersRecordsAreFound();
    void rotationWhileShown();
    void filterSearchesEveryFile();
    void filterMatchesTheShownTime();
    void filterIgnoresKeys();
    void filteredAppends();
    void exportWritesTheWholeLog();
    void unreadableLogIsNamed();
};

void tst_EventLogModel::newestFirstOlderOnDemand()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    QVERIFY(writeFile(dir.filePath("journal-20240301T000000Z.jsonl"), records(0, 999) + "{\"id\":\"cut"));
    QVERIFY(writeFile(dir.filePath("journal-20240301T010000Z.jsonl"), records(1000, 1999) + "not a record\n\n"));
    QVERIFY(writeFile(path, records(2000, 2999) + "{\"id\":\"being written"));
    EventLog log(path);
    EventLogModel model(&log, columns, {"Time", "Device", "Id", "State"});
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QTRY_VERIFY(!model.isLoading());
    QVERIFY(model.rowCount() > 0 && model.rowCount() < 3000);   // the newest part only
    QCOMPARE(id(model, 0), QString("r2999"));
    QCOMPARE(model.headerData(2, Qt::Horizontal).toString(), QString("Id"));
    QVERIFY(model.canFetchMore({}));
    QVERIFY(loadAll(model));
    QVERIFY(model.isComplete());
    QCOMPARE(model.rowCount(), 3000);
    for (int row = 0; row < 3000; ++row)
        QCOMPARE(id(model, row), QStringLiteral("r%1").arg(2999 - row));
    // Shown in local time.
    QCOMPARE(model.index(2999, 0).data().toString(),
             QDateTime(QDate(2024, 3, 1), QTime(0, 0), Qt::UTC).toLocalTime().toString("yyyy-MM-dd HH:mm:ss.zzz"));
}

void tst_EventLogModel::appendedRecordsComeOnTop()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    QVERIFY(writeFile(path, records(0, 9)));
    EventLog log(path);
    EventLogModel model(&log, columns, {});
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QTRY_COMPARE(model.rowCount(), 10);
    for (int n = 10; n < 15; ++n)
        QVERIFY(log.append(QJsonObject{{"time", timeOf(n)}, {"id", QStringLiteral("r%1").arg(n)}}));
    QTRY_COMPARE(model.rowCount(), 15);
    for (int row = 0; row < 15; ++row)
        QCOMPARE(id(model, row), QStringLiteral("r%1").arg(14 - row));
}

void tst_EventLogModel::anotherWritersRecordsAreFound()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("write-audit.jsonl");
    EventLog hmi(path);
    EventLog jumoctl(path);   // another program on the same log
    EventLogModel model(&hmi, columns, {});
    QTRY_VERIFY(!model.isLoading());
    QCOMPARE(model.rowCount(), 0);
    QVERIFY(hmi.append(QJsonObject{{"id", "hmi 1"}}));
    QVERIFY(jumoctl.append(QJsonObject{{"id", "jumoctl 1"}}));
    QVERIFY(hmi.append(QJsonObject{{"id", "hmi 2"}}));
    QTRY_COMPARE(model.rowCount(), 3);
    QCOMPARE(id(model, 0), QString("hmi 2"));
    QCOMPARE(id(model, 1), QString("jumoctl 1"));
    QCOMPARE(id(model, 2), QString("hmi 1"));
}

void tst_EventLogModel::rotationWhileShown()
{
    // Records appended while the log rotates, by this program and by another: every one
    // is shown; rows stay readable when the rotation removes their file.
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    EventLog hmi(path);
    EventLog jumoctl(path);
    hmi.setRotation({250, 100});
    jumoctl.setRotation({250, 100});
    EventLogModel model(&hmi, columns, {});
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QTRY_VERIFY(!model.isLoading());
    for (int n = 0; n < 60; ++n) {
        EventLog &writer = n % 3 == 2 ? jumoctl : hmi;
        QVERIFY(writer.append(QJsonObject{{"time", timeOf(n)}, {"id", QStringLiteral("r%1").arg(n)}}));
        if (n % 7 == 0)
            QTest::qWait(5);   // lets a look at the log in now and then
    }
    QVERIFY(hmi.append(QJsonObject{{"time", timeOf(60)}, {"id", "r60"}}));
    QTRY_COMPARE(model.rowCount(), 61);
    QVERIFY(EventLog::files(path).size() > 10);
    // Now only one older file is kept: the others go, the rows they hold stay.
    hmi.setRotation({250, 1});
    for (int n = 61; n < 70; ++n) {
        QVERIFY(hmi.append(QJsonObject{{"time", timeOf(n)}, {"id", QStringLiteral("r%1").arg(n)}}));
        QTRY_COMPARE(model.rowCount(), n + 1);
    }
    QCOMPARE(EventLog::files(path).size(), 2);
    for (int row = 0; row < 70; ++row)
        QCOMPARE(id(model, row), QStringLiteral("r%1").arg(69 - row));
}

void tst_EventLogModel::filterSearchesEveryFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    QVERIFY(writeFile(dir.filePath("journal-20240301T000000Z.jsonl"), records(0, 4999, 1000)));
    QVERIFY(writeFile(path, records(5000, 9999, 1000)));
    EventLog log(path);
    EventLogModel model(&log, columns, {});
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QTRY_VERIFY(!model.isLoading());
    model.setFilter("FUSE");
    QVERIFY(loadAll(model));
    QCOMPARE(model.rowCount(), 10);
    for (int row = 0; row < 10; ++row)
        QCOMPARE(id(model, row), QStringLiteral("r%1").arg(9000 - 1000 * row));
    model.setFilter("r4321");
    QVERIFY(loadAll(model));
    QCOMPARE(model.rowCount(), 1);
    QCOMPARE(id(model, 0), QString("r4321"));
    model.setFilter(QString());
    QTRY_VERIFY(!model.isLoading());
    QCOMPARE(id(model, 0), QString("r9999"));
}

void tst_EventLogModel::filterMatchesTheShownTime()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    QVERIFY(writeFile(path, records(0, 7200)));   // two hours, a record a second
    EventLog log(path);
    EventLogModel model(&log, columns, {});
    QTRY_VERIFY(!model.isLoading());
    // As the table shows it: local time, to the second.
    const QString shown = QDateTime::fromString(timeOf(4000), Qt::ISODateWithMs).toLocalTime().toString("yyyy-MM-dd HH:mm:ss");
    model.setFilter(shown);
    QVERIFY(loadAll(model));
    QCOMPARE(model.rowCount(), 1);
    QCOMPARE(id(model, 0), QString("r4000"));
}

void tst_EventLogModel::filterIgnoresKeys()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    QVERIFY(writeFile(path, records(0, 99)));
    EventLog log(path);
    EventLogModel model(&log, columns, {});
    model.setFilter("device");   // a key in every line, a value in none
    QVERIFY(loadAll(model));
    QCOMPARE(model.rowCount(), 0);
    model.setFilter("IPC300@");
    QVERIFY(loadAll(model));
    QCOMPARE(model.rowCount(), 100);
}

void tst_EventLogModel::filteredAppends()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    QVERIFY(writeFile(path, records(0, 99, 10)));
    EventLog log(path);
    EventLogModel model(&log, columns, {});
    model.setFilter("fuse");
    QVERIFY(loadAll(model));
    QCOMPARE(model.rowCount(), 10);
    QVERIFY(log.append(QJsonObject{{"id", "r100"}, {"state", "set"}}));
    QVERIFY(log.append(QJsonObject{{"id", "r101"}, {"state", "fuse failure"}}));
    QTRY_COMPARE(model.rowCount(), 11);
    QCOMPARE(id(model, 0), QString("r101"));
}

void tst_EventLogModel::exportWritesTheWholeLog()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    QVERIFY(writeFile(dir.filePath("journal-20240301T000000Z.jsonl"), records(0, 2)));
    QVERIFY(writeFile(path, records(3, 4)));
    EventLog log(path);
    EventLogModel model(&log, {"id", "state"}, {});
    model.setFilter("r4");   // the export takes every record all the same
    QSignalSpy finished(&model, &EventLogModel::exportFinished);
    model.exportCsv(dir.filePath("out.csv"));
    QVERIFY(finished.wait(20000));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
    QCOMPARE(finished.at(0).at(1).toString(), "5 record(s) exported to " + dir.filePath("out.csv"));
    QFile csv(dir.filePath("out.csv"));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    QCOMPARE(csv.readAll(), QByteArray("id,state\nr0,set\nr1,set\nr2,set\nr3,set\nr4,set\n"));
}

void tst_EventLogModel::unreadableLogIsNamed()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    QVERIFY(::mkfifo(QFile::encodeName(path).constData(), 0600) == 0);
    EventLog log(path);
    EventLogModel model(&log, columns, {});
    QSignalSpy changed(&model, &EventLogModel::stateChanged);
    QTRY_VERIFY(!model.readError().isEmpty());
    QCOMPARE(model.readError(), "cannot read " + path + ": not a regular file");
    QCOMPARE(model.rowCount(), 0);
}

QTEST_GUILESS_MAIN(tst_EventLogModel)
#include "tst_eventlogmodel.moc"
