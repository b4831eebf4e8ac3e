// Files that cannot lie: a whole file is replaced only when every byte of the new one
// is on disk (a failed save leaves the old file byte for byte), and files handed to us
// are read only when they are regular files below a limit: never a FIFO (which would
// block open()), a device (a link to /dev/zero would never end) or a huge file.
#include "protocol/filesaver.h"
#include "protocol/regularfile.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <sys/resource.h>
#include <sys/stat.h>

using namespace jumo;

class tst_Files : public QObject
{
    Q_OBJECT

private slots:
    void saveReplacesTheWholeFile();
    void failedSaveKeepsThePreviousFile();
    void folderInTheWayIsNamed();
    void fifoOrDeviceIsNotReplaced();
    void regularFileIsRead();
    void fifoIsRefusedWithoutBlocking();
    void deviceIsRefused();
    void tooBigIsRefused();
    void appendRefusesFifoAndDevice();

private:
    QTemporaryDir m_dir;
};

namespace {

QByteArray contents(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(unreadable)");
}

bool writeFile(const QString &path, const QByteArray &data)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(data) == data.size();
}

} // namespace

void tst_Files::saveReplacesTheWholeFile()
{
    const QString path = m_dir.filePath("whole.json");
    QVERIFY(writeFile(path, QByteArray(5000, 'o')));
    QString error;
    QVERIFY2(FileSaver::save(path, "new", &error), qPrintable(error));
    QCOMPARE(contents(path), QByteArray("new"));
}

void tst_Files::failedSaveKeepsThePreviousFile()
{
    // A file size limit makes every write past 1000 bytes fail as a full disk would,
    // after the first bytes went through (QSaveFile then used to commit what it had).
    const QString path = m_dir.filePath("backup.json");
    const QByteArray old(500, 'o');
    QVERIFY(writeFile(path, old));
    struct rlimit saved = {};
    QVERIFY(::getrlimit(RLIMIT_FSIZE, &saved) == 0);
    struct rlimit limit = saved;
    limit.rlim_cur = 1000;
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    QVERIFY(::setrlimit(RLIMIT_FSIZE, &limit) == 0);
    QString error;
    const bool saved2 = FileSaver::save(path, QByteArray(5000, 'n'), &error);
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previousHandler);
    QVERIFY(!saved2);
    QVERIFY2(error.startsWith("cannot write " + path + ": "), qPrintable(error));
    QVERIFY2(error.contains("too large", Qt::CaseInsensitive), qPrintable(error));
    QCOMPARE(contents(path), old);
    QCOMPARE(QDir(m_dir.path()).entryList(QDir::Files | QDir::Hidden).filter("backup.json").size(), 1);   // no debris
}

void tst_Files::folderInTheWayIsNamed()
{
    const QString path = m_dir.filePath("folder.html");
    QVERIFY(QDir().mkpath(path));
    QString error;
    QVERIFY(!FileSaver::save(path, "report", &error));
    QVERIFY2(error.startsWith("cannot write " + path + ": "), qPrintable(error));
    QVERIFY(!FileSaver::save(m_dir.filePath("missing/report.html"), "report", &error));
    QVERIFY2(error.contains("missing/report.html"), qPrintable(error));
}

void tst_Files::fifoOrDeviceIsNotReplaced()
{
    const QString fifo = m_dir.filePath("report.fifo");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    QString error;
    QVERIFY(!FileSaver::save(fifo, "report", &error));
    QCOMPARE(error, "cannot write " + fifo + ": not a regular file");
    QVERIFY(QFileInfo(fifo).exists() && !QFileInfo(fifo).isFile());   // still the FIFO
    const QString device = m_dir.filePath("null.html");   // a link to a device: its target counts
    QVERIFY(QFile::link("/dev/null", device));
    QVERIFY(!FileSaver::save(device, "report", &error));
    QVERIFY(QFileInfo(device).isSymLink());
}

void tst_Files::regularFileIsRead()
{
    const QString path = m_dir.filePath("map.json");
    QVERIFY(writeFile(path, "{}"));
    QString error;
    QCOMPARE(RegularFile::read(path, 100, &error).value_or("(none)"), QByteArray("{}"));
    QVERIFY(error.isEmpty());
    QCOMPARE(RegularFile::read(":/maps/ipc300.json").value_or(QByteArray()).left(1), QByteArray("{"));
    QVERIFY(!RegularFile::read(m_dir.filePath("absent.json"), 100, &error));
    QVERIFY2(error.startsWith(m_dir.filePath("absent.json") + ": "), qPrintable(error));
}

void tst_Files::fifoIsRefusedWithoutBlocking()
{
    // Opened the ordinary way, this would wait for a writer forever.
    const QString path = m_dir.filePath("fifo.json");
    QVERIFY(::mkfifo(QFile::encodeName(path).constData(), 0600) == 0);
    QString error;
    QVERIFY(!RegularFile::read(path, 1000, &error));
    QCOMPARE(error, path + ": not a regular file");
}

void tst_Files::deviceIsRefused()
{
    const QString path = m_dir.filePath("zero.json");
    QVERIFY(QFile::link("/dev/zero", path));
    QString error;
    QVERIFY(!RegularFile::read(path, 1000, &error));
    QCOMPARE(error, path + ": not a regular file");
}

void tst_Files::tooBigIsRefused()
{
    const QString path = m_dir.filePath("big.json");
    QVERIFY(writeFile(path, QByteArray(1001, ' ')));
    QString error;
    QVERIFY(!RegularFile::read(path, 1000, &error));
    QVERIFY2(error.contains("too big (1001 bytes, at most 1000)"), qPrintable(error));
    QVERIFY(RegularFile::read(path, 1001));
}

void tst_Files::appendRefusesFifoAndDevice()
{
    const QString fifo = m_dir.filePath("append.fifo");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    QFile file;
    QString error;
    QVERIFY(!RegularFile::openForAppending(file, fifo, &error));
    QVERIFY(!RegularFile::openForAppending(file, "/dev/full", &error));
    QCOMPARE(error, QString("/dev/full: not a regular file"));
    QVERIFY(RegularFile::openForAppending(file, m_dir.filePath("new.jsonl"), &error));
}

QTEST_GUILESS_MAIN(tst_Files)
#include "tst_files.moc"
