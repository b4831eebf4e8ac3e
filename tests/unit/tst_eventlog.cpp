// Event logs (alarm journal, audit log) keep their records across restarts, survive a
// line cut by a crash, and export CSV.
#include "logs/eventlog.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace jumo;

class tst_EventLog : public QObject
{
    Q_OBJECT

private slots:
    void recordsSurviveARestart();
    void aCutLineIsSkipped();
    void csvExportQuotes();
    void appendOnlyDoesNotRead();
    void failedAppendIsReported_data();
    void failedAppendIsReported();
    void fifoLogIsNotWaitedFor();
};

void tst_EventLog::recordsSurviveARestart()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    {
        EventLog log(path);
        log.append(QJsonObject{{"device", "ipc300@1"}, {"state", "set"}});
        log.append(QJsonObject{{"device", "ipc300@1"}, {"state", "cleared"}});
        QVERIFY(log.lastError().isEmpty());
    }
    EventLog again(path);
    QCOMPARE(again.records().size(), 2);
    QCOMPARE(again.records().at(1).value("state").toString(), QString("cleared"));
    QVERIFY(QDateTime::fromString(again.records().at(0).value("time").toString(), Qt::ISODateWithMs).isValid());
}

void tst_EventLog::aCutLineIsSkipped()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("audit.jsonl");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"entry\":\"a\"}\n{\"entry\":\"b\"}\n{\"entry\":\"c");
    file.close();
    EventLog log(path);
    QCOMPARE(log.records().size(), 2);
    log.append(QJsonObject{{"entry", "d"}});
    EventLog again(path);
    QCOMPARE(again.records().size(), 3);
    QCOMPARE(again.records().last().value("entry").toString(), QString("d"));
}

void tst_EventLog::csvExportQuotes()
{
    QTemporaryDir dir;
    EventLog log(QString{});
    log.append(QJsonObject{{"time", "t1"}, {"message", "refused: exception 3, \"out of range\""}});
    QVERIFY(log.exportCsv(dir.filePath("out.csv"), {"time", "message"}));
    QFile f(dir.filePath("out.csv"));
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(), QByteArray("time,message\nt1,\"refused: exception 3, \"\"out of range\"\"\"\n"));
    QString error;
    QVERIFY(!log.exportCsv("/nonexistent/dir/out.csv", {"time"}, &error));
    QVERIFY(error.contains("cannot write"));
}

void tst_EventLog::appendOnlyDoesNotRead()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("audit.jsonl");
    EventLog(path).append(QJsonObject{{"entry", "a"}});
    EventLog appendOnly(path, nullptr, EventLog::Open::AppendOnly);
    QCOMPARE(appendOnly.records().size(), 0);
    appendOnly.append(QJsonObject{{"entry", "b"}});
    QCOMPARE(EventLog(path).records().size(), 2);
}

void tst_EventLog::failedAppendIsReported_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("reason");
    QTest::newRow("the log is a folder") << "folder" << "Is a directory";
    QTest::newRow("the log folder is a file") << "file" << "Not a directory";
    QTest::newRow("the log is /dev/full") << "full" << "not a regular file";
}

void tst_EventLog::failedAppendIsReported()
{
    QFETCH(QString, kind);
    QFETCH(QString, reason);
    QTemporaryDir dir;
    QString path = dir.filePath("write-audit.jsonl");
    if (kind == "folder") {
        QVERIFY(QDir().mkpath(path));
    } else if (kind == "file") {
        QFile blocker(dir.filePath("logs"));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        path = dir.filePath("logs/write-audit.jsonl");
    } else {
        QVERIFY(QFile::link("/dev/full", path));
    }
    EventLog log(path, nullptr, EventLog::Open::AppendOnly);
    QSignalSpy failed(&log, &EventLog::writeFailed);
    QVERIFY(!log.append(QJsonObject{{"device", "ipc300@1"}, {"result", "confirmed"}}));
    QCOMPARE(failed.count(), 1);
    QVERIFY2(failed.at(0).at(0).toString().startsWith("cannot write " + path), qPrintable(failed.at(0).at(0).toString()));
    QVERIFY2(log.lastError().contains(reason), qPrintable(log.lastError()));
}

void tst_EventLog::fifoLogIsNotWaitedFor()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("write-audit.jsonl");
    QVERIFY(::mkfifo(QFile::encodeName(path).constData(), 0600) == 0);
    const EventLog log(path);   // a plain open() would wait for a writer
    QVERIFY(log.records().isEmpty());
    QVERIFY2(log.lastError().contains("not a regular file"), qPrintable(log.lastError()));
}

QTEST_GUILESS_MAIN(tst_EventLog)
#include "tst_eventlog.moc"
