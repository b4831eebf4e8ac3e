// The line kinds end to end: the bus over a Modbus TCP gateway (tcp://) and over a
// serial device server (rtu+tcp://), each against our simulator and against the
// independent libmodbus peer. Reads, writes verified by read-back, the gateway's own
// exceptions, a gateway that goes away and comes back, stray bytes and late replies on a
// device server, broadcasts, jumoctl reading and scanning each kind and over IPv6, and a gateway
// that lies: another unit's reply, changed ids, junk and wrong lengths.
#include "bus/bus.h"
#include "bus/linetiming.h"
#include "clirun.h"
#include "lyinggateway.h"
#include "sim/simulatorserver.h"
#include "testpeers.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QScopeGuard>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

#include <cmath>

using namespace jumo;
using namespace jumo::test;

namespace {

// The far end of a network line, whoever serves it.
class FarEnd
{
public:
    FarEnd(const QString &kind, const QString &peer) : m_kind(kind), m_peerName(peer) { }

    bool start(const QList<quint8> &slaves)
    {
        m_slaves = slaves;
        if (m_kind == "tcp" && m_peerName == "simulator") {
            auto sim = std::make_unique<SimulatorPeer>();
            sim->line().setFormat(testFormat());
            for (quint8 s : slaves)
                sim->line().addDevice(families().family("ipc300"), s);
            m_server = std::make_unique<SimulatorServer>(&sim->line(), SimulatorServer::Mode::ModbusTcp);
            if (!m_server->listen(QHostAddress::LocalHost, 0))
                return false;
            m_port = m_server->port();
            m_peer = std::move(sim);
        } else if (m_kind == "tcp") {
            auto peer = std::make_unique<LibmodbusPeer>();
            if (!peer->startTcp(slaves))
                return false;
            m_port = peer->tcpPort();
            m_peer = std::move(peer);
        } else {
            if (!m_deviceServer.start())
                return false;
            m_port = m_deviceServer.port();
            m_peer = makePeer(m_peerName);
            if (!m_peer->start(m_deviceServer.ptyPath(), slaves))
                return false;
        }
        return setValues();
    }

    // The gateway or device server dies: its connection drops.
    void goAway()
    {
        if (m_server)
            m_server->close();
        else if (m_kind == "tcp")
            static_cast<LibmodbusPeer *>(m_peer.get())->kill();
        else
            m_deviceServer.kill();
    }

    // Back at the same port, with the same devices and values.
    bool comeBack()
    {
        if (m_server)
            return m_server->listen(QHostAddress::LocalHost, m_port);
        if (m_kind == "tcp") {
            auto *peer = static_cast<LibmodbusPeer *>(m_peer.get());
            return peer->startTcp(m_slaves, m_port) && setValues();
        }
        if (!m_deviceServer.start(m_port))
            return false;
        if (m_peerName == "simulator") {
            auto *sim = static_cast<SimulatorPeer *>(m_peer.get());
            sim->line().close();   // its pty went with the old device server
            return sim->reopen();
        }
        m_peer = makePeer(m_peerName);   // the old one ended with its pty
        return m_peer->start(m_deviceServer.ptyPath(), m_slaves) && setValues();
    }

    QString url() const { return QStringLiteral("%1://127.0.0.1:%2").arg(m_kind).arg(m_port); }
    Peer *peer() const { return m_peer.get(); }

private:
    bool setValues()
    {
        const auto map = families().family("ipc300");
        for (quint8 slave : std::as_const(m_slaves)) {
            for (const QString &id : polledIds) {
                const QList<quint16> words = ValueCodec::encodeFloat(float(expectedValue(id, slave)), WordOrder::CDAB);
                if (!m_peer->setWords(slave, map->entry(id)->address, words))
                    return false;
            }
        }
        return true;
    }

