// Why a port cannot be opened, composed from what the system says: errno to problem,
// the messages for each case (the group and the command to join it, a login that
// predates joining, a device open to no group, the holders), and the /proc holder
// lookup against a folder laid out like /proc.
#include "bus/portaccess.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>

using namespace jumo;

Q_DECLARE_METATYPE(jumo::PortAccess::Problem)

class tst_PortAccess : public QObject
{
    Q_OBJECT

private slots:
    void problemFromErrno_data();
    void problemFromErrno();
    void messages_data();
    void messages();
    void holdersFromProcFolder();
    void inspectMissingAndFine();
};

void tst_PortAccess::problemFromErrno_data()
{
    QTest::addColumn<int>("errorNumber");
    QTest::addColumn<PortAccess::Problem>("problem");
    QTest::newRow("ENOENT: unplugged") << ENOENT << PortAccess::Problem::Missing;
    QTest::newRow("ENODEV: gone while open") << ENODEV << PortAccess::Problem::Missing;
    QTest::newRow("ENXIO: no device behind the node") << ENXIO << PortAccess::Problem::Missing;
    QTest::newRow("EACCES: not in the group") << EACCES << PortAccess::Problem::Permission;
    QTest::newRow("EPERM") << EPERM << PortAccess::Problem::Permission;
    QTest::newRow("EBUSY: exclusive elsewhere") << EBUSY << PortAccess::Problem::Busy;
    QTest::newRow("EIO: nothing to advise") << EIO << PortAccess::Problem::None;
}

void tst_PortAccess::problemFromErrno()
{
    QFETCH(int, errorNumber);
    QFETCH(PortAccess::Problem, problem);
    QCOMPARE(PortAccess::problemFromErrno(errorNumber), problem);
}

void tst_PortAccess::messages_data()
{
    QTest::addColumn<int>("errorNumber");
    QTest::addColumn<QString>("group");
    QTest::addColumn<uint>("mode");
    QTest::addColumn<bool>("joinedAfterLogin");
    QTest::addColumn<QList<qint64>>("holderPids");
    QTest::addColumn<QString>("message");
    QTest::newRow("not in the group that owns the device")
            << EACCES << "dialout" << 0660u << false << QList<qint64>{}
            << "no permission: /dev/ttyUSB0 belongs to the group 'dialout'. Join it with 'sudo usermod -aG dialout "
               "$USER', then log out and in again.";
    QTest::newRow("another group, the same advice with its name")
            << EACCES << "uucp" << 0660u << false << QList<qint64>{}
            << "no permission: /dev/ttyUSB0 belongs to the group 'uucp'. Join it with 'sudo usermod -aG uucp $USER', "
               "then log out and in again.";
    QTest::newRow("joined, but this login is older")
            << EACCES << "dialout" << 0660u << true << QList<qint64>{}
            << "no permission: /dev/ttyUSB0 belongs to the group 'dialout'; you are in it, but this login started "
               "before you joined: log out and in again.";
    QTest::newRow("open to its owner only: joining does not help")
            << EACCES << "dialout" << 0600u << false << QList<qint64>{}
            << "no permission: /dev/ttyUSB0 (owner root, group dialout, mode 0600) is not open to a group. Ask the "
               "administrator to give it to the group dialout (a udev rule).";
    QTest::newRow("root's group: never advise joining it")
            << EACCES << "root" << 0660u << false << QList<qint64>{}
            << "no permission: /dev/ttyUSB0 (owner root, group root, mode 0660) is not open to a group. Ask the "
               "administrator to give it to the group dialout (a udev rule).";
    QTest::newRow("busy, holders known") << EBUSY << "dialout" << 0660u << false << QList<qint64>{4242, 777}
                                         << "/dev/ttyUSB0 is in use by jumo-hmi (PID 4242), minicom (PID 777): close "
                                            "it there first.";
    QTest::newRow("busy, holders unknown") << EBUSY << "dialout" << 0660u << false << QList<qint64>{}
                                           << "/dev/ttyUSB0 is in use by another program (the system does not tell "
                                              "which).";
    QTest::newRow("unplugged") << ENOENT << "" << 0u << false << QList<qint64>{}
                               << "there is no such port: is the adapter plugged in? 'jumoctl ports' lists the serial "
                                  "ports.";
    QTest::newRow("nothing to advise") << EIO << "dialout" << 0660u << false << QList<qint64>{} << "";
}

