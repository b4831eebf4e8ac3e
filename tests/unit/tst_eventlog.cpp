// Event logs (alarm journal, audit log) keep their records across restarts, survive a
// line cut by a crash, rotate by size keeping the newest files, lose nothing when two
// programs append and rotate at once, report every record a full disk or a file size
// limit keeps out (and the first one kept again), and export CSV.
#include "logs/eventlog.h"
#include "logs/eventlogreader.h"
#include "logs/eventlogscanner.h"
#include "logrecords.h"
#include "smalldisk.h"

#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <sys/resource.h>
#include <sys/stat.h>
#include <thread>

using namespace jumo;
using namespace jumo::test;

namespace {

QByteArray contents(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class tst_EventLog : public QObject
{
    Q_OBJECT

private slots:
    void recordsSurviveARestart();
    void aCutLineIsSkipped();
    void csvExportQuotes();
    void csvExportTakesEveryFile();
    void failedAppendIsReported_data();
    void failedAppendIsReported();
    void fifoLogIsNotWaitedFor();
    void rotationKeepsTheNewestFiles();
    void rotationSettings_data();
    void rotationSettings();
    void twoWritersLoseNothing();
    void fullDiskIsReportedAndRecovered();
    void fileSizeLimitIsReported();
    void readerGoesBackAcrossFiles();
    void linesBackwardAreLinesForward_data();
    void linesBackwardAreLinesForward();
    void defaultFolderNeedsAHome_data();
    void defaultFolderNeedsAHome();
};

void tst_EventLog::recordsSurviveARestart()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    {
        EventLog log(path);
        QVERIFY(log.append(QJsonObject{{"device", "ipc300@1"}, {"state", "set"}}));
        QVERIFY(log.append(QJsonObject{{"device", "ipc300@1"}, {"state", "cleared"}}));
        QVERIFY(log.lastError().isEmpty());
    }
    const QList<QJsonObject> again = logRecords(path);
    QCOMPARE(again.size(), 2);
    QCOMPARE(again.at(1).value("state").toString(), QString("cleared"));
    QVERIFY(QDateTime::fromString(again.at(0).value("time").toString(), Qt::ISODateWithMs).isValid());
}

void tst_EventLog::aCutLineIsSkipped()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("audit.jsonl");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"entry\":\"a\"}\n{\"entry\":\"b\"}\n{\"entry\":\"c");
    file.close();
    QCOMPARE(logRecords(path).size(), 2);
    EventLog(path).append(QJsonObject{{"entry", "d"}});
    const QList<QJsonObject> again = logRecords(path);
    QCOMPARE(again.size(), 3);
    QCOMPARE(again.last().value("entry").toString(), QString("d"));
    QVERIFY(contents(path).contains("{\"entry\":\"c\n{"));   // the new record on a line of its own
}

void tst_EventLog::csvExportQuotes()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("audit.jsonl");
    EventLog(path).append(QJsonObject{{"time", "t1"}, {"message", "refused: exception 3, \"out of range\""}});
    const std::atomic_int query{1};
    EventLogScanner scanner(path, {"time", "message"}, &query);
    QSignalSpy finished(&scanner, &EventLogScanner::exportFinished);
    scanner.exportCsv(dir.filePath("out.csv"));
    QCOMPARE(finished.count(), 1);
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
    QCOMPARE(contents(dir.filePath("out.csv")), QByteArray("time,message\nt1,\"refused: exception 3, \"\"out of range\"\"\"\n"));
    scanner.exportCsv("/nonexistent/dir/out.csv");
    QCOMPARE(finished.count(), 2);
    QVERIFY(!finished.at(1).at(0).toBool());
    QVERIFY(finished.at(1).at(1).toString().startsWith("cannot write /nonexistent/dir/out.csv"));
}