    QString m_kind;
    QString m_peerName;
    QList<quint8> m_slaves;
    quint16 m_port = 0;
    std::unique_ptr<Peer> m_peer;
    std::unique_ptr<SimulatorServer> m_server;
    DeviceServer m_deviceServer;
};

struct Observer
{
    QHash<DeviceId, int> good;
    int wrong = 0;
    QSet<QString> statuses;
};

// Counts every polled value the bus takes as current: right (expectedValue) or wrong.
void watch(Bus &bus, Observer &observed)
{
    QObject::connect(&bus, &Bus::entriesUpdated, &bus, [&bus, &observed](DeviceId id, const QStringList &ids) {
        const quint8 slave = bus.deviceAddress(id);
        for (const QString &entryId : ids) {
            if (!polledIds.contains(entryId))
                continue;
            const EntryState *state = bus.entryState(id, entryId);
            observed.statuses << QStringLiteral("%1:%2").arg(slave).arg(state->statusName());
            if (state->error != ReadError::None || state->validity != Validity::Current)
                continue;
            if (std::fabs(state->value.value.toDouble() - expectedValue(entryId, slave)) > 1e-3) {
                ++observed.wrong;
                qWarning() << "wrong value" << slave << entryId << state->value.display;
            } else {
                ++observed.good[id];
            }
        }
    });
}

// jumo-sim as a gateway or device server on its own (--tcp or --rtu-tcp LISTEN): the
// address it says to connect to, empty if it did not.
QString startJumoSim(QProcess &sim, const QString &kind, const QString &listen)
{
    sim.start(QStringLiteral(JUMO_SIM_PATH),
              {kind == "tcp" ? "--tcp" : "--rtu-tcp", listen, "--baud", "38400", "ipc300@1", "tya200@2"});
    if (!sim.waitForStarted(5000))
        return {};
    QElapsedTimer timer;
    timer.start();
    QByteArray out;
    while (timer.elapsed() < 10000 && !out.contains("connect to ")) {
        sim.waitForReadyRead(100);
        out += sim.readAllStandardOutput();
    }
    const qsizetype at = out.indexOf("connect to ");
    if (at < 0)
        return {};
    return QString::fromUtf8(out.mid(at + 11)).section('\n', 0, 0).trimmed();
}

} // namespace

class tst_LineKinds : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void readsAndWrites_data();
    void readsAndWrites();
    void gatewayGoesAwayAndComesBack_data();
    void gatewayGoesAwayAndComesBack();
    void strayByteBeforeReplyIsSkipped_data();
    void strayByteBeforeReplyIsSkipped();
    void gatewayExceptions_data();
    void gatewayExceptions();
    void unitWithoutDeviceIsOffline_data();
    void unitWithoutDeviceIsOffline();
    void broadcastRefusedThroughGateway();
    void broadcastOverDeviceServer_data();
    void broadcastOverDeviceServer();
    void unreachableGatewayIsALostLine_data();
    void unreachableGatewayIsALostLine();
    void jumoctlReadsEachKind_data();
    void jumoctlReadsEachKind();
    void simulatedGatewayEchoesTransactionIds();
    void jumoctlReadsOverIpv6_data();
    void jumoctlReadsOverIpv6();
    void lyingGatewayNeverGivesAnotherUnitsValue_data();
    void lyingGatewayNeverGivesAnotherUnitsValue();
    void lyingGatewayNeverConfirmsAWrite_data();
    void lyingGatewayNeverConfirmsAWrite();
    void connectionCutUnderAWriteLeavesItUnknown();
    void badGatewayFrameDoesNotCutADeviceOff_data();
    void badGatewayFrameDoesNotCutADeviceOff();
    void deviceServerLateRepliesAreNeverTaken();

private:
    // The simulated ipc300@1, ipc300@2 (with the values expectedValue gives) and
    // dtron300@4 behind a gateway that lies when told to, and a bus polling the two IPCs.
    struct Lying
    {
        Lying() : gateway(&line) { }
        SimulatorLine line;
        LyingGateway gateway;
        Bus bus;
        DeviceId first = 0;
        DeviceId second = 0;
        Observer observed;
    };
    bool prepare(Lying &s);
    struct Setup
    {
        explicit Setup(const QString &kind, const QString &peer) : far(kind, peer) { }
        FarEnd far;
        Bus bus;
        DeviceId first = 0;
        DeviceId second = 0;
        Observer observed;
    };
    bool prepare(Setup &s, int retries = 2);
    QTemporaryDir m_logs;
    static void addRows(const QStringList &kinds);
};

void tst_LineKinds::initTestCase()
{
    qputenv("JUMO_MAP_PATH", "");
    qputenv("XDG_DATA_HOME", QByteArray(QDir::tempPath().toUtf8() + "/jumo-test-no-maps"));
    QVERIFY(m_logs.isValid());
    qputenv("JUMO_LOG_DIR", m_logs.path().toUtf8());   // jumoctl's audit log, in this test's own folder
}

void tst_LineKinds::addRows(const QStringList &kinds)
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("peer");
    for (const QString &kind : kinds) {
        for (const char *peer : {"simulator", "libmodbus"})
            QTest::addRow("%s: %s", qPrintable(kind), peer) << kind << QString(peer);
    }
}

// The bus on a line, polling ipc300@1 and ipc300@2, every value watched.
static bool openBus(Bus &bus, const QString &url, int retries, DeviceId *first, DeviceId *second, Observer &observed)
{
    BusSettings settings;
    settings.portName = url;
    settings.format = testFormat();
    settings.retries = retries;   // the timeout is derived: the family's at 19200 baud + the network margin
    bus.setSettings(settings);
    if (!bus.open())
        return false;
    const auto map = families().family("ipc300");
    *first = bus.addDevice(map, 1);
    *second = bus.addDevice(map, 2);
    for (DeviceId id : {*first, *second})
        bus.setPollEntries(id, polledIds);
    watch(bus, observed);
    return true;
}

