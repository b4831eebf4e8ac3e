// The data logger checks every write: a full disk stops it with the reason instead of
// rows that never reach the disk; it keeps only the newest files when asked to.
#include "bus/bus.h"
#include "logs/datalogger.h"
#include "protocol/familyregistry.h"
#include "smalldisk.h"

#include <QDir>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

class tst_DataLogger : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void fullDiskStopsWithTheReason();
    void fullDiskAtStart();
    void keepsTheNewestFiles();

private:
    DataLogger::Settings settings(const QString &folder, int entries = 1) const;

    FamilyRegistry m_families = FamilyRegistry::load({}, true);
    Bus m_bus;
    DeviceId m_device{};
};

void tst_DataLogger::initTestCase()
{
    m_device = m_bus.addDevice(m_families.family("ipc300"), 1);   // never read: rows say "not_read"
}

DataLogger::Settings tst_DataLogger::settings(const QString &folder, int entries) const
{
    DataLogger::Settings s;
    s.folder = folder;
    s.intervalMs = 100;
    const QStringList ids = m_families.family("ipc300")->overview;
    for (int i = 0; i < entries; ++i)
        s.entries << qMakePair(m_device, ids.value(i % ids.size()));
    return s;
}

void tst_DataLogger::fullDiskStopsWithTheReason()
{
    SmallDisk disk;
    if (!disk.mount(64))
        QSKIP("no small tmpfs can be mounted here (needs root)");
    DataLogger logger(&m_bus);
    QSignalSpy failed(&logger, &DataLogger::failed);
    QString error;
    QVERIFY2(logger.start(settings(disk.path(), 40), &error), qPrintable(error));
    QTRY_VERIFY(logger.rowsWritten() >= 80);
    disk.fill();
    QVERIFY(failed.wait(20000));
    QVERIFY(!logger.isRunning());
    const QString reason = failed.at(0).at(0).toString();
    QVERIFY2(reason == "cannot write " + logger.currentFile() + ": No space left on device", qPrintable(reason));
    // Every row counted is on disk.
    QFile file(logger.currentFile());
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.readAll().count('\n') - 1 >= logger.rowsWritten());
}

void tst_DataLogger::fullDiskAtStart()
{
    SmallDisk disk;
    if (!disk.mount(64))
        QSKIP("no small tmpfs can be mounted here (needs root)");
    disk.fill();
    DataLogger logger(&m_bus);
    QString error;
    QVERIFY(!logger.start(settings(disk.path()), &error));
    QVERIFY2(error.endsWith(": No space left on device"), qPrintable(error));
    QVERIFY(!logger.isRunning());
}

void tst_DataLogger::keepsTheNewestFiles()
{
    QTemporaryDir dir;
    QFile other(dir.filePath("jumo-data-20000101-000000.csv"));   // not this logger's
    QVERIFY(other.open(QIODevice::WriteOnly));
    other.close();
    DataLogger logger(&m_bus);
    DataLogger::Settings s = settings(dir.path(), 40);   // a sample is larger than a file may grow
    s.maxFileBytes = 1024;
    s.keepFiles = 2;
    QString error;
    QVERIFY2(logger.start(s, &error), qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(logger.rowsWritten() >= 5 * 40, 20000);
    logger.stop();
    QCOMPARE(logger.files().size(), 2);
    QStringList expected{other.fileName()};
    expected << logger.files();
    QStringList present;
    for (const QString &name : QDir(dir.path()).entryList(QDir::Files, QDir::Name))
        present << dir.filePath(name);
    expected.sort();
    QCOMPARE(present, expected);
}

QTEST_GUILESS_MAIN(tst_DataLogger)
#include "tst_datalogger.moc"