void tst_EventLog::csvExportTakesEveryFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("journal.jsonl");
    EventLog log(path);
    log.setRotation({60, 100});
    for (int i = 0; i < 10; ++i)
        QVERIFY(log.append(QJsonObject{{"time", QString::number(i)}, {"id", QStringLiteral("record %1").arg(i)}}));
    QVERIFY(EventLog::files(path).size() > 3);
    const std::atomic_int query{1};
    EventLogScanner scanner(path, {"time", "id"}, &query);
    QSignalSpy finished(&scanner, &EventLogScanner::exportFinished);
    scanner.exportCsv(dir.filePath("out.csv"));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
    QByteArray expected = "time,id\n";
    for (int i = 0; i < 10; ++i)
        expected += QByteArray::number(i) + ",record " + QByteArray::number(i) + '\n';
    QCOMPARE(contents(dir.filePath("out.csv")), expected);
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
    EventLog log(path);
    QSignalSpy failed(&log, &EventLog::writeFailed);
    QSignalSpy appended(&log, &EventLog::appended);
    QVERIFY(!log.append(QJsonObject{{"device", "ipc300@1"}, {"result", "confirmed"}}));
    QCOMPARE(failed.count(), 1);
    QCOMPARE(appended.count(), 1);   // a view still hears of it
    QVERIFY2(failed.at(0).at(0).toString().startsWith("cannot write " + path), qPrintable(failed.at(0).at(0).toString()));
    QVERIFY2(log.lastError().contains(reason), qPrintable(log.lastError()));
    QVERIFY(!log.append(QJsonObject{{"device", "ipc300@1"}}));
    QCOMPARE(failed.count(), 2);
    QCOMPARE(log.unwrittenRecords(), 2);
}

void tst_EventLog::fifoLogIsNotWaitedFor()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("write-audit.jsonl");
    QVERIFY(::mkfifo(QFile::encodeName(path).constData(), 0600) == 0);
    EventLogReader reader(path);   // a plain open() would wait for a writer
    QVERIFY(!reader.previous());
    QVERIFY2(reader.lastError().contains("not a regular file"), qPrintable(reader.lastError()));
    EventLog log(path);
    QVERIFY(!log.append(QJsonObject{{"entry", "a"}}));
    QVERIFY2(log.lastError().contains("not a regular file"), qPrintable(log.lastError()));
}

void tst_EventLog::rotationKeepsTheNewestFiles()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("alarm-journal.jsonl");
    QFile unrelated(dir.filePath("alarm-journal-notes.jsonl"));   // not one of the log's files
    QVERIFY(unrelated.open(QIODevice::WriteOnly));
    unrelated.close();
    EventLog log(path);
    log.setRotation({300, 2});
    for (int i = 0; i < 40; ++i)
        QVERIFY2(log.append(QJsonObject{{"id", QStringLiteral("record %1").arg(i, 2, 10, QLatin1Char('0'))}}),
                 qPrintable(log.lastError()));
    const QStringList files = EventLog::files(path);
    QCOMPARE(files.size(), 3);   // two older ones and the current one
    QCOMPARE(files.last(), path);
    for (const QString &f : files) {
        QVERIFY2(QFileInfo(f).size() <= 300, qPrintable(f));
        QVERIFY2(QFileInfo(f).fileName().contains(QRegularExpression("^alarm-journal(-\\d{8}T\\d{6}Z(-\\d+)?)?\\.jsonl$")),
                 qPrintable(f));
    }
    QVERIFY(unrelated.exists());
    // The newest records, in order, none missing in between.
    const QList<QJsonObject> kept = logRecords(path);
    QVERIFY(kept.size() >= 6);
    for (int i = 0; i < kept.size(); ++i)
        QCOMPARE(kept.at(i).value("id").toString(),
                 QStringLiteral("record %1").arg(40 - kept.size() + i, 2, 10, QLatin1Char('0')));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 4);
}