bool tst_LineKinds::prepare(Setup &s, int retries)
{
    return s.far.start({1, 2}) && openBus(s.bus, s.far.url(), retries, &s.first, &s.second, s.observed);
}

void tst_LineKinds::readsAndWrites_data()
{
    addRows({"tcp", "rtu+tcp"});
}

void tst_LineKinds::readsAndWrites()
{
    QFETCH(QString, kind);
    QFETCH(QString, peer);
    Setup s(kind, peer);
    QVERIFY(prepare(s));
    QCOMPARE(s.bus.lineKind(), kind == "tcp" ? LineAddress::Kind::ModbusTcp : LineAddress::Kind::RtuOverTcp);
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 4 && s.observed.good.value(s.second) >= 4, 20000);
    QCOMPARE(s.observed.wrong, 0);
    QCOMPARE(s.bus.statistics(s.first)->timeouts, 0);

    // A float as one 0x10 write, confirmed by reading it back; the far end has it.
    s.bus.setPolling(false);
    QSignalSpy finished(&s.bus, &Bus::writeFinished);
    s.bus.write(s.first, "input_setpoint", "12.34");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 10000);
    const WriteOutcome outcome = finished.at(0).at(1).value<WriteOutcome>();
    QVERIFY2(outcome.result == WriteOutcome::Result::Confirmed, qPrintable(outcome.message));
    QCOMPARE(outcome.readBack.display, QString("12.34"));
    QCOMPARE(s.far.peer()->words(1, 0x00D5, 2), ValueCodec::encodeFloat(12.34f, WordOrder::CDAB));
    QCOMPARE(s.far.peer()->writeFrames(), 1);
    // The timeout counts the gateway's serial side and the network.
    QVERIFY(s.bus.requestTimeoutMs(families().family("ipc300")->protocol, 8, 9) >= LineTiming::networkMarginMs);
}

void tst_LineKinds::gatewayGoesAwayAndComesBack_data()
{
    addRows({"tcp", "rtu+tcp"});
}

void tst_LineKinds::gatewayGoesAwayAndComesBack()
{
    QFETCH(QString, kind);
    QFETCH(QString, peer);
    Setup s(kind, peer);
    QVERIFY(prepare(s));
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 4, 20000);
    QSignalSpy lineErrors(&s.bus, &Bus::lineError);

    s.far.goAway();
    QTRY_COMPARE_WITH_TIMEOUT(s.bus.state(), LineState::Lost, 10000);
    QVERIFY(!lineErrors.isEmpty());
    // Every value is unknown at once, not left to go stale.
    for (DeviceId id : {s.first, s.second}) {
        QCOMPARE(s.bus.condition(id).state, DeviceCondition::State::LineLost);
        for (const QString &entry : polledIds)
            QCOMPARE(s.bus.entryState(id, entry)->validity, Validity::Unknown);
    }
    // While it is away the line stays lost: failed attempts do not make it "connected".
    QSignalSpy states(&s.bus, &Bus::stateChanged);
    QTest::qWait(2500);
    QCOMPARE(states.count(), 0);
    QCOMPARE(s.bus.state(), LineState::Lost);

    QVERIFY(s.far.comeBack());
    QTRY_COMPARE_WITH_TIMEOUT(s.bus.state(), LineState::Connected, 15000);
    s.observed = Observer();
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 2 && s.observed.good.value(s.second) >= 2, 20000);
    QCOMPARE(s.observed.wrong, 0);
}

void tst_LineKinds::strayByteBeforeReplyIsSkipped_data()
{
    addRows({"rtu+tcp"});
}

void tst_LineKinds::strayByteBeforeReplyIsSkipped()
{
    QFETCH(QString, kind);
    QFETCH(QString, peer);
    Setup s(kind, peer);
    QVERIFY(prepare(s));
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 4, 20000);
    s.observed = Observer();
    // Qt's RTU client loses every such reply; this transport finds the reply behind it.
    QVERIFY(s.far.peer()->setFault(1, "stray", 3, 0));
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 8, 20000);
    QCOMPARE(s.observed.wrong, 0);
    QCOMPARE(s.bus.statistics(s.first)->timeouts, 0);
    QVERIFY2(!s.observed.statuses.contains("1:timeout"), qPrintable(QStringList(s.observed.statuses.values()).join(' ')));
}

void tst_LineKinds::gatewayExceptions_data()
{
    addRows({"tcp"});
}