void tst_PortAccess::messages()
{
    QFETCH(int, errorNumber);
    QFETCH(QString, group);
    QFETCH(uint, mode);
    QFETCH(bool, joinedAfterLogin);
    QFETCH(QList<qint64>, holderPids);
    QFETCH(QString, message);
    PortAccess access;
    access.port = "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0";
    access.device = "/dev/ttyUSB0";
    access.problem = PortAccess::problemFromErrno(errorNumber);
    access.owner = "root";
    access.group = group;
    access.mode = mode;
    access.groupMayOpen = (mode & 0060) == 0060 && group != "root";
    access.joinedAfterLogin = joinedAfterLogin;
    for (qint64 pid : holderPids)
        access.holders << PortHolder{pid, pid == 4242 ? "jumo-hmi" : "minicom"};
    QCOMPARE(access.message(), message);
}

void tst_PortAccess::holdersFromProcFolder()
{
    // 100 holds the device, 200 something else, 300 the device under a second fd,
    // "self" is no process, and this process never counts as a holder of its own.
    QTemporaryDir proc;
    QVERIFY(proc.isValid());
    const QString device = proc.filePath("ttyUSB0");
    QVERIFY(QFile(device).open(QIODevice::WriteOnly));
    const QString own = QString::number(QCoreApplication::applicationPid());
    const QList<std::tuple<QString, QString, QString>> fds{
            {"100", "3", device}, {"100", "4", "/dev/null"}, {"200", "0", "/dev/null"},
            {"300", "7", "/dev/ttyUSB9"}, {"300", "9", device}, {"self", "3", device}, {own, "5", device}};
    for (const auto &[pid, fd, target] : fds) {
        QVERIFY(QDir(proc.path()).mkpath(pid + "/fd"));
        QVERIFY(QFile::link(target, proc.filePath(pid + "/fd/" + fd)));
        QFile comm(proc.filePath(pid + "/comm"));
        QVERIFY(comm.open(QIODevice::WriteOnly));
        comm.write(pid == "100" ? "jumo-hmi\n" : "minicom\n");
    }
    const QList<PortHolder> holders = PortAccess::holdersOf(device, proc.path());
    QCOMPARE(holders.size(), 2);
    QCOMPARE(holders[0].pid, 100);
    QCOMPARE(holders[0].command, "jumo-hmi");
    QCOMPARE(holders[1].pid, 300);
    QCOMPARE(holders[1].command, "minicom");

    // Held by someone: the port is busy and the message names them.
    const PortAccess access = PortAccess::inspect(device, proc.path());
    QCOMPARE(access.problem, PortAccess::Problem::Busy);
    QVERIFY2(access.message().contains("jumo-hmi (PID 100), minicom (PID 300)"), qPrintable(access.message()));
}

void tst_PortAccess::inspectMissingAndFine()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const PortAccess missing = PortAccess::inspect(dir.filePath("ttyUSB3"), dir.path());
    QCOMPARE(missing.problem, PortAccess::Problem::Missing);
    QVERIFY(missing.message().contains("is the adapter plugged in?"));
    const QString device = dir.filePath("ttyUSB0");
    QVERIFY(QFile(device).open(QIODevice::WriteOnly));   // our own, read and write: nothing in the way
    const PortAccess fine = PortAccess::inspect(device, dir.path());
    QCOMPARE(fine.problem, PortAccess::Problem::None);
    QVERIFY(fine.message().isEmpty());
}

QTEST_GUILESS_MAIN(tst_PortAccess)
#include "tst_portaccess.moc"
