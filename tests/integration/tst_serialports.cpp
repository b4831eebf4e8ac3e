// Serial ports as users have them, on real pseudo-terminals: a line opened by a by-id
// style link follows it to the new device when the adapter comes back; the process
// holding a port is found in /proc; a second program on a port names the first; and a
// user outside the device's group (nobody, via setpriv) is told the group and the
// command to join it.
#include "bus/bus.h"
#include "bus/portaccess.h"
#include "bus/serialportlist.h"
#include "clirun.h"
#include "testpeers.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTest>

#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <stdlib.h>
#include <unistd.h>

using namespace jumo;
using namespace jumo::test;

namespace {

// Pseudo-terminal masters held open, so their numbers are taken: a pty made after
// that cannot come back under an old number. Never unlocked: their slaves do not open.
class HeldPtys
{
public:
    ~HeldPtys()
    {
        for (int fd : m_fds)
            ::close(fd);
    }
    // Takes numbers until `device` (a /dev/pts/N) is among them.
    bool hold(const QString &device)
    {
        for (int i = 0; i < 256; ++i) {
            const int fd = ::posix_openpt(O_RDWR | O_NOCTTY);
            if (fd < 0)
                return false;
            m_fds << fd;
            if (QString::fromLocal8Bit(::ptsname(fd)) == device)
                return true;
        }
        return false;
    }

private:
    QList<int> m_fds;
};

bool relink(const QString &link, const QString &target)
{
    QFile::remove(link);
    return QFile::link(target, link);
}

} // namespace

class tst_SerialPorts : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void lineFollowsByIdLinkToTheNewDevice();
    void holderOfAPtyIsNamed();
    void secondProgramOnAPortNamesTheFirst();
    void userOutsideTheGroupIsToldHowToJoin();
};

void tst_SerialPorts::initTestCase()
{
    qputenv("JUMO_MAP_PATH", "");
}