void tst_LineKinds::gatewayExceptions()
{
    QFETCH(QString, kind);
    QFETCH(QString, peer);
    Setup s(kind, peer);
    QVERIFY(prepare(s, 1));
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 2, 20000);
    const auto map = families().family("ipc300");
    QVERIFY2(map->exceptionMeaning(0x0A).contains("gateway"), qPrintable(map->exceptionMeaning(0x0A)));
    QVERIFY2(map->exceptionMeaning(0x0B).contains("gateway"), qPrintable(map->exceptionMeaning(0x0B)));

    // Reads answered 0x0B: the device does not answer; shown as the gateway's exception,
    // and the device goes offline as after timeouts (a device's own exception would not).
    QVERIFY(s.far.peer()->setFault(1, "exception", -1, 0x0B));
    QTRY_VERIFY_WITH_TIMEOUT(!s.bus.isOnline(s.first), 20000);
    QVERIFY(s.observed.statuses.contains("1:exception:11"));
    QVERIFY(s.bus.isOnline(s.second));
    QVERIFY(s.far.peer()->setFault(1, "none"));
    QTRY_VERIFY_WITH_TIMEOUT(s.bus.isOnline(s.first), 20000);

    s.bus.setPolling(false);
    QTest::qWait(500);
    QSignalSpy finished(&s.bus, &Bus::writeFinished);
    const QList<quint16> before = s.far.peer()->words(1, 0x00D5, 2);

    // 0x0A: the gateway could not pass the write on; nothing changed.
    QVERIFY(s.far.peer()->setFault(1, "exception", 1, 0x0A));
    int frames = s.far.peer()->writeFrames();
    s.bus.write(s.first, "input_setpoint", "33");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 10000);
    WriteOutcome outcome = finished.at(0).at(1).value<WriteOutcome>();
    QCOMPARE(outcome.result, WriteOutcome::Result::Refused);
    QCOMPARE(outcome.exceptionCode, 0x0A);
    QVERIFY2(outcome.message.contains("gateway could not reach the device"), qPrintable(outcome.message));
    QCOMPARE(s.far.peer()->writeFrames(), frames + 1);
    QCOMPARE(s.far.peer()->words(1, 0x00D5, 2), before);

    // 0x0B: it may have reached the device; unknown, and never sent again.
    QVERIFY(s.far.peer()->setFault(1, "exception", 1, 0x0B));
    frames = s.far.peer()->writeFrames();
    s.bus.write(s.first, "input_setpoint", "34");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 10000);
    outcome = finished.at(1).at(1).value<WriteOutcome>();
    QCOMPARE(outcome.result, WriteOutcome::Result::Unknown);
    QCOMPARE(outcome.exceptionCode, 0x0B);
    QVERIFY2(outcome.message.contains("may or may not have reached it"), qPrintable(outcome.message));
    QTest::qWait(1000);
    QCOMPARE(s.far.peer()->writeFrames(), frames + 1);
}

void tst_LineKinds::unitWithoutDeviceIsOffline_data()
{
    addRows({"tcp"});
}

void tst_LineKinds::unitWithoutDeviceIsOffline()
{
    QFETCH(QString, kind);
    QFETCH(QString, peer);
    Setup s(kind, peer);
    QVERIFY(prepare(s, 0));
    const DeviceId absent = s.bus.addDevice(families().family("ipc300"), 7);
    s.bus.setPollEntries(absent, polledIds);
    // The gateway answers for the silent unit with 0x0B: offline, never "online with exceptions".
    QTRY_VERIFY2_WITH_TIMEOUT(s.observed.statuses.contains("7:exception:11"),
                              qPrintable(QStringList(s.observed.statuses.values()).join(' ')), 20000);
    QTRY_COMPARE_WITH_TIMEOUT(s.bus.condition(absent).state, DeviceCondition::State::Offline, 20000);
    QVERIFY(!s.bus.isOnline(absent));
    QVERIFY(s.bus.isOnline(s.first));
}

void tst_LineKinds::broadcastRefusedThroughGateway()
{
    Setup s("tcp", "libmodbus");
    QVERIFY(prepare(s));
    QSignalSpy finished(&s.bus, &Bus::writeFinished);
    s.bus.writeBroadcast("ipc300", "input_setpoint", "50");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 10000);
    const WriteOutcome outcome = finished.at(0).at(1).value<WriteOutcome>();
    QCOMPARE(outcome.result, WriteOutcome::Result::Invalid);
    QVERIFY2(outcome.message.contains("Modbus TCP gateway"), qPrintable(outcome.message));

    // jumoctl says so before any scan or identity check.
    const Run r = run({"write", "--port", s.far.url(), "--baud", "19200", "ipc300@0", "input_setpoint=50", "--verify", "1",
                       "--line-has-only", "ipc300"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("no broadcast through a Modbus TCP gateway"), qPrintable(r.err));
    QCOMPARE(s.far.peer()->writeFrames(), 0);
}