void tst_EventLog::rotationSettings_data()
{
    QTest::addColumn<QString>("maxFileMiB");
    QTest::addColumn<QString>("keepFiles");
    QTest::addColumn<qint64>("bytes");
    QTest::addColumn<int>("keep");
    QTest::newRow("defaults") << "" << "" << qint64(32) * 1024 * 1024 << 9;
    QTest::newRow("set") << "4" << "30" << qint64(4) * 1024 * 1024 << 30;
    QTest::newRow("out of range: defaults") << "0" << "-1" << qint64(32) * 1024 * 1024 << 9;
    QTest::newRow("no numbers: defaults") << "big" << "many" << qint64(32) * 1024 * 1024 << 9;
}

void tst_EventLog::rotationSettings()
{
    QFETCH(QString, maxFileMiB);
    QFETCH(QString, keepFiles);
    QTemporaryDir dir;
    QSettings settings(dir.filePath("jumo-hmi.conf"), QSettings::IniFormat);
    if (!maxFileMiB.isEmpty())
        settings.setValue("logs/maxFileMiB", maxFileMiB);
    if (!keepFiles.isEmpty())
        settings.setValue("logs/keepFiles", keepFiles);
    const EventLog::Rotation rotation = EventLog::Rotation::fromSettings(settings);
    QTEST(rotation.maxFileBytes, "bytes");
    QTEST(rotation.keepFiles, "keep");
}

void tst_EventLog::twoWritersLoseNothing()
{
    // The HMI and jumoctl append to one audit log, each rotating it when it is full:
    // every record of both ends up in it once, in each writer's order.
    QTemporaryDir dir;
    const QString path = dir.filePath("write-audit.jsonl");
    constexpr int records = 400;
    std::atomic_int failures{0};
    auto writer = [&](const QString &name) {
        EventLog log(path);
        log.setRotation({2000, 1000});
        for (int i = 0; i < records; ++i) {
            if (!log.append(QJsonObject{{"writer", name}, {"n", i}}))
                ++failures;
        }
    };
    std::thread hmi(writer, QStringLiteral("hmi"));
    std::thread jumoctl(writer, QStringLiteral("jumoctl"));
    hmi.join();
    jumoctl.join();
    QCOMPARE(failures.load(), 0);
    QVERIFY(EventLog::files(path).size() > 10);
    QHash<QString, int> next;
    for (const QJsonObject &r : logRecords(path)) {
        const QString name = r.value("writer").toString();
        QCOMPARE(r.value("n").toInt(), next[name]);
        ++next[name];
    }
    QCOMPARE(next.value("hmi"), records);
    QCOMPARE(next.value("jumoctl"), records);
    for (const QString &f : EventLog::files(path))
        QVERIFY2(QFileInfo(f).size() <= 2000, qPrintable(f));
}

void tst_EventLog::fullDiskIsReportedAndRecovered()
{
    SmallDisk disk;
    if (!disk.mount(64))
        QSKIP("no small tmpfs can be mounted here (needs root); fileSizeLimitIsReported covers a failed write");
    const QString path = disk.filePath("write-audit.jsonl");
    EventLog log(path);
    QSignalSpy failed(&log, &EventLog::writeFailed);
    QSignalSpy recovered(&log, &EventLog::writeRecovered);
    QVERIFY(log.append(QJsonObject{{"n", 1}}));
    disk.fill();
    QVERIFY(!log.append(QJsonObject{{"n", 2}, {"padding", QString(6000, 'p')}}));
    QVERIFY(!log.append(QJsonObject{{"n", 3}}));
    QCOMPARE(failed.count(), 2);
    QVERIFY2(failed.at(0).at(0).toString() == "cannot write " + path + ": No space left on device",
             qPrintable(failed.at(0).at(0).toString()));
    QCOMPARE(recovered.count(), 0);
    disk.free();
    QVERIFY2(log.append(QJsonObject{{"n", 4}}), qPrintable(log.lastError()));
    QCOMPARE(recovered.count(), 1);
    QCOMPARE(recovered.at(0).at(0).toInt(), 2);
    QCOMPARE(log.unwrittenRecords(), 0);
    // What is in the file is what was reported kept: a part of a record the full disk
    // took is no record.
    QList<int> kept;
    for (const QJsonObject &r : logRecords(path))
        kept << r.value("n").toInt();
    QCOMPARE(kept, QList<int>({1, 4}));
}