void tst_SerialPorts::lineFollowsByIdLinkToTheNewDevice()
{
    TestLine line;
    QVERIFY(line.start());
    SimulatorPeer sim;
    QVERIFY(sim.start(line.deviceEnd(), {1}));
    // What udev makes for an adapter: a stable name linking to the device it is now.
    QTemporaryDir byId;
    QVERIFY(byId.isValid());
    const QString link = byId.filePath("usb-JUMO_Test_Adapter_T1234-if00-port0");
    const QString before = QFileInfo(line.masterEnd()).canonicalFilePath();
    QVERIFY(relink(link, before));

    Bus bus;
    BusSettings settings;
    settings.portName = link;
    settings.format = testFormat();
    settings.timeoutMs = 500;
    settings.reconnectIntervalMs = 200;
    bus.setSettings(settings);
    QVERIFY2(bus.open(), qPrintable(bus.lastError()));
    const DeviceId id = bus.addDevice(families().family("ipc300"), 1);
    bus.setPollEntries(id, {"load_current"});
    QTRY_VERIFY_WITH_TIMEOUT(bus.entryState(id, "load_current") && bus.entryState(id, "load_current")->isCurrent(), 10000);

    // Unplugged: the device and its link go away.
    sim.stop();
    line.stop();
    QFile::remove(link);
    QTRY_COMPARE_WITH_TIMEOUT(bus.state(), LineState::Lost, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(!bus.entryState(id, "load_current")->isCurrent(), 10000);

    // Plugged in again, it comes back as another device (its old number is taken
    // meanwhile), and the link follows it, as udev does.
    HeldPtys held;
    QVERIFY(held.hold(before));
    QVERIFY(line.restart());
    QVERIFY(sim.reopen());
    const QString after = QFileInfo(line.masterEnd()).canonicalFilePath();
    QVERIFY2(after != before, qPrintable(after));
    QVERIFY(relink(link, after));
    QCOMPARE(SerialPortList::currentDevice(link), after);
    QTRY_COMPARE_WITH_TIMEOUT(bus.state(), LineState::Connected, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(bus.entryState(id, "load_current")->isCurrent(), 10000);
    QCOMPARE(bus.settings().portName, link);
}

void tst_SerialPorts::holderOfAPtyIsNamed()
{
    TestLine line;
    QVERIFY(line.start());
    const QString device = QFileInfo(line.deviceEnd()).canonicalFilePath();
    QProcess holder;
    holder.setStandardInputFile(device);
    holder.start("sleep", {"600"});
    QVERIFY(holder.waitForStarted());

    const QList<PortHolder> holders = PortAccess::holdersOf(device);
    const bool named = std::any_of(holders.cbegin(), holders.cend(), [&](const PortHolder &h) {
        return h.pid == holder.processId() && h.command == "sleep";
    });
    QVERIFY2(named, qPrintable(PortAccess::inspect(device).message()));
    const PortAccess access = PortAccess::inspect(line.deviceEnd());
    QCOMPARE(access.problem, PortAccess::Problem::Busy);
    QVERIFY2(access.message().contains(QStringLiteral("sleep (PID %1)").arg(holder.processId())), qPrintable(access.message()));

    holder.kill();
    holder.waitForFinished();
    const QList<PortHolder> after = PortAccess::holdersOf(device);
    QVERIFY(std::none_of(after.cbegin(), after.cend(), [&](const PortHolder &h) { return h.command == "sleep"; }));
}

void tst_SerialPorts::secondProgramOnAPortNamesTheFirst()
{
    TestLine line;
    QVERIFY(line.start());
    SimulatorPeer sim;
    QVERIFY(sim.start(line.deviceEnd(), {1}));
    QProcess first;
    first.start(JUMOCTL_PATH, {"monitor", "--port", line.masterEnd(), "--baud", "19200", "ipc300@1", "--jsonl",
                               "--interval", "200"});
    QVERIFY(first.waitForStarted());
    QTRY_VERIFY_WITH_TIMEOUT(first.canReadLine(), 20000);   // it has the port: a cycle came through

    const qint64 firstPid = first.processId();
    const Run second = run({"read", "--port", line.masterEnd(), "--baud", "19200", "ipc300@1", "load_current"});
    first.terminate();
    first.waitForFinished();
    QCOMPARE(second.code, 1);
    // Qt only says "Permission error while locking the device".
    QVERIFY2(second.err.contains(QStringLiteral("cannot open %1: ").arg(line.masterEnd())), qPrintable(second.err));
    QVERIFY2(second.err.contains(QStringLiteral("is in use by ")), qPrintable(second.err));
    QVERIFY2(second.err.contains(QStringLiteral("jumoctl (PID %1)").arg(firstPid)), qPrintable(second.err));
}

void tst_SerialPorts::userOutsideTheGroupIsToldHowToJoin()
{
    if (::geteuid() != 0)
        QSKIP("needs root to hand the pty to the group dialout and to run as nobody");
    const group *dialout = ::getgrnam("dialout");
    const passwd *nobody = ::getpwnam("nobody");
    const QString setpriv = QStandardPaths::findExecutable("setpriv");
    if (!dialout || !nobody || setpriv.isEmpty())
        QSKIP("needs the group dialout, the user nobody and setpriv");

    // The pty as a USB adapter is on Debian: root:dialout, mode 0660, under a by-id name.
    TestLine line;
    QVERIFY(line.start());
    const QString device = QFileInfo(line.masterEnd()).canonicalFilePath();
    QCOMPARE(::chown(QFile::encodeName(device).constData(), 0, dialout->gr_gid), 0);
    QVERIFY(QFile::setPermissions(device, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup | QFile::WriteGroup));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir("by-id"));
    QVERIFY(QDir(dir.path()).mkdir("home"));
    const QFileDevice::Permissions open = QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner | QFile::ReadGroup
            | QFile::ExeGroup | QFile::ReadOther | QFile::ExeOther;
    QVERIFY(QFile::setPermissions(dir.path(), open));
    QVERIFY(QFile::setPermissions(dir.filePath("by-id"), open));
    QVERIFY(QFile::setPermissions(dir.filePath("home"), open | QFile::WriteOther));
    const QString link = dir.filePath("by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0");
    QVERIFY(QFile::link(device, link));

    auto asNobody = [&](const QStringList &arguments, QString *err) {
        QProcess process;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("HOME", dir.filePath("home"));
        env.insert("JUMO_SERIAL_BY_ID_DIR", dir.filePath("by-id"));
        env.insert("LANG", "C.UTF-8");
        env.remove("LANGUAGE");
        process.setProcessEnvironment(env);
        process.start(setpriv, QStringList{QStringLiteral("--reuid=%1").arg(nobody->pw_uid),
                                           QStringLiteral("--regid=%1").arg(nobody->pw_gid), "--clear-groups",
                                           JUMOCTL_PATH}
                                       + arguments);
        process.waitForFinished(60000);
        *err = QString::fromLocal8Bit(process.readAllStandardError());
        return std::make_pair(process.exitCode(), QString::fromLocal8Bit(process.readAllStandardOutput()));
    };

    QString err;
    // setpriv exits 127 when nobody cannot reach the program (a build folder below a
    // private home directory): nothing to learn about the port then.
    if (asNobody({"--version"}, &err).first == 127)
        QSKIP("the user nobody cannot run jumoctl from this build folder");
    const auto [code, out] = asNobody({"read", "--port", link, "--baud", "19200", "ipc300@1", "load_current"}, &err);
    QCOMPARE(code, 1);
    const QString advice = QStringLiteral("no permission: %1 belongs to the group 'dialout'. Join it with 'sudo usermod "
                                          "-aG dialout $USER', then log out and in again.")
                                   .arg(device);
    QVERIFY2(err.contains(QStringLiteral("cannot open %1: ").arg(link) + advice), qPrintable(err));

    const auto [listed, json] = asNobody({"ports", "--json"}, &err);
    QCOMPARE(listed, 0);
    QJsonObject port;
    for (const QJsonValue &value : QJsonDocument::fromJson(json.toUtf8()).array()) {
        if (value.toObject().value("port").toString() == link)
            port = value.toObject();
    }
    QVERIFY2(!port.isEmpty(), qPrintable(json));
    QCOMPARE(port.value("device").toString(), device);
    QCOMPARE(port.value("stable").toBool(), true);
    QCOMPARE(port.value("access").toString(), "permission");
    QCOMPARE(port.value("group").toString(), "dialout");
    QCOMPARE(port.value("message").toString(), advice);
}

QTEST_GUILESS_MAIN(tst_SerialPorts)
#include "tst_serialports.moc"