void tst_LineKinds::broadcastOverDeviceServer_data()
{
    addRows({"rtu+tcp"});
}

void tst_LineKinds::broadcastOverDeviceServer()
{
    QFETCH(QString, kind);
    QFETCH(QString, peer);
    Setup s(kind, peer);
    QVERIFY(prepare(s));
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 1 && s.observed.good.value(s.second) >= 1, 20000);
    // Raw RTU frames: address 0 reaches every device as on a serial line, and each is read back.
    QSignalSpy finished(&s.bus, &Bus::writeFinished);
    s.bus.writeBroadcast("ipc300", "input_setpoint", "50");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 15000);
    const WriteOutcome outcome = finished.at(0).at(1).value<WriteOutcome>();
    QVERIFY2(outcome.result == WriteOutcome::Result::Confirmed, qPrintable(outcome.message));
    for (quint8 slave : {quint8(1), quint8(2)})
        QCOMPARE(s.far.peer()->words(slave, 0x00D5, 2), ValueCodec::encodeFloat(50.0f, WordOrder::CDAB));
}

void tst_LineKinds::unreachableGatewayIsALostLine_data()
{
    QTest::addColumn<QString>("kind");
    QTest::newRow("tcp") << "tcp";
    QTest::newRow("rtu+tcp") << "rtu+tcp";
}

void tst_LineKinds::unreachableGatewayIsALostLine()
{
    QFETCH(QString, kind);
    const quint16 closed = freeTcpPort();   // nobody listens there
    Bus bus;
    BusSettings settings;
    settings.portName = QStringLiteral("%1://127.0.0.1:%2").arg(kind).arg(closed);
    settings.format = testFormat();
    bus.setSettings(settings);
    const DeviceId id = bus.addDevice(families().family("ipc300"), 1);
    QSignalSpy lineErrors(&bus, &Bus::lineError);
    QVERIFY(bus.open());   // connecting is asynchronous ...
    QTRY_COMPARE_WITH_TIMEOUT(bus.state(), LineState::Lost, 10000);   // ... and its failure a loss
    QVERIFY(!lineErrors.isEmpty());
    QVERIFY2(lineErrors.first().first().toString().contains(QString::number(closed)),
             qPrintable(lineErrors.first().first().toString()));
    QCOMPARE(bus.condition(id).state, DeviceCondition::State::LineLost);

    const Run r = run({"read", "--port", settings.portName, "--baud", "19200", "ipc300@1", "load_voltage"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("127.0.0.1:" + QString::number(closed)), qPrintable(r.err));
}

void tst_LineKinds::jumoctlReadsEachKind_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("peer");
    QTest::newRow("tcp: jumo-sim") << "tcp" << "jumo-sim";
    QTest::newRow("rtu+tcp: jumo-sim") << "rtu+tcp" << "jumo-sim";
    QTest::newRow("rtu+tcp: socat + jumo-sim") << "rtu+tcp" << "socat + jumo-sim";
    QTest::newRow("tcp: libmodbus") << "tcp" << "libmodbus";
    QTest::newRow("rtu+tcp: socat + libmodbus") << "rtu+tcp" << "libmodbus";
}