void tst_EventLog::fileSizeLimitIsReported()
{
    // A file size limit fails a write the way a full disk does, after a part of it.
    QTemporaryDir dir;
    const QString path = dir.filePath("alarm-journal.jsonl");
    EventLog log(path);
    QVERIFY(log.append(QJsonObject{{"n", 1}}));
    const qint64 limitAt = QFileInfo(path).size() + 40;
    struct rlimit saved = {};
    QVERIFY(::getrlimit(RLIMIT_FSIZE, &saved) == 0);
    struct rlimit limit = saved;
    limit.rlim_cur = rlim_t(limitAt);
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    QVERIFY(::setrlimit(RLIMIT_FSIZE, &limit) == 0);
    const bool cut = log.append(QJsonObject{{"n", 2}, {"padding", QString(200, 'p')}});
    const QString error = log.lastError();
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previousHandler);
    QVERIFY(!cut);
    QVERIFY2(error.startsWith("cannot write " + path + ": ") && error.contains("too large", Qt::CaseInsensitive),
             qPrintable(error));
    QCOMPARE(QFileInfo(path).size(), limitAt);   // a part went in
    QVERIFY(log.append(QJsonObject{{"n", 3}}));
    QList<int> kept;
    for (const QJsonObject &r : logRecords(path))
        kept << r.value("n").toInt();
    QCOMPARE(kept, QList<int>({1, 3}));
}

void tst_EventLog::readerGoesBackAcrossFiles()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("write-audit.jsonl");
    EventLog log(path);
    log.setRotation({200, 100});
    for (int i = 0; i < 30; ++i)
        QVERIFY(log.append(QJsonObject{{"n", i}}));
    QVERIFY(EventLog::files(path).size() > 2);
    EventLogReader reader(path);
    for (int i = 29; i >= 0; --i) {
        const auto r = reader.previous();
        QVERIFY(r);
        QCOMPARE(r->value("n").toInt(), i);
    }
    QVERIFY(!reader.previous());
    QVERIFY(reader.lastError().isEmpty());
}

void tst_EventLog::linesBackwardAreLinesForward_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QList<qint64>>("starts");   // of the complete lines
    QTest::newRow("empty") << QByteArray() << QList<qint64>{};
    QTest::newRow("no newline at all") << QByteArray("{\"a\":1}") << QList<qint64>{};
    QTest::newRow("one line") << QByteArray("{\"a\":1}\n") << QList<qint64>{0};
    QTest::newRow("a cut last line") << QByteArray("ab\ncd\nef") << QList<qint64>{0, 3};
    QTest::newRow("empty lines") << QByteArray("\n\nab\n\n") << QList<qint64>{0, 1, 2, 5};
    QTest::newRow("a line longer than a chunk") << QByteArray("a\n" + QByteArray(100, 'x') + "\nb\n")
                                                << QList<qint64>{0, 2, 103};
    QTest::newRow("a long first line") << QByteArray(QByteArray(50, 'y') + "\nz\n") << QList<qint64>{0, 51};
    // Past the size read forward at a time (1 MiB), lines go on from one read to the next.
    QByteArray many;
    QList<qint64> starts;
    for (int n = 0; many.size() < 3 * 1024 * 1024; ++n) {
        starts << many.size();
        many += "{\"n\":" + QByteArray::number(n) + ",\"text\":\"" + QByteArray(n % 97, 't') + "\"}\n";
    }
    QTest::newRow("lines across reads") << many << starts;
}