void tst_LineKinds::jumoctlReadsEachKind()
{
    QFETCH(QString, kind);
    QFETCH(QString, peer);
    QString url;
    QProcess sim;
    DeviceServer deviceServer;
    std::unique_ptr<FarEnd> far;
    auto stopSim = qScopeGuard([&sim] {
        if (sim.state() != QProcess::NotRunning) {
            sim.terminate();
            if (!sim.waitForFinished(3000))
                sim.kill();
        }
    });
    if (peer == "jumo-sim") {
        // jumo-sim as the gateway or device server itself, on a port it picks.
        url = startJumoSim(sim, kind, "127.0.0.1:0");
        QVERIFY2(url.startsWith(kind + "://127.0.0.1:"), qPrintable(url));
    } else if (peer == "socat + jumo-sim") {
        // A serial device server in front of jumo-sim on a pty, as in a cabinet.
        QVERIFY(deviceServer.start());
        sim.start(QStringLiteral(JUMO_SIM_PATH),
                  {"--port", deviceServer.ptyPath(), "--baud", "38400", "ipc300@1", "tya200@2"});
        QVERIFY(sim.waitForStarted(5000));
        QVERIFY(sim.waitForReadyRead(10000));
        url = deviceServer.url();
    } else {
        far = std::make_unique<FarEnd>(kind, peer);
        QVERIFY(far->start({1, 2}));
        url = far->url();
    }
    const QStringList line{"--port", url, "--baud", "38400"};
    if (peer == "libmodbus") {
        // The libmodbus peer has no identity registers: the read goes without the check.
        const Run r = run(QStringList{"read", "--no-identify"} + line + QStringList{"ipc300@1", "load_voltage", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonArray rows = QJsonDocument::fromJson(r.out.toUtf8()).array();
        QCOMPARE(rows.size(), 1);
        QCOMPARE(rows[0].toObject()["value"].toDouble(), expectedValue("load_voltage", 1));
        return;
    }
    const Run r = run(QStringList{"read"} + line + QStringList{"ipc300@1", "load_voltage", "load_current"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QVERIFY2(r.out.contains("load_voltage = "), qPrintable(r.out));
    if (peer == "socat + jumo-sim")
        return;   // socat served its one connection and ended
    const Run two = run(QStringList{"read"} + line + QStringList{"tya200@2", "setpoint"});
    QVERIFY2(two.code == 0, qPrintable(two.err));
    QVERIFY2(two.out.contains("setpoint = "), qPrintable(two.out));
    // A scan: quick behind a device server, thorough through a gateway (which answers each
    // request itself, at its own timeout), and it says which before it starts.
    const Run scan = run(QStringList{"scan"} + line + QStringList{"--from", "1", "--to", "12"});
    QVERIFY2(scan.code == 0, qPrintable(scan.err));
    QVERIFY2(scan.out.contains("ipc300@1\t") && scan.out.contains("tya200@2\t"), qPrintable(scan.out));
    QCOMPARE(scan.out.split('\n', Qt::SkipEmptyParts).size(), 2);
    const QString plan = kind == "tcp" ? "thorough scan of addresses 1..12 (a Modbus TCP gateway answers every request "
                                         "itself, at its own timeout)"
                                       : "quick scan of addresses 1..12: each probed once at ";
    QVERIFY2(scan.err.contains(plan), qPrintable(scan.err));
}

void tst_LineKinds::simulatedGatewayEchoesTransactionIds()
{
    SimulatorLine line;
    line.setFormat(testFormat());
    line.addDevice(families().family("ipc300"), 1);
    SimulatorServer gateway(&line, SimulatorServer::Mode::ModbusTcp);
    QVERIFY(gateway.listen(QHostAddress::LocalHost, 0));
    QTcpSocket client;
    client.connectToHost(QHostAddress::LocalHost, gateway.port());
    QVERIFY(client.waitForConnected(5000));
    // Two requests under way at once: the device's read and one for a unit nobody has.
    client.write(QByteArray::fromHex("123400000006" "01" "0300B10002") + QByteArray::fromHex("123500000006" "09" "0300B10002"));
    QByteArray replies;
    QTRY_VERIFY_WITH_TIMEOUT((replies += client.readAll()).size() >= 13 + 9, 5000);
    QCOMPARE(replies.left(7).toHex(), QByteArray("12340000000701"));   // MBAP: its id, length 7, unit 1
    QCOMPARE(replies.mid(7, 2).toHex(), QByteArray("0304"));            // 2 words
    QCOMPARE(replies.mid(13).toHex(), QByteArray("123500000003" "09" "830b"));   // the gateway's 0x0B
}

void tst_LineKinds::jumoctlReadsOverIpv6_data()
{
    QTest::addColumn<QString>("kind");
    QTest::newRow("tcp://[::1]") << "tcp";
    QTest::newRow("rtu+tcp://[::1]") << "rtu+tcp";
}

void tst_LineKinds::jumoctlReadsOverIpv6()
{
    QFETCH(QString, kind);
    {
        QTcpServer probe;
        if (!probe.listen(QHostAddress::LocalHostIPv6, 0))
            QSKIP("this machine has no IPv6 loopback (::1)");
    }
    QProcess sim;
    auto stopSim = qScopeGuard([&sim] {
        sim.terminate();
        if (!sim.waitForFinished(3000))
            sim.kill();
    });
    // README's own syntax: the address in brackets.
    const QString url = startJumoSim(sim, kind, "[::1]:0");
    QVERIFY2(url.startsWith(kind + "://[::1]:"), qPrintable(url));
    const QStringList line{"--port", url, "--baud", "38400"};
    const Run r = run(QStringList{"read"} + line + QStringList{"ipc300@1", "load_voltage"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QVERIFY2(r.out.contains("load_voltage = "), qPrintable(r.out));
}

bool tst_LineKinds::prepare(Lying &s)
{
    s.line.setFormat(testFormat());
    const auto map = families().family("ipc300");
    for (quint8 slave : {quint8(1), quint8(2)}) {
        s.line.addDevice(map, slave);
        for (const QString &id : polledIds) {
            if (!s.line.device(slave)->setWords(map->entry(id)->address,
                                                ValueCodec::encodeFloat(float(expectedValue(id, slave)), WordOrder::CDAB)))
                return false;
        }
    }
    s.line.addDevice(families().family("dtron300"), 4);
    return s.gateway.listen() && openBus(s.bus, s.gateway.url(), 1, &s.first, &s.second, s.observed);
}

void tst_LineKinds::lyingGatewayNeverGivesAnotherUnitsValue_data()
{
    QTest::addColumn<int>("lie");
    QTest::newRow("unit 2's reply to unit 1") << int(LyingGateway::Lie::OtherUnitsReply);
    QTest::newRow("unit 1's reply said to be unit 2's") << int(LyingGateway::Lie::UnitIdChanged);
    QTest::newRow("unit 1's reply with protocol id 1") << int(LyingGateway::Lie::ProtocolIdChanged);
}

void tst_LineKinds::lyingGatewayNeverGivesAnotherUnitsValue()
{
    QFETCH(int, lie);
    Lying s;
    QVERIFY(prepare(s));
    s.gateway.lie(1, LyingGateway::Lie(lie));
    // Unit 2 is read as it is; no reply for unit 1 is taken, and unit 1 goes offline.
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.second) >= 4, 20000);
    QTRY_COMPARE_WITH_TIMEOUT(s.bus.condition(s.first).state, DeviceCondition::State::Offline, 20000);
    QCOMPARE(s.observed.wrong, 0);
    QCOMPARE(s.observed.good.value(s.first), 0);
    QVERIFY(s.bus.statistics(s.first)->mismatches > 0);
    QVERIFY(s.bus.isOnline(s.second));

    // jumoctl says it has no value, never unit 2's.
    const Run r = run({"read", "--port", s.gateway.url(), "--baud", "19200", "ipc300@1", "load_voltage"});
    QVERIFY2(r.code != 0, qPrintable(r.out));
    QVERIFY2(!r.out.contains("202"), qPrintable(r.out));
    QVERIFY2(!r.err.isEmpty(), "says why");

    // Told the truth again, unit 1 comes back.
    s.gateway.lie(1, LyingGateway::Lie::None);
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 2, 40000);
    QCOMPARE(s.observed.wrong, 0);
}

void tst_LineKinds::lyingGatewayNeverConfirmsAWrite_data()
{
    QTest::addColumn<int>("lie");
    QTest::newRow("unit 2's echo") << int(LyingGateway::Lie::OtherUnitsReply);
    QTest::newRow("unit 1's echo said to be unit 2's") << int(LyingGateway::Lie::UnitIdChanged);
    QTest::newRow("unit 1's echo with protocol id 1") << int(LyingGateway::Lie::ProtocolIdChanged);
}

void tst_LineKinds::lyingGatewayNeverConfirmsAWrite()
{
    QFETCH(int, lie);
    Lying s;
    QVERIFY(prepare(s));
    const DeviceId dtron = s.bus.addDevice(families().family("dtron300"), 4);
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 2, 20000);
    s.bus.setPolling(false);
    QSignalSpy finished(&s.bus, &Bus::writeFinished);

    // A value: repeated (it is safe), never confirmed by a reply that is not its own.
    s.gateway.lie(1, LyingGateway::Lie(lie), -1, true);
    s.bus.write(s.first, "input_setpoint", "12.5");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 20000);
    WriteOutcome outcome = finished.at(0).at(1).value<WriteOutcome>();
    QVERIFY2(outcome.result == WriteOutcome::Result::Unknown, qPrintable(outcome.message));
    QVERIFY2(outcome.message.contains("may or may not"), qPrintable(outcome.message));

    // A command: sent once, its outcome unknown.
    s.gateway.lie(4, LyingGateway::Lie(lie), -1, true);
    const int frames = s.line.writeRequestsReceived();
    s.bus.write(dtron, "program_controller_functions", "segment_change");
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 20000);
    outcome = finished.at(1).at(1).value<WriteOutcome>();
    QVERIFY2(outcome.result == WriteOutcome::Result::Unknown, qPrintable(outcome.message));
    QVERIFY2(outcome.message.contains("not sent again"), qPrintable(outcome.message));
    QTest::qWait(1000);
    QCOMPARE(s.line.writeRequestsReceived(), frames + 1);
}

void tst_LineKinds::connectionCutUnderAWriteLeavesItUnknown()
{
    // The device took the value; the gateway's connection broke in the middle of the
    // reply. jumoctl says unknown (exit 3), not only "line lost", and audits the write.
    Lying s;
    QVERIFY(prepare(s));
    s.bus.close();
    s.gateway.lie(1, LyingGateway::Lie::CutMidReply, 1, true);
    const int frames = s.line.writeRequestsReceived();
    const Run r = run({"write", "--port", s.gateway.url(), "--baud", "19200", "ipc300@1", "input_setpoint=43.5"});
    QVERIFY2(r.code == 3, qPrintable(QString::number(r.code) + ": " + r.err));
    QVERIFY2(r.err.contains("unknown, check the device"), qPrintable(r.err));
    QCOMPARE(s.line.writeRequestsReceived(), frames + 1);
    QFile audit(QDir(m_logs.path()).filePath("write-audit.jsonl"));
    QVERIFY(audit.open(QIODevice::ReadOnly));
    const QList<QByteArray> records = audit.readAll().trimmed().split('\n');
    const QJsonObject last = QJsonDocument::fromJson(records.constLast()).object();
    QCOMPARE(last["entry"].toString(), QString("input_setpoint"));
    QCOMPARE(last["result"].toString(), QString("unknown"));
}