void tst_EventLog::linesBackwardAreLinesForward()
{
    QFETCH(QByteArray, text);
    QFETCH(QList<qint64>, starts);
    QTemporaryDir dir;
    QFile f(dir.filePath("lines.jsonl"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
    f.close();
    QString error;
    const auto file = LogFile::open(f.fileName(), &error);
    QVERIFY2(file, qPrintable(error));
    QList<qint64> forward;
    file->linesFrom(0, file->size(), [&](const LogFile::Line &line) {
        forward << line.offset;
        if (line.text.size() != line.length || line.text.toByteArray() != text.mid(line.offset, line.length))
            forward << -1;
        return true;
    });
    QCOMPARE(forward, starts);
    const QList<qint64> chunks = text.size() > 100000 ? QList<qint64>{1000, 256 * 1024} : QList<qint64>{3, 16, 4096};
    for (const qint64 chunk : chunks) {
        QList<qint64> backward;
        for (qint64 cursor = file->lastLineEnd(file->size()); cursor > 0;) {
            cursor = file->linesBefore(cursor, chunk, [&](const LogFile::Line &line) {
                backward.prepend(line.offset);
                if (line.text.toByteArray() != text.mid(line.offset, line.length))
                    backward.prepend(-1);
                return true;
            });
        }
        QCOMPARE(backward, starts);
    }
}

void tst_EventLog::defaultFolderNeedsAHome_data()
{
    QTest::addColumn<QString>("logDir");    // JUMO_LOG_DIR; empty: unset
    QTest::addColumn<QString>("dataHome");  // XDG_DATA_HOME
    QTest::addColumn<QString>("home");      // HOME
    QTest::addColumn<QString>("folder");    // the logs' folder below the test's; "-": none
    QTest::newRow("JUMO_LOG_DIR") << "logs" << "" << "" << "logs";
    QTest::newRow("XDG_DATA_HOME") << "" << "data" << "" << "data/jumo";
    QTest::newRow("HOME") << "" << "" << "home" << "home/.local/share/jumo";
    QTest::newRow("nothing set") << "" << "" << "" << "-";
    QTest::newRow("a relative HOME") << "" << "" << "RELATIVE" << "-";
}

void tst_EventLog::defaultFolderNeedsAHome()
{
    // Without any of them Qt names /.local/share: logs of everyone's writes in the root
    // folder. No folder is the answer then, with the reason.
    QFETCH(QString, logDir);
    QFETCH(QString, dataHome);
    QFETCH(QString, home);
    QFETCH(QString, folder);
    QTemporaryDir dir;
    const QHash<const char *, QString> values{{"JUMO_LOG_DIR", logDir}, {"XDG_DATA_HOME", dataHome}, {"HOME", home}};
    QHash<const char *, QByteArray> before;
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        before.insert(it.key(), qgetenv(it.key()));
        if (it.value() == "RELATIVE")
            qputenv(it.key(), "relative/home");
        else if (it.value().isEmpty())
            qunsetenv(it.key());
        else
            qputenv(it.key(), QFile::encodeName(dir.filePath(it.value())));
    }
    QString error;
    const QString found = EventLog::defaultFolder(&error);
    for (auto it = before.cbegin(); it != before.cend(); ++it) {
        if (it.value().isNull())
            qunsetenv(it.key());
        else
            qputenv(it.key(), it.value());
    }
    if (folder == "-") {
        QVERIFY2(found.isEmpty(), qPrintable(found));
        QCOMPARE(error, QString("no folder for the logs: neither JUMO_LOG_DIR, XDG_DATA_HOME nor HOME is set to an "
                                "absolute folder"));
    } else {
        QCOMPARE(found, dir.filePath(folder));
        QVERIFY(QFileInfo(found).isDir());
    }
}

QTEST_GUILESS_MAIN(tst_EventLog)
#include "tst_eventlog.moc"