void tst_LineKinds::badGatewayFrameDoesNotCutADeviceOff_data()
{
    QTest::addColumn<int>("lie");
    QTest::addColumn<int>("count");
    QTest::newRow("13 junk bytes after one reply") << int(LyingGateway::Lie::JunkAfterReply) << 1;
    QTest::newRow("one MBAP length 2 bytes short") << int(LyingGateway::Lie::LengthTwoShort) << 1;
    QTest::newRow("junk after every reply") << int(LyingGateway::Lie::JunkAfterReply) << -1;
}

void tst_LineKinds::badGatewayFrameDoesNotCutADeviceOff()
{
    QFETCH(int, lie);
    QFETCH(int, count);
    Lying s;
    QVERIFY(prepare(s));
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 2 && s.observed.good.value(s.second) >= 2, 20000);
    const int connections = s.gateway.connections();
    s.gateway.lie(1, LyingGateway::Lie(lie), count);
    s.observed = Observer();
    QElapsedTimer clock;
    clock.start();
    // The connection is made anew and the device answers again.
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 4, 20000);
    qInfo("unit 1 read 4 times again %lld ms after the bad frame(s); %d new connection(s)", clock.elapsed(),
          s.gateway.connections() - connections);
    QVERIFY(s.gateway.connections() > connections);
    QCOMPARE(s.observed.wrong, 0);
    QCOMPARE(s.bus.state(), LineState::Connected);
    QVERIFY(s.bus.isOnline(s.first));
    QVERIFY(s.bus.isOnline(s.second));

    // jumoctl reads it through the same gateway afterwards.
    s.bus.close();
    const Run r = run({"read", "--port", s.gateway.url(), "--baud", "19200", "ipc300@1", "load_voltage", "--json"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    const QJsonArray rows = QJsonDocument::fromJson(r.out.toUtf8()).array();
    QCOMPARE(rows.size(), 1);
    QCOMPARE(rows[0].toObject()["value"].toDouble(), expectedValue("load_voltage", 1));
}

void tst_LineKinds::deviceServerLateRepliesAreNeverTaken()
{
    Setup s("rtu+tcp", "simulator");
    QVERIFY(prepare(s));
    QTRY_VERIFY_WITH_TIMEOUT(s.observed.good.value(s.first) >= 4, 20000);
    // Every reply of unit 1 comes 0.75 s late, beyond its timeout: its two polled
    // blocks have replies of one shape, so a late reply fits the next request.
    QVERIFY(s.far.peer()->setFault(1, "late", -1, 750));
    QTRY_COMPARE_WITH_TIMEOUT(s.bus.condition(s.first).state, DeviceCondition::State::Offline, 40000);
    QTest::qWait(3000);
    QCOMPARE(s.observed.wrong, 0);
    QVERIFY(s.bus.statistics(s.first)->mismatches > 0);
    QVERIFY(s.bus.isOnline(s.second));

    // jumoctl reading that device says it has no value, never another block's.
    s.bus.close();
    const Run r = run({"read", "--port", s.far.url(), "--baud", "19200", "--no-identify", "ipc300@1", "load_voltage",
                       "analog_output_value", "--json"});
    for (const QJsonValue &row : QJsonDocument::fromJson(r.out.toUtf8()).array()) {
        const QJsonObject o = row.toObject();
        QVERIFY2(o["status"].toString() != "ok"
                         || std::fabs(o["value"].toDouble() - expectedValue(o["id"].toString(), 1)) < 1e-3,
                 qPrintable(r.out));
    }
}

QTEST_GUILESS_MAIN(tst_LineKinds)
#include "tst_linekinds.moc"
