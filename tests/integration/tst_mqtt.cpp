// The station published over MQTT, end to end with real parts: Debian's Mosquitto, the
// simulator on a pty line, the jumo-publisher program, mosquitto_sub as an independent
// subscriber and RemoteStation as the viewers' mirror. The line dies, the publisher is
// killed, stopped, frozen, the broker is killed and started again: what viewers see must
// follow each time.
#include "mosquittobroker.h"
#include "bus/bus.h"
#include "bus/pollselection.h"
#include "models/livevaluesmodel.h"
#include "mqtt/remotelines.h"
#include "mqtt/remotestation.h"
#include "mqtt/stationpublisher.h"
#include "protocol/valuecodec.h"
#include "testpeers.h"

#include <QAbstractItemModelTester>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSocketNotifier>

#include <csignal>
#include <fcntl.h>
#include <unistd.h>

using namespace jumo;
using namespace jumo::test;

namespace {

const QString station = QStringLiteral("teststation");

QJsonObject json(const QByteArray &payload)
{
    return QJsonDocument::fromJson(payload).object();
}

// Entries of a device that count as what a station publishes (read, no reserves).
int publishedEntries(const QString &family)
{
    int n = 0;
    for (const RegisterEntry &e : families().family(family)->entries())
        n += e.isReadable() && !e.reserved ? 1 : 0;
    return n;
}

} // namespace

class TstMqtt : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void freshSubscribersGetTheWholeStateAtOnce();
    void changedValueArrives();
    void lostLineMakesValuesUnknown();
    void killedPublisherLeavesItsWill();
    void remoteLinesShowWhatTheStationShows();
    void silentStationGoesStale();
    void stopSignalsSayStopped_data();
    void stopSignalsSayStopped();
    void brokerRestartLosesNothing();
    void twoLinesFromAStationFile();
    void removedLineIsCleared();
    void pollSelectionAndAnEarlierRunsLeftovers();
    void aHugeLeftoverNeverHoldsUpTheStation();
    void aTakeOverStopsTheFirstPublisher();
    void secondPublisherOfOneNameRefuses();
    void garbageMakesNoDeviceAndNoHeartbeat();
    void devicesComeFromTheirInfoAlone();
    void aDeviceThatLeavesTheStationLeavesTheViewer();
    void viewersShowTheStationsOrder();
    void aForgedValueIsUndoneByTheStation();
    void viewerFindsOutThatItMayPublish();
    void theShippedAclKeepsRoguesOut();
    void floodsDoNotHoldUpTheStatus();
    void lineLossPublishesEachConditionOnce();
    void ageIsOfTheLastRead();
    void lostSinceIsWhenTheViewerLostContact();
    void aNewRunIsNotSilentBeforeItsFirstHeartbeat();
    void aDeviceTheNextRunDropsIsNeverRestored();
    void stalledBrokerIsNoRival();
    void passwordIsChecked();
    void tls();

private:
    bool startPublisher(const QString &broker, const QStringList &extra = {},
                        const QProcessEnvironment &environment = QProcessEnvironment::systemEnvironment());
    std::unique_ptr<RemoteStation> startMirror(const MqttSettings &settings);
    // A client of its own (a vandal, a listener), connected.
    std::unique_ptr<MqttClient> connectClient(const MqttSettings &settings);
    std::unique_ptr<MqttClient> connectClient() { return connectClient(*MqttSettings::fromUrl(brokerUrl(), nullptr)); }
    // The client ids that published something, from the broker's log.
    QSet<QString> publishingClients() const;
    // A station file of this test's line and a second one (its name and devices each).
    using LineDevices = QPair<QString, QStringList>;
    QString writeTwoLineStation(const TestLine &second, const LineDevices &first, const LineDevices &other);
    std::unique_ptr<RemoteStation> startMirror() { return startMirror(*MqttSettings::fromUrl(brokerUrl(), nullptr)); }
    QString brokerUrl() const { return QStringLiteral("mqtt://127.0.0.1:%1").arg(m_broker->port()); }
    // Every device online and every published entry current in the mirror.
    static bool everythingCurrent(const RemoteStation &mirror, int devices = 2);
    QString publisherErrors();

    std::unique_ptr<MosquittoBroker> m_broker;
    std::unique_ptr<TestLine> m_line;
    std::unique_ptr<SimulatorPeer> m_peer;
    std::unique_ptr<QProcess> m_publisher;
    QByteArray m_publisherErr;
    int m_publisherLogFd = -1;   // >= 0: the next publisher's stderr goes there, not to m_publisherErr
};

void TstMqtt::init()
{
    m_broker = std::make_unique<MosquittoBroker>();
    m_line = std::make_unique<TestLine>();
    QVERIFY(m_line->start());
    m_peer = std::make_unique<SimulatorPeer>(QStringLiteral("ipc300"));
    m_peer->line().addDevice(families().family(QStringLiteral("tya200")), 2);
    QVERIFY(m_peer->start(m_line->deviceEnd(), {1}));
}

void TstMqtt::cleanup()
{
    if (m_publisher && m_publisher->state() != QProcess::NotRunning) {
        m_publisher->kill();
        m_publisher->waitForFinished(10000);
    }
    if (QTest::currentTestFailed()) {
        qWarning().noquote() << "publisher:" << publisherErrors();
        QStringList events;   // connections, wills, subscriptions: not every message
        for (const QString &line : m_broker->log().split('\n')) {
            if (!line.contains(QLatin1String("PUBLISH")) && !line.contains(QLatin1String("PUBACK")))
                events << line;
        }
        qWarning().noquote() << "broker:" << events.mid(std::max<qsizetype>(0, events.size() - 60)).join('\n');
    }
    m_publisher.reset();
    m_publisherErr.clear();
    m_peer.reset();
    m_line.reset();
    m_broker.reset();
}

bool TstMqtt::startPublisher(const QString &broker, const QStringList &extra, const QProcessEnvironment &environment)
{
    const QStringList lines = extra.contains(QLatin1String("--station"))
            ? QStringList()
            : QStringList{QStringLiteral("--port"), m_line->masterEnd(), QStringLiteral("--baud"), QStringLiteral("19200"),
                          QStringLiteral("--device"), QStringLiteral("ipc300@1"), QStringLiteral("--device"),
                          QStringLiteral("tya200@2")};
    m_publisher = std::make_unique<QProcess>();
    m_publisher->setProcessEnvironment(environment);
    connect(m_publisher.get(), &QProcess::readyReadStandardError, this,
            [this] { m_publisherErr += m_publisher->readAllStandardError(); });
    if (const int fd = std::exchange(m_publisherLogFd, -1); fd >= 0)
        m_publisher->setChildProcessModifier([fd] { ::dup2(fd, STDERR_FILENO); });
    m_publisher->start(QStringLiteral(JUMO_PUBLISHER_PATH),
                       QStringList{QStringLiteral("--broker"), broker, QStringLiteral("--name"), station} + lines
                               + extra);
    return m_publisher->waitForStarted(10000);
}

std::unique_ptr<MqttClient> TstMqtt::connectClient(const MqttSettings &settings)
{
    auto client = std::make_unique<MqttClient>();
    client->setSettings(settings);
    if (!client->connectToBroker())
        return nullptr;
    QSignalSpy connected(client.get(), &MqttClient::connected);
    if (!client->isConnected() && !connected.wait(20000))
        return nullptr;
    return client;
}

QString TstMqtt::writeTwoLineStation(const TestLine &second, const LineDevices &first, const LineDevices &other)
{
    auto line = [](const LineDevices &devices, const QString &port) {
        return QJsonObject{{"name", devices.first}, {"port", port}, {"baud", 19200},
                           {"devices", QJsonArray::fromStringList(devices.second)}};
    };
    const QJsonObject station{{"format", "jumo-station"}, {"version", 1}, {"name", "ignored-by---name"},
                              {"lines", QJsonArray{line(first, m_line->masterEnd()), line(other, second.masterEnd())}}};
    QFile file(m_broker->file(QStringLiteral("station.json")));
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write(QJsonDocument(station).toJson());
    return file.fileName();
}

QSet<QString> TstMqtt::publishingClients() const
{
    QSet<QString> ids;
    static const QRegularExpression received(QStringLiteral("Received PUBLISH from (\\S+)"));
    for (const QString &line : m_broker->log().split('\n')) {
        const QRegularExpressionMatch m = received.match(line);
        if (m.hasMatch())
            ids.insert(m.captured(1));
    }
    return ids;
}

QString TstMqtt::publisherErrors()
{
    if (m_publisher)
        m_publisherErr += m_publisher->readAllStandardError();
    return QString::fromUtf8(m_publisherErr);
}

std::unique_ptr<RemoteStation> TstMqtt::startMirror(const MqttSettings &settings)
{
    auto mirror = std::make_unique<RemoteStation>(families());
    mirror->setStation(station);
    QString error;
    if (!mirror->start(settings, &error)) {
        qWarning().noquote() << error;
        return nullptr;
    }
    return mirror;
}

bool TstMqtt::everythingCurrent(const RemoteStation &mirror, int devices)
{
    if (mirror.devices().size() != devices || !mirror.isLive(station))
        return false;
    for (DeviceId id : mirror.devices()) {
        const RemoteDevice *d = mirror.device(id);
        if (!d->condition.isOnline() || mirror.entryIds(id).size() != publishedEntries(d->family))
            return false;
        for (const QString &entry : mirror.entryIds(id)) {
            const EntryState *s = mirror.entryState(id, entry);
            if (s->validity != Validity::Current && s->error != ReadError::NotAvailable && s->error != ReadError::Exception)
                return false;
        }
    }
    return true;
}

void TstMqtt::freshSubscribersGetTheWholeStateAtOnce()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);

    // An independent subscriber gets all of it from the retained messages alone.
    const QHash<QString, QByteArray> retained = retainedMessages(m_broker->port(), QStringLiteral("jumo/#"));
    const QString base = QStringLiteral("jumo/%1/").arg(station);
    QCOMPARE(json(retained.value(base + "status")).value("state").toString(), QStringLiteral("online"));
    QCOMPARE(json(retained.value(base + "status")).value("lines").toVariant().toStringList(), QStringList{"line1"});
    QCOMPARE(json(retained.value(base + "lines/line1")).value("state").toString(), QStringLiteral("connected"));
    QCOMPARE(json(retained.value(base + "lines/line1")).value("kind").toString(), QStringLiteral("rtu"));
    QVERIFY(!retained.contains(base + "heartbeat"));
    int values = 0;
    for (const QString &device : {QStringLiteral("ipc300@1"), QStringLiteral("tya200@2")}) {
        const QString family = device.section('@', 0, 0);
        QCOMPARE(json(retained.value(base + "devices/line1/" + device + "/info")).value("family").toString(), family);
        QCOMPARE(json(retained.value(base + "devices/line1/" + device + "/condition")).value("state").toString(),
                 QStringLiteral("online"));
        const auto id = mirror->findDevice(station, QStringLiteral("line1"), device);
        QVERIFY(id);
        for (const QString &entry : mirror->entryIds(*id)) {
            const QByteArray payload = retained.value(base + "devices/line1/" + device + "/values/" + entry);
            QVERIFY2(!payload.isEmpty(), qPrintable(device + " " + entry + " not retained"));
            // The same value as the mirror shows, decoded from the same words.
            QCOMPARE(json(payload).value("text").toString(), mirror->published(*id, entry)->text);
            ++values;
        }
    }
    QCOMPARE(values, publishedEntries("ipc300") + publishedEntries("tya200"));
    // Nothing else: info, condition and the values of two devices, the line, the status,
    // the device order and the mirror's presence (not under its client id).
    QCOMPARE(retained.size(), values + 2 * 2 + 1 + 1 + 1 + 1);
    QCOMPARE(json(retained.value(base + "order")).value("devices").toVariant().toStringList(),
             (QStringList{"line1/ipc300@1", "line1/tya200@2"}));
    QCOMPARE(json(retained.value(base + "viewers/" + mirror->viewerId())).value("state").toString(),
             QStringLiteral("watching"));
    for (auto it = retained.cbegin(); it != retained.cend(); ++it) {
        QVERIFY(!it.key().contains(mirror->client().clientId()));
        QVERIFY(!it.value().contains(mirror->client().clientId().toUtf8()));
    }

    // A second mirror, started now, has everything at once too.
    auto second = startMirror();
    QVERIFY(second);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*second), 10000);
}

void TstMqtt::changedValueArrives()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    const auto map = families().family(QStringLiteral("ipc300"));
    const RegisterEntry *voltage = map->entry(QStringLiteral("load_voltage"));
    QVERIFY(m_peer->setWords(1, voltage->address, ValueCodec::encodeFloat(123.5f, map->protocol.floatWordOrder)));
    const DeviceId id = *mirror->findDevice(station, QStringLiteral("line1"), QStringLiteral("ipc300@1"));
    QTRY_COMPARE_WITH_TIMEOUT(mirror->entryState(id, voltage->id)->value.value.toDouble(), 123.5, 10000);
    QCOMPARE(mirror->entryState(id, voltage->id)->validity, Validity::Current);
    QCOMPARE(mirror->published(id, voltage->id)->text, QStringLiteral("123.5 V"));
    const QByteArray retained = retainedMessages(m_broker->port(), QStringLiteral("jumo/%1/devices/line1/ipc300@1/values/load_voltage").arg(station),
                                                 {QStringLiteral("-C"), QStringLiteral("1")})
                                        .values()
                                        .value(0);
    QCOMPARE(json(retained).value("value").toDouble(), 123.5);
}

void TstMqtt::lostLineMakesValuesUnknown()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);

    m_line->stop();   // socat, by its PID: both ends of the line vanish
    QTRY_VERIFY_WITH_TIMEOUT(mirror->line(station, QStringLiteral("line1"))
                                     && mirror->line(station, QStringLiteral("line1"))->state == LineState::Lost,
                             10000);
    QVERIFY(!mirror->line(station, QStringLiteral("line1"))->error.isEmpty());
    for (DeviceId id : mirror->devices()) {
        QTRY_COMPARE_WITH_TIMEOUT(mirror->condition(id).state, DeviceCondition::State::LineLost, 10000);
        for (const QString &entry : mirror->entryIds(id)) {
            QTRY_COMPARE_WITH_TIMEOUT(mirror->entryState(id, entry)->validity, Validity::Unknown, 10000);
            QCOMPARE(mirror->published(id, entry)->status, QStringLiteral("line_lost"));
        }
    }
    // The station itself is alive: the values are unknown because of the line, not stale.
    QVERIFY(mirror->isLive(station));
    const QHash<QString, QByteArray> retained = retainedMessages(m_broker->port(), QStringLiteral("jumo/#"));
    QCOMPARE(json(retained.value("jumo/teststation/lines/line1")).value("state").toString(), QStringLiteral("lost"));
    const QJsonObject voltage = json(retained.value("jumo/teststation/devices/line1/ipc300@1/values/load_voltage"));
    QCOMPARE(voltage.value("validity").toString(), QStringLiteral("unknown"));
    QVERIFY(voltage.value("value").isNull());

    // Back: the line comes again, so do the values.
    m_peer->stop();   // its end of the old pair, if it has not noticed yet
    QVERIFY(m_line->restart());
    QVERIFY(m_peer->reopen());
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
}

void TstMqtt::killedPublisherLeavesItsWill()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);

    m_publisher->kill();   // SIGKILL to its PID: no goodbye
    QVERIFY(m_publisher->waitForFinished(10000));
    QTRY_VERIFY_WITH_TIMEOUT(!mirror->isLive(station), 2000);
    QVERIFY(mirror->station(station)->statusKnown);
    QVERIFY(!mirror->station(station)->status.online);
    QCOMPARE(mirror->station(station)->status.reason, QStringLiteral("connection lost"));
    for (DeviceId id : mirror->devices()) {
        for (const QString &entry : mirror->entryIds(id)) {
            const EntryState *s = mirror->entryState(id, entry);
            // What was current is stale now; the station's own word stays underneath.
            if (mirror->published(id, entry)->validity == Validity::Current)
                QCOMPARE(s->validity, Validity::Stale);
            QVERIFY(s->validity != Validity::Current);
        }
    }
    const QHash<QString, QByteArray> retained =
            retainedMessages(m_broker->port(), QStringLiteral("jumo/%1/status").arg(station), {"-C", "1"});
    QCOMPARE(json(retained.value("jumo/teststation/status")),
             QJsonObject({{"state", "offline"}, {"reason", "connection lost"}}));

    // A new publisher: current again.
    QVERIFY(startPublisher(brokerUrl()));
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
}

// The remote HMI's lines: the mirror's devices as MirroredLines under the same models a
// station's own lines have. They show what the station published, and a dead station as
// lost, with its values stale, never as current.
void TstMqtt::remoteLinesShowWhatTheStationShows()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    RemoteLines lines(mirror.get());
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    QCOMPARE(lines.lines().size(), 1);
    MirroredLine *line = lines.lines().constFirst();
    QCOMPARE(lines.stationOf(line), station);
    QCOMPARE(line->devices().size(), 2);
    QCOMPARE(line->state(), LineState::Connected);
    const DeviceId ipc = line->device(QStringLiteral("ipc300"), 1);
    QVERIFY(ipc >= 0);
    QVERIFY(line->condition(ipc).isOnline());

    LiveValuesModel values(line, ipc);
    QAbstractItemModelTester tester(&values, QAbstractItemModelTester::FailureReportingMode::QtTest);
    const int row = values.rowOf(QStringLiteral("load_voltage"));
    QVERIFY(row >= 0);
    const QModelIndex index = values.index(row, LiveValuesModel::ValueColumn);
    QTRY_COMPARE_WITH_TIMEOUT(values.data(index, LiveValuesModel::ValidityRole).toInt(), int(Validity::Current), 10000);
    // The same text the station published, made here from the words through the map.
    const RemoteDevice *remote = nullptr;
    for (DeviceId id : mirror->devices()) {
        if (mirror->device(id)->name == QLatin1String("ipc300@1"))
            remote = mirror->device(id);
    }
    QVERIFY(remote);
    QCOMPARE(values.data(index, LiveValuesModel::ValueWithUnitRole).toString(),
             mirror->published(remote->id, QStringLiteral("load_voltage"))->text);

    // A value changed in the simulator reaches the viewer's model.
    const auto map = families().family(QStringLiteral("ipc300"));
    const RegisterEntry *voltage = map->entry(QStringLiteral("load_voltage"));
    QVERIFY(m_peer->setWords(1, voltage->address, ValueCodec::encodeFloat(187.5f, map->protocol.floatWordOrder)));
    QTRY_COMPARE_WITH_TIMEOUT(values.data(index, LiveValuesModel::NumericRole).toDouble(), 187.5, 10000);

    m_publisher->kill();
    QVERIFY(m_publisher->waitForFinished(10000));
    QTRY_COMPARE_WITH_TIMEOUT(line->state(), LineState::Lost, 2000);
    QVERIFY2(line->stateReason().contains(QLatin1String("offline")), qPrintable(line->stateReason()));
    QCOMPARE(line->condition(ipc).state, DeviceCondition::State::LineLost);
    QCOMPARE(values.data(index, LiveValuesModel::ValidityRole).toInt(), int(Validity::Stale));
    QVERIFY(!values.data(index, LiveValuesModel::NumericRole).isValid());

    QVERIFY(startPublisher(brokerUrl()));
    QTRY_COMPARE_WITH_TIMEOUT(line->state(), LineState::Connected, 30000);
    QTRY_COMPARE_WITH_TIMEOUT(values.data(index, LiveValuesModel::ValidityRole).toInt(), int(Validity::Current), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(line->condition(ipc).isOnline(), 10000);
}

void TstMqtt::silentStationGoesStale()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    const DeviceId id = *mirror->findDevice(station, QStringLiteral("line1"), QStringLiteral("ipc300@1"));

    // Frozen: its connection stays open, so the broker sends no will for a while; the
    // missing heartbeat tells.
    QCOMPARE(::kill(pid_t(m_publisher->processId()), SIGSTOP), 0);
    QTRY_VERIFY_WITH_TIMEOUT(!mirror->isLive(station), 5000);
    QVERIFY(mirror->station(station)->status.online);
    QVERIFY(mirror->station(station)->silent);
    QCOMPARE(mirror->entryState(id, QStringLiteral("load_voltage"))->validity, Validity::Stale);
    QCOMPARE(mirror->entryState(id, QStringLiteral("load_voltage"))->statusName(), QStringLiteral("stale"));

    QCOMPARE(::kill(pid_t(m_publisher->processId()), SIGCONT), 0);
    QTRY_VERIFY_WITH_TIMEOUT(mirror->isLive(station), 10000);
    QTRY_COMPARE_WITH_TIMEOUT(mirror->entryState(id, QStringLiteral("load_voltage"))->validity, Validity::Current, 10000);
}

void TstMqtt::stopSignalsSayStopped_data()
{
    QTest::addColumn<int>("signal");
    QTest::addColumn<bool>("logReaderGone");
    QTest::addColumn<int>("exitCode");
    QTest::newRow("SIGTERM, as systemd stops it") << int(SIGTERM) << false << 0;
    QTest::newRow("SIGINT, Ctrl+C") << int(SIGINT) << false << 0;
    QTest::newRow("SIGHUP, a closed terminal: 129 as jumoctl") << int(SIGHUP) << false << 129;
    // No signal: libmosquitto ignores SIGPIPE. It sees for itself that nobody reads.
    QTest::newRow("its log's reader gone: 141 as jumoctl's SIGPIPE") << 0 << true << 141;
    // Its log still read: the signal came from a socket, and it goes on (SIGTERM ends it).
    QTest::newRow("SIGPIPE, its log still read: goes on") << int(SIGPIPE) << false << 0;
}

void TstMqtt::stopSignalsSayStopped()
{
    QFETCH(int, signal);
    QFETCH(bool, logReaderGone);
    QFETCH(int, exitCode);
    QVERIFY(m_broker->start());
    // Its log into a pipe of this test, whose reader it can close.
    int log[2] = {-1, -1};
    QCOMPARE(::pipe2(log, O_CLOEXEC), 0);
    m_publisherLogFd = log[1];
    const bool started = startPublisher(brokerUrl());
    ::close(log[1]);
    QVERIFY(started);
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);

    QSocketNotifier reader(log[0], QSocketNotifier::Read);
    connect(&reader, &QSocketNotifier::activated, this, [&] {
        char buffer[4096];
        if (::read(log[0], buffer, sizeof buffer) <= 0)
            reader.setEnabled(false);
    });
    if (logReaderGone) {
        reader.setEnabled(false);
        ::close(log[0]);
        log[0] = -1;
    }
    if (signal != 0)
        QCOMPARE(::kill(pid_t(m_publisher->processId()), signal), 0);
    // A signal it goes on after: the stop asked for next ends it.
    if (exitCode == 0 && signal == SIGPIPE)
        QCOMPARE(::kill(pid_t(m_publisher->processId()), SIGTERM), 0);
    QVERIFY(m_publisher->waitForFinished(10000));
    QCOMPARE(m_publisher->exitStatus(), QProcess::NormalExit);
    QCOMPARE(m_publisher->exitCode(), exitCode);
    if (log[0] >= 0)
        ::close(log[0]);
    QTRY_VERIFY_WITH_TIMEOUT(!mirror->isLive(station), 5000);
    QCOMPARE(mirror->station(station)->status.reason, QStringLiteral("stopped"));
    const QHash<QString, QByteArray> retained = retainedMessages(m_broker->port(), QStringLiteral("jumo/#"), {}, 3);
    QCOMPARE(json(retained.value("jumo/teststation/status")), QJsonObject({{"state", "offline"}, {"reason", "stopped"}}));
    // It clears nothing else: the last known values stay for whoever looks.
    QVERIFY(retained.contains("jumo/teststation/devices/line1/ipc300@1/values/load_voltage"));
    QVERIFY(retained.contains("jumo/teststation/lines/line1"));
}

void TstMqtt::brokerRestartLosesNothing()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    const DeviceId id = *mirror->findDevice(station, QStringLiteral("line1"), QStringLiteral("ipc300@1"));
    const auto map = families().family(QStringLiteral("ipc300"));
    QVERIFY(m_peer->setWords(1, map->entry(QStringLiteral("load_voltage"))->address,
                             ValueCodec::encodeFloat(231.25f, map->protocol.floatWordOrder)));
    QTRY_COMPARE_WITH_TIMEOUT(mirror->published(id, QStringLiteral("load_voltage"))->text, QStringLiteral("231.3 V"),
                              10000);
    QHash<QString, QString> before;
    for (DeviceId d : mirror->devices()) {
        for (const QString &entry : mirror->entryIds(d))
            before.insert(mirror->deviceName(d) + '/' + entry, mirror->published(d, entry)->text);
    }
    const int retainedBefore = retainedMessages(m_broker->port(), QStringLiteral("jumo/#")).size();

    m_broker->kill();   // SIGKILL, no persistence: every retained message is gone
    QTRY_VERIFY_WITH_TIMEOUT(!mirror->isConnected(), 10000);
    QVERIFY(!mirror->isLive(station));
    QCOMPARE(mirror->entryState(id, QStringLiteral("load_voltage"))->validity, Validity::Stale);

    QVERIFY(m_broker->restart());
    // Both come back by themselves, the publisher publishes everything again.
    QTRY_VERIFY_WITH_TIMEOUT(mirror->isConnected(), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    for (DeviceId d : mirror->devices()) {
        for (const QString &entry : mirror->entryIds(d))
            QCOMPARE(mirror->published(d, entry)->text, before.value(mirror->deviceName(d) + '/' + entry));
    }
    QCOMPARE(mirror->published(id, QStringLiteral("load_voltage"))->text, QStringLiteral("231.3 V"));
    QTRY_COMPARE_WITH_TIMEOUT(retainedMessages(m_broker->port(), QStringLiteral("jumo/#")).size(), retainedBefore, 10000);
    QVERIFY(publisherErrors().contains(QLatin1String("connected to")));
}

void TstMqtt::twoLinesFromAStationFile()
{
    // A second line with the same address as the first one has: devices are told apart
    // by their line.
    TestLine second;
    QVERIFY(second.start());
    SimulatorPeer secondPeer(QStringLiteral("quantrol"));
    QVERIFY(secondPeer.start(second.deviceEnd(), {1}));
    const QString file = writeTwoLineStation(second, {"cabinet-a", {"ipc300@1", "tya200@2"}}, {"cabinet-b", {"quantrol@1"}});
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl(), {QStringLiteral("--station"), file}));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror, 3), 30000);
    QCOMPARE(mirror->lines(station), (QStringList{"cabinet-a", "cabinet-b"}));
    QCOMPARE(mirror->station(station)->status.lines, (QStringList{"cabinet-a", "cabinet-b"}));
    QVERIFY(mirror->findDevice(station, "cabinet-a", "ipc300@1"));
    const auto quantrol = mirror->findDevice(station, "cabinet-b", "quantrol@1");
    QVERIFY(quantrol);
    QCOMPARE(mirror->device(*quantrol)->model, families().family("quantrol")->name);

    // One line dies, the other goes on.
    second.stop();
    QTRY_COMPARE_WITH_TIMEOUT(mirror->line(station, "cabinet-b")->state, LineState::Lost, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(mirror->condition(*quantrol).state, DeviceCondition::State::LineLost, 10000);
    QCOMPARE(mirror->line(station, "cabinet-a")->state, LineState::Connected);
    const auto ipc = mirror->findDevice(station, "cabinet-a", "ipc300@1");
    QVERIFY(mirror->condition(*ipc).isOnline());
    QCOMPARE(mirror->entryState(*ipc, "load_voltage")->validity, Validity::Current);
}

void TstMqtt::removedLineIsCleared()
{
    // The publisher in-process, on a bus of ours, and a mirror of every station.
    QVERIFY(m_broker->start());
    Bus bus;
    BusSettings settings;
    settings.portName = m_line->masterEnd();
    settings.format = testFormat();
    settings.readOnly = true;
    bus.setSettings(settings);
    bus.addDevice(families().family(QStringLiteral("ipc300")), 1);
    QVERIFY(bus.open());
    bus.setPolling(true);
    StationPublisher publisher(*MqttSettings::fromUrl(brokerUrl(), nullptr), QStringLiteral("jumo"),
                               QStringLiteral("inproc"));
    publisher.addLine(QStringLiteral("a"), &bus);
    QString error;
    QVERIFY2(publisher.start(&error), qPrintable(error));
    RemoteStation mirror(families());
    QVERIFY(mirror.start(*MqttSettings::fromUrl(brokerUrl(), nullptr), &error));
    QTRY_VERIFY_WITH_TIMEOUT(mirror.findDevice(QStringLiteral("inproc"), QStringLiteral("a"), QStringLiteral("ipc300@1"))
                                     && mirror.isLive(QStringLiteral("inproc")),
                             20000);
    const DeviceId id = *mirror.findDevice(QStringLiteral("inproc"), QStringLiteral("a"), QStringLiteral("ipc300@1"));
    QTRY_COMPARE_WITH_TIMEOUT(mirror.entryState(id, QStringLiteral("load_voltage"))
                                      ? mirror.entryState(id, QStringLiteral("load_voltage"))->validity
                                      : Validity::Unknown,
                              Validity::Current, 20000);
    QVERIFY(!retainedMessages(m_broker->port(), QStringLiteral("jumo/inproc/devices/#"), {}, 3).isEmpty());

    QSignalSpy removed(&mirror, &RemoteStation::deviceRemoved);
    publisher.removeLine(QStringLiteral("a"));
    QTRY_COMPARE_WITH_TIMEOUT(removed.size(), 1, 10000);
    QCOMPARE(removed.constFirst().constFirst().value<DeviceId>(), id);
    QVERIFY(!mirror.findDevice(QStringLiteral("inproc"), QStringLiteral("a"), QStringLiteral("ipc300@1")));
    QTRY_VERIFY_WITH_TIMEOUT(mirror.lines(QStringLiteral("inproc")).isEmpty(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(mirror.station(QStringLiteral("inproc"))->status.lines.isEmpty(), 10000);
    // Nothing of the line is retained any more: a new viewer does not see a ghost.
    const QHash<QString, QByteArray> retained = retainedMessages(m_broker->port(), QStringLiteral("jumo/#"));
    for (auto it = retained.begin(); it != retained.end(); ++it)
        QVERIFY2(!it.key().contains(QLatin1String("/devices/")) && !it.key().contains(QLatin1String("/lines/")),
                 qPrintable(it.key()));
    QVERIFY(retained.contains(QStringLiteral("jumo/inproc/status")));
}

void TstMqtt::pollSelectionAndAnEarlierRunsLeftovers()
{
    // A first run publishes both devices whole.
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    {
        auto mirror = startMirror();
        QVERIFY(mirror);
        QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    }
    m_publisher->terminate();
    QVERIFY(m_publisher->waitForFinished(10000));

    // The next run has the IPC 300 only, and polls what its faceplate shows and its alarms.
    QFile file(m_broker->file(QStringLiteral("one.json")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QStringLiteral(R"({"format": "jumo-station", "version": 1, "name": "%1",
        "lines": [{"name": "line1", "port": "%2", "baud": 19200, "devices": ["ipc300@1"]}]})")
                       .arg(station, m_line->masterEnd())
                       .toUtf8());
    file.close();
    const QStringList wanted = *PollSelection::expand(*families().family("ipc300"), {"faceplate", "alarms"}, nullptr);
    QVERIFY(wanted.contains("load_voltage") && wanted.contains("malfunction_signal_1"));
    const int requestsBefore = m_peer->line().requestsReceived();
    QVERIFY(startPublisher(brokerUrl(), {"--station", file.fileName(), "--poll", "ipc300:faceplate,alarms"}));

    // What the first run left and this one does not publish is gone from the broker: a
    // new subscriber sees the IPC 300's selection, each value current, and nothing else.
    const QString base = QStringLiteral("jumo/%1/devices/").arg(station);
    QHash<QString, QByteArray> retained;
    QString whyNot;   // what the last look found wrong
    const auto onlyTheSelection = [&] {
        retained = retainedMessages(m_broker->port(), QStringLiteral("jumo/%1/#").arg(station), {}, 3);
        const QJsonObject status = json(retained.value(QStringLiteral("jumo/%1/status").arg(station)));
        if (status.value("state") != "online") {
            whyNot = QStringLiteral("status %1").arg(QString::fromUtf8(QJsonDocument(status).toJson(QJsonDocument::Compact)));
            return false;
        }
        QStringList values;
        QStringList notCurrent;
        for (auto it = retained.cbegin(); it != retained.cend(); ++it) {
            if (it.key().startsWith(base + "line1/tya200@2")) {
                whyNot = QStringLiteral("left over: %1").arg(it.key());
                return false;
            }
            if (it.key().startsWith(base + "line1/ipc300@1/values/")) {
                const QJsonObject value = json(it.value());
                if (value.value("validity") != "current")
                    notCurrent << QStringLiteral("%1 %2/%3").arg(it.key().section('/', -1), value.value("validity").toString(),
                                                             value.value("status").toString());
                values << it.key().section('/', -1);
            }
        }
        values.sort();
        QStringList expected = wanted;
        expected.sort();
        const QString found = values != expected
                ? QStringLiteral("values %1, wanted %2").arg(values.join(','), expected.join(','))
                : QStringLiteral("not current: %1").arg(notCurrent.join(", "));
        // Said as it changes: QTRY's check after its timeout does not show the message.
        if (found != whyNot)
            qInfo("onlyTheSelection: %s", qPrintable(found));
        whyNot = found;
        return values == expected && notCurrent.isEmpty();
    };
    QTRY_VERIFY2_WITH_TIMEOUT(onlyTheSelection(), qPrintable(whyNot), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(publisherErrors().contains("cleared"), 10000);

    // A viewer's mirror has the one device, its selection current, nothing more.
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(mirror->devices().size() == 1 && mirror->isLive(station), 20000);
    const DeviceId id = mirror->devices().constFirst();
    QTRY_COMPARE_WITH_TIMEOUT(mirror->entryIds(id).size(), wanted.size(), 10000);
    for (const QString &entry : wanted)
        QTRY_COMPARE_WITH_TIMEOUT(mirror->entryState(id, entry)->validity, Validity::Current, 10000);
    // The line carries the selection's blocks only: no read reaches the identity texts at
    // 0x0000, which every whole-map cycle reads.
    QVERIFY(m_peer->line().requestsReceived() > requestsBefore);
    int reads = 0;
    int identityReads = 0;
    const auto watch = connect(&m_peer->line(), &SimulatorLine::requestReceived, this, [&](const QByteArray &frame) {
        if (frame.size() == 8 && (frame.at(1) == 3 || frame.at(1) == 4)) {
            ++reads;
            identityReads += frame.at(2) == 0 && frame.at(3) == 0 ? 1 : 0;
        }
    });
    QTRY_VERIFY_WITH_TIMEOUT(reads >= 20, 20000);
    disconnect(watch);
    QCOMPARE(identityReads, 0);
    // A value of the selection still follows the device.
    m_peer->line().device(1)->setNumber("load_voltage", 123.4);
    QTRY_VERIFY_WITH_TIMEOUT(mirror->published(id, "load_voltage")->text.startsWith("123.4"), 20000);
}

void TstMqtt::aHugeLeftoverNeverHoldsUpTheStation()
{
    // 60000 retained values an earlier run (or anyone) left under the station, far more
    // than a broker queues for a client: the publisher's clean-up takes them in and clears
    // them over a connection of its own, while the station's heartbeat and values go on.
    QVERIFY(m_broker->start());
    const MqttSettings broker = *MqttSettings::fromUrl(brokerUrl(), nullptr);
    {
        MqttClient junk;
        junk.setSettings(broker);
        QSignalSpy connected(&junk, &MqttClient::connected);
        QVERIFY(junk.connectToBroker());
        QTRY_COMPARE_WITH_TIMEOUT(connected.size(), 1, 10000);
        const QByteArray payload = R"({"value":1,"text":"1","unit":"","status":"ok","validity":"current",)"
                                   R"("words":[1],"read":"2026-12-01T00:00:00.000Z"})";
        for (int i = 0; i < 60000; ++i) {
            QVERIFY(junk.publish(QStringLiteral("jumo/%1/devices/line1/ipc300@1/values/junk%2").arg(station).arg(i),
                                 payload, true, 0));
            if (i % 1000 == 999)
                QTRY_VERIFY_WITH_TIMEOUT(!junk.hasPendingWrites(), 30000);
        }
        QTRY_VERIFY_WITH_TIMEOUT(!junk.hasPendingWrites(), 30000);
        junk.disconnectFromBroker();
    }
    QCOMPARE(retainedMessages(m_broker->port(), QStringLiteral("jumo/%1/devices/line1/ipc300@1/values/junk1").arg(station),
                              {}, 3)
                     .size(),
             1);

    // Heartbeats from the start, while the clean-up runs.
    MqttClient listener;
    listener.setSettings(broker);
    int heartbeats = 0;
    connect(&listener, &MqttClient::messageReceived, this, [&](const QString &topic) {
        heartbeats += topic.endsWith(QLatin1String("/heartbeat")) ? 1 : 0;
    });
    listener.subscribe(QStringLiteral("jumo/%1/heartbeat").arg(station), 0);
    QVERIFY(listener.connectToBroker());
    QTRY_VERIFY_WITH_TIMEOUT(listener.isConnected(), 10000);
    QVERIFY(startPublisher(brokerUrl()));
    QTRY_VERIFY_WITH_TIMEOUT(heartbeats >= 3, 30000);

    // In the end nothing of it is left, and a viewer has exactly the station's entries.
    QTRY_VERIFY_WITH_TIMEOUT(publisherErrors().contains(QLatin1String("cleared")), 120000);
    QVERIFY2(!publisherErrors().contains(QLatin1String("still there")), qPrintable(publisherErrors()));
    QVERIFY(retainedMessages(m_broker->port(), QStringLiteral("jumo/%1/devices/+/+/values/+").arg(station), {}, 5)
                    .size()
            == publishedEntries("ipc300") + publishedEntries("tya200"));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 60000);
    QVERIFY(m_publisher->state() == QProcess::Running);
}

void TstMqtt::aTakeOverStopsTheFirstPublisher()
{
    // Two in-process publishers of one name (the second as with --take-over, which skips
    // the name check): the first hears the second's "online" on its watch and stops,
    // without a "stopped" over the second's status and without its will.
    QVERIFY(m_broker->start());
    const MqttSettings broker = *MqttSettings::fromUrl(brokerUrl(), nullptr);
    StationPublisher first(broker, QStringLiteral("jumo"), QStringLiteral("twin"));
    first.setHeartbeatInterval(100);
    QSignalSpy firstTakenOver(&first, &StationPublisher::takenOver);
    QString error;
    QVERIFY2(first.start(&error), qPrintable(error));
    auto listener = connectClient();
    QVERIFY(listener);
    int heartbeats = 0;
    connect(listener.get(), &MqttClient::messageReceived, this, [&](const QString &topic) {
        heartbeats += topic == QLatin1String("jumo/twin/heartbeat") ? 1 : 0;
    });
    listener->subscribe(QStringLiteral("jumo/twin/#"), 0);
    QTRY_VERIFY_WITH_TIMEOUT(heartbeats >= 5, 20000);
    QCOMPARE(firstTakenOver.size(), 0);

    StationPublisher second(broker, QStringLiteral("jumo"), QStringLiteral("twin"));
    second.setHeartbeatInterval(100);
    QSignalSpy secondTakenOver(&second, &StationPublisher::takenOver);
    QVERIFY2(second.start(&error), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(firstTakenOver.size(), 1, 20000);
    QVERIFY(!first.client().isConnected());
    // The station stays online, the second's.
    heartbeats = 0;
    QTRY_VERIFY_WITH_TIMEOUT(heartbeats >= 5, 20000);
    const QJsonObject status = json(retainedMessages(m_broker->port(), QStringLiteral("jumo/twin/status"), {}, 3)
                                            .value(QStringLiteral("jumo/twin/status")));
    QCOMPARE(status.value("state").toString(), QStringLiteral("online"));
    QCOMPARE(secondTakenOver.size(), 0);
}

void TstMqtt::secondPublisherOfOneNameRefuses()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    const QSet<QString> publishersBefore = publishingClients();
    QVERIFY(!publishersBefore.isEmpty());

    // A second one of the same name: refused before it opens a line or publishes anything.
    QProcess second;
    second.start(QStringLiteral(JUMO_PUBLISHER_PATH),
                 {QStringLiteral("--broker"), brokerUrl(), QStringLiteral("--name"), station, QStringLiteral("--port"),
                  m_broker->file(QStringLiteral("no-such-port")), QStringLiteral("--device"), QStringLiteral("ipc300@1")});
    QVERIFY(second.waitForFinished(30000));
    const QString said = QString::fromUtf8(second.readAllStandardError());
    QCOMPARE(second.exitCode(), 2);
    QVERIFY2(said.contains(QLatin1String("a station named teststation is online")), qPrintable(said));
    QVERIFY2(!said.contains(QLatin1String("no-such-port")), qPrintable(said));   // no line was opened
    QCOMPARE(publishingClients(), publishersBefore);
    QVERIFY(m_publisher->state() == QProcess::Running);
    QVERIFY(mirror->isLive(station));

    // With --take-over it starts, and the first one stops, saying so, with exit code 2
    // (so a service manager does not start it again against the new one).
    QProcess takeOver;
    takeOver.start(QStringLiteral(JUMO_PUBLISHER_PATH),
                   {QStringLiteral("--broker"), brokerUrl(), QStringLiteral("--name"), station, QStringLiteral("--port"),
                    m_line->masterEnd(), QStringLiteral("--baud"), QStringLiteral("19200"), QStringLiteral("--device"),
                    QStringLiteral("ipc300@1"), QStringLiteral("--device"), QStringLiteral("tya200@2"),
                    QStringLiteral("--take-over")});
    QVERIFY(takeOver.waitForStarted(10000));
    QVERIFY(m_publisher->waitForFinished(30000));
    QCOMPARE(m_publisher->exitCode(), 2);
    QVERIFY2(publisherErrors().contains(QLatin1String("took over station teststation")), qPrintable(publisherErrors()));
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    QCOMPARE(mirror->station(station)->status.reason, QString());
    takeOver.terminate();
    QVERIFY(takeOver.waitForFinished(10000));
    QCOMPARE(takeOver.exitCode(), 0);
}

void TstMqtt::stalledBrokerIsNoRival()
{
    // A broker stopped (SIGSTOP) long enough for the keepalive to give up: the publisher
    // connects again, and its own heartbeats that the broker passes on late are no
    // other publisher's. The loss says why in words.
    QVERIFY(m_broker->start());
    MqttSettings broker = *MqttSettings::fromUrl(brokerUrl(), nullptr);
    broker.keepAliveS = 5;   // the least libmosquitto takes
    StationPublisher publisher(broker, QStringLiteral("jumo"), QStringLiteral("stalled"));
    publisher.setHeartbeatInterval(50);
    publisher.client().setReconnectDelays(100, 200);
    QSignalSpy heard(&publisher, &StationPublisher::rivalHeard);
    QSignalSpy lost(&publisher.client(), &MqttClient::disconnected);
    QSignalSpy connected(&publisher.client(), &MqttClient::connected);
    QString error;
    QVERIFY2(publisher.start(&error), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(connected.size(), 1, 20000);
    QVERIFY(::kill(pid_t(m_broker->pid()), SIGSTOP) == 0);
    QTRY_VERIFY_WITH_TIMEOUT(!lost.isEmpty(), 20000);
    QVERIFY2(lost.constFirst().constFirst().toString().contains(QLatin1String("keepalive")),
             qPrintable(lost.constFirst().constFirst().toString()));
    // Stopped for longer than the last 16 heartbeats took.
    QTest::qWait(2000);
    QVERIFY(::kill(pid_t(m_broker->pid()), SIGCONT) == 0);
    QTRY_VERIFY_WITH_TIMEOUT(connected.size() >= 2, 30000);
    int heartbeats = 0;
    connect(&publisher.client(), &MqttClient::messageReceived, this, [&](const QString &topic) {
        if (topic == QLatin1String("jumo/stalled/heartbeat"))
            ++heartbeats;
    });
    QTRY_VERIFY_WITH_TIMEOUT(heartbeats >= 20, 20000);
    QCOMPARE(heard.size(), 0);
}

void TstMqtt::garbageMakesNoDeviceAndNoHeartbeat()
{
    // Someone else publishes under the station's topics: malformed payloads and device
    // levels that name no device. The mirror takes none of it as a device or as a sign of
    // life of the station.
    QVERIFY(m_broker->start());
    std::unique_ptr<RemoteStation> mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(mirror->isConnected(), 20000);
    MqttClient vandal;
    vandal.setSettings(*MqttSettings::fromUrl(brokerUrl(), nullptr));
    QVERIFY(vandal.connectToBroker());
    QTRY_VERIFY_WITH_TIMEOUT(vandal.isConnected(), 20000);
    const QString prefix = QStringLiteral("jumo/%1/").arg(station);
    const QByteArray status = TopicScheme::statusOnline(QStringLiteral("x"), QDateTime::currentDateTimeUtc(), {});
    QVERIFY(vandal.publish(prefix + QStringLiteral("status"), status, false));
    QVERIFY(vandal.publish(prefix + QStringLiteral("devices/line1/ipc300@1/values/load_voltage"), "garbage", false));
    QVERIFY(vandal.publish(prefix + QStringLiteral("devices/line1/ipc300@1/condition"), "{\"state\":1}", false));
    QVERIFY(vandal.publish(prefix + QStringLiteral("devices/line1/evil/info"),
                           R"({"line":"line1","family":"evil","address":1,"model":"x"})", false));
    QVERIFY(vandal.publish(prefix + QStringLiteral("heartbeat"), "garbage", false));
    // Then one good device: the messages of one client arrive in order.
    QVERIFY(vandal.publish(prefix + QStringLiteral("devices/line1/tya200@2/info"),
                           R"({"line":"line1","family":"tya200","address":2,"model":"x"})", false));
    QTRY_VERIFY_WITH_TIMEOUT(mirror->findDevice(station, QStringLiteral("line1"), QStringLiteral("tya200@2")), 20000);
    QCOMPARE(mirror->devices().size(), 1);
    QVERIFY(!mirror->station(station)->lastHeartbeat.isValid());
    // Online, but no heartbeat came: silent once the limit is over, and garbage on the
    // heartbeat topic does not wake it.
    QTRY_VERIFY_WITH_TIMEOUT(mirror->station(station)->silent, 20000);
    QVERIFY(vandal.publish(prefix + QStringLiteral("heartbeat"), "{\"time\":\"yesterday\"}", false));
    QVERIFY(vandal.publish(prefix + QStringLiteral("devices/line1/tya200@3/info"),
                           R"({"line":"line1","family":"tya200","address":3,"model":"x"})", false));
    QTRY_VERIFY_WITH_TIMEOUT(mirror->findDevice(station, QStringLiteral("line1"), QStringLiteral("tya200@3")), 20000);
    QVERIFY(mirror->station(station)->silent);
    QVERIFY(!mirror->isLive(station));
}

void TstMqtt::passwordIsChecked()
{
    QProcess passwd;
    const QString passwordFile = m_broker->file(QStringLiteral("passwords"));
    passwd.start(findTool(QStringLiteral("mosquitto_passwd")),
                 {QStringLiteral("-c"), QStringLiteral("-b"), passwordFile, QStringLiteral("station"),
                  QStringLiteral("right-secret")});
    QVERIFY(passwd.waitForFinished(10000));
    QCOMPARE(passwd.exitCode(), 0);
    QVERIFY(m_broker->start(QStringLiteral("allow_anonymous false\npassword_file %1\n").arg(passwordFile)));
    const QString url = QStringLiteral("mqtt://station@127.0.0.1:%1").arg(m_broker->port());

    // Wrong: refused, said clearly, and the password appears nowhere.
    QProcessEnvironment wrong = QProcessEnvironment::systemEnvironment();
    wrong.insert(QStringLiteral("JUMO_MQTT_PASSWORD"), QStringLiteral("wrong-secret"));
    QVERIFY(startPublisher(url, {}, wrong));
    QTRY_VERIFY_WITH_TIMEOUT(publisherErrors().contains(QLatin1String("refused the connection")), 10000);
    QVERIFY2(publisherErrors().contains(QLatin1String("not authorised"), Qt::CaseInsensitive), qPrintable(publisherErrors()));
    QVERIFY(!publisherErrors().contains(QLatin1String("wrong-secret")));
    QVERIFY(retainedMessages(m_broker->port(), QStringLiteral("jumo/#"), {"-u", "station", "-P", "right-secret"}, 2)
                    .isEmpty());
    m_publisher->kill();
    m_publisher->waitForFinished(10000);
    m_publisherErr.clear();

    // Right, from a file.
    QFile file(m_broker->file(QStringLiteral("publisher-password")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("right-secret\n");
    file.close();
    QProcessEnvironment none = QProcessEnvironment::systemEnvironment();
    none.remove(QStringLiteral("JUMO_MQTT_PASSWORD"));
    QVERIFY(startPublisher(url, {QStringLiteral("--password-file"), file.fileName()}, none));
    MqttSettings settings = *MqttSettings::fromUrl(url, nullptr);
    settings.password = QStringLiteral("right-secret");
    auto mirror = startMirror(settings);
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    QVERIFY(!publisherErrors().contains(QLatin1String("refused")));
    // An anonymous viewer gets nothing.
    QVERIFY(retainedMessages(m_broker->port(), QStringLiteral("jumo/#"), {}, 2).isEmpty());
}

void TstMqtt::tls()
{
    // A throwaway CA and a server certificate for 127.0.0.1 and localhost.
    const QString dir = m_broker->dir();
    auto openssl = [&](const QStringList &args) {
        QProcess p;
        p.setWorkingDirectory(dir);
        p.start(findTool(QStringLiteral("openssl")), args);
        return p.waitForFinished(60000) && p.exitCode() == 0;
    };
    QFile ext(m_broker->file(QStringLiteral("server.ext")));
    QVERIFY(ext.open(QIODevice::WriteOnly));
    ext.write("subjectAltName=IP:127.0.0.1,DNS:localhost\n");
    ext.close();
    QVERIFY(openssl({"req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout", "ca.key", "-out", "ca.crt", "-days",
                     "1", "-subj", "/CN=jumo test CA"}));
    QVERIFY(openssl({"req", "-newkey", "rsa:2048", "-nodes", "-keyout", "server.key", "-out", "server.csr", "-subj",
                     "/CN=127.0.0.1"}));
    QVERIFY(openssl({"x509", "-req", "-in", "server.csr", "-CA", "ca.crt", "-CAkey", "ca.key", "-CAcreateserial",
                     "-out", "server.crt", "-days", "1", "-extfile", "server.ext"}));
    QVERIFY(m_broker->start(QStringLiteral("allow_anonymous true\ncafile %1\ncertfile %2\nkeyfile %3\n")
                                    .arg(m_broker->file("ca.crt"), m_broker->file("server.crt"),
                                         m_broker->file("server.key"))));
    const QString url = QStringLiteral("mqtts://127.0.0.1:%1").arg(m_broker->port());

    // Without our CA the broker's certificate is not trusted.
    QVERIFY(startPublisher(url));
    auto untrusting = startMirror(*MqttSettings::fromUrl(url, nullptr));
    QVERIFY(untrusting);
    QSignalSpy failed(&untrusting->client(), &MqttClient::disconnected);
    QVERIFY(failed.wait(10000));
    QVERIFY2(failed.constFirst().constFirst().toString().contains(QLatin1String("TLS")),
             qPrintable(failed.constFirst().constFirst().toString()));
    QVERIFY(!untrusting->isConnected());
    QTRY_VERIFY_WITH_TIMEOUT(publisherErrors().contains(QLatin1String("TLS")), 10000);
    m_publisher->kill();
    m_publisher->waitForFinished(10000);
    untrusting.reset();

    QVERIFY(startPublisher(url, {QStringLiteral("--tls-ca"), m_broker->file("ca.crt")}));
    MqttSettings settings = *MqttSettings::fromUrl(url, nullptr);
    QCOMPARE(settings.port, m_broker->port());
    settings.caFile = m_broker->file("ca.crt");
    auto mirror = startMirror(settings);
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
}

namespace {

QByteArray infoPayload(const QString &line, const QString &family, int address)
{
    return QJsonDocument(QJsonObject{{"line", line}, {"family", family}, {"address", address}, {"model", "x"}})
            .toJson(QJsonDocument::Compact);
}

QByteArray currentValue(const QString &text)
{
    return QJsonDocument(QJsonObject{{"value", 1.0}, {"text", text}, {"unit", "V"}, {"status", "ok"},
                                     {"validity", "current"}, {"words", QJsonArray{0, 16256}},
                                     {"read", TopicScheme::timeText(QDateTime::currentDateTimeUtc())}})
            .toJson(QJsonDocument::Compact);
}

} // namespace

void TstMqtt::devicesComeFromTheirInfoAlone()
{
    // A device exists while its info topic does: values alone, an address out of the
    // family's range and info that names another device make none.
    QVERIFY(m_broker->start());
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(mirror->isConnected(), 20000);
    auto vandal = connectClient();
    QVERIFY(vandal);
    const QString base = QStringLiteral("jumo/%1/devices/").arg(station);
    QVERIFY(vandal->publish(base + "line1/ipc300@5/values/load_voltage", currentValue("1 V"), true));
    QVERIFY(vandal->publish(base + "line1/ipc300@999/info", infoPayload("line1", "ipc300", 999), true));
    QVERIFY(vandal->publish(base + "line1/ipc300@999/values/load_voltage", currentValue("1 V"), true));
    QVERIFY(vandal->publish(base + "line1/ipc300@7/info", infoPayload("line1", "ipc300", 8), true));
    QVERIFY(vandal->publish(base + "line1/s7@1/info", infoPayload("line1", "s7", 1), true));
    for (int i = 1; i <= 200; ++i)
        QVERIFY(vandal->publish(base + QStringLiteral("ghost/ipc300@%1/values/load_voltage").arg(i), currentValue("1 V"), true));
    // Then a device announced as a station does it: the messages of one client arrive in order.
    QVERIFY(vandal->publish(base + "line1/tya200@2/info", infoPayload("line1", "tya200", 2), true));
    QTRY_VERIFY_WITH_TIMEOUT(mirror->findDevice(station, "line1", "tya200@2"), 20000);
    QCOMPARE(mirror->devices().size(), 1);
    QVERIFY(!mirror->findDevice(station, "line1", "ipc300@231"));
    QVERIFY(!mirror->findDevice(station, "line1", "ipc300@999"));
    QVERIFY(mirror->refusedCount() >= 3);

    // A viewer started now takes the same from the retained messages alone, in whatever
    // order the broker sends them: a value retained before its device's info still counts.
    QVERIFY(vandal->publish(base + "line1/ipc300@1/values/load_voltage", currentValue("7 V"), true));
    QVERIFY(vandal->publish(base + "line1/ipc300@1/info", infoPayload("line1", "ipc300", 1), true));
    auto late = startMirror();
    QVERIFY(late);
    QTRY_VERIFY_WITH_TIMEOUT(late->isConnected(), 20000);
    QVERIFY(vandal->publish(base + "line1/tya200@3/info", infoPayload("line1", "tya200", 3), false));
    QTRY_VERIFY_WITH_TIMEOUT(late->findDevice(station, "line1", "tya200@3"), 20000);
    QCOMPARE(late->devices().size(), 3);
    const auto ipc = late->findDevice(station, "line1", "ipc300@1");
    QVERIFY(ipc);
    QVERIFY(late->published(*ipc, "load_voltage"));
    QCOMPARE(late->published(*ipc, "load_voltage")->text, QStringLiteral("7 V"));

    // The ghosts cleared from the broker leave nothing behind either.
    for (int i = 1; i <= 200; ++i)
        QVERIFY(vandal->publish(base + QStringLiteral("ghost/ipc300@%1/values/load_voltage").arg(i), {}, true));
    QVERIFY(vandal->publish(base + "line1/tya200@2/info", {}, true));
    QTRY_VERIFY_WITH_TIMEOUT(!late->findDevice(station, "line1", "tya200@2"), 20000);
    QCOMPARE(late->devices().size(), 2);
}

void TstMqtt::aDeviceThatLeavesTheStationLeavesTheViewer()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    RemoteLines lines(mirror.get());
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    QCOMPARE(lines.lines().constFirst()->devices().size(), 2);

    // The station restarted with one device fewer: its clean-up clears the other's topics.
    m_publisher->terminate();
    QVERIFY(m_publisher->waitForFinished(10000));
    m_publisher = std::make_unique<QProcess>();
    connect(m_publisher.get(), &QProcess::readyReadStandardError, this,
            [this] { m_publisherErr += m_publisher->readAllStandardError(); });
    m_publisher->start(QStringLiteral(JUMO_PUBLISHER_PATH),
                       {"--broker", brokerUrl(), "--name", station, "--port", m_line->masterEnd(), "--baud", "19200",
                        "--device", "ipc300@1"});
    QVERIFY(m_publisher->waitForStarted(10000));
    QTRY_VERIFY_WITH_TIMEOUT(!mirror->findDevice(station, "line1", "tya200@2"), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror, 1), 30000);
    QCOMPARE(lines.lines().constFirst()->devices().size(), 1);

    // Anyone clearing a device's info takes it out of every viewer; the station, watching
    // its topics, publishes it again, and it is back.
    auto vandal = connectClient();
    QVERIFY(vandal);
    QSignalSpy removed(mirror.get(), &RemoteStation::deviceRemoved);
    QSignalSpy added(mirror.get(), &RemoteStation::deviceAdded);
    QVERIFY(vandal->publish(QStringLiteral("jumo/%1/devices/line1/ipc300@1/info").arg(station), {}, true));
    QTRY_COMPARE_WITH_TIMEOUT(removed.size(), 1, 20000);
    QTRY_COMPARE_WITH_TIMEOUT(added.size(), 1, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(mirror->findDevice(station, "line1", "ipc300@1"), 20000);
}

void TstMqtt::viewersShowTheStationsOrder()
{
    // The station's order is its station file's: not by address, not by arrival.
    TestLine second;
    QVERIFY(second.start());
    SimulatorPeer secondPeer(QStringLiteral("quantrol"));
    QVERIFY(secondPeer.start(second.deviceEnd(), {1}));
    const QString file = writeTwoLineStation(second, {"zeta", {"tya200@2", "ipc300@1"}}, {"alpha", {"quantrol@1"}});
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl(), {QStringLiteral("--station"), file}));
    const QStringList expected{"zeta/tya200@2", "zeta/ipc300@1", "alpha/quantrol@1"};
    for (int viewer = 0; viewer < 2; ++viewer) {
        auto mirror = startMirror();
        QVERIFY(mirror);
        RemoteLines lines(mirror.get());
        QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror, 3), 30000);
        QCOMPARE(mirror->station(station)->order, expected);
        QStringList shown;
        for (MirroredLine *line : lines.orderedLines()) {
            for (DeviceId id : lines.orderedDevices(line))
                shown << line->name() + '/' + line->deviceName(id);
        }
        QCOMPARE(shown, expected);
    }
    QVERIFY(json(retainedMessages(m_broker->port(), QStringLiteral("jumo/%1/order").arg(station), {}, 3)
                         .value(QStringLiteral("jumo/%1/order").arg(station)))
                    .value("devices")
                    .toVariant()
                    .toStringList()
            == expected);
}

void TstMqtt::aForgedValueIsUndoneByTheStation()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    const DeviceId id = *mirror->findDevice(station, "line1", "ipc300@1");
    // An entry that never changes: the station would never publish it again by itself.
    const QString entry = QStringLiteral("device_name");
    QVERIFY(mirror->published(id, entry));
    const QString truth = mirror->published(id, entry)->text;
    const QString topic = QStringLiteral("jumo/%1/devices/line1/ipc300@1/values/%2").arg(station, entry);
    auto rogue = connectClient();
    QVERIFY(rogue);
    int forgedSeen = 0;
    connect(mirror.get(), &RemoteStation::entriesUpdated, this, [&](DeviceId device, const QStringList &ids) {
        if (device == id && ids.contains(entry) && mirror->published(id, entry)->text == QLatin1String("FORGED"))
            ++forgedSeen;
    });
    QElapsedTimer roundTrip;
    roundTrip.start();
    const QByteArray forged = QJsonDocument(QJsonObject{{"value", "FORGED"}, {"text", "FORGED"}, {"unit", ""},
                                                        {"status", "ok"}, {"validity", "current"},
                                                        {"words", QJsonArray{}}, {"read", QJsonValue()}})
                                      .toJson(QJsonDocument::Compact);
    QVERIFY(rogue->publish(topic, forged, true));
    QTRY_VERIFY_WITH_TIMEOUT(forgedSeen > 0, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(mirror->published(id, entry)->text, truth, 10000);
    qInfo("a forged retained value was undone by the station after %lld ms (as this viewer saw it)",
          qint64(roundTrip.elapsed()));
    // On the broker too, and the station says so in its status.
    const QHash<QString, QByteArray> onBroker = retainedMessages(m_broker->port(), topic, {}, 3);
    QVERIFY2(json(onBroker.value(topic)).value("text").toString() == truth, onBroker.value(topic).constData());
    QTRY_VERIFY_WITH_TIMEOUT(mirror->station(station)->status.restored >= 1, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(publisherErrors().contains(QLatin1String("another client wrote on")), 10000);

    // Junk under one of its devices is cleared.
    const QString junk = QStringLiteral("jumo/%1/devices/line1/ipc300@1/values/no_such_entry").arg(station);
    QVERIFY(rogue->publish(junk, currentValue("1 V"), true));
    QTRY_VERIFY_WITH_TIMEOUT(mirror->station(station)->status.cleared >= 1, 10000);
    QVERIFY(retainedMessages(m_broker->port(), junk, {}, 2).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(mirror->station(station)->status.cleared >= 1, 10000);

    // A value whose validity and status disagree is none: the viewer never takes it.
    const quint64 refusedBefore = mirror->refusedCount();
    int disagreeingTaken = 0;
    connect(mirror.get(), &RemoteStation::entriesUpdated, this, [&](DeviceId device, const QStringList &ids) {
        if (device == id && ids.contains("load_voltage") && mirror->published(id, "load_voltage")->text == "666 V")
            ++disagreeingTaken;
    });
    QJsonObject disagreeing = json(currentValue("666 V"));
    disagreeing.insert("status", "timeout");
    QVERIFY(rogue->publish(QStringLiteral("jumo/%1/devices/line1/ipc300@1/values/load_voltage").arg(station),
                           QJsonDocument(disagreeing).toJson(QJsonDocument::Compact), false));
    QTRY_VERIFY_WITH_TIMEOUT(mirror->refusedCount() > refusedBefore, 10000);
    QCOMPARE(disagreeingTaken, 0);
}

void TstMqtt::viewerFindsOutThatItMayPublish()
{
    // Anonymous access: the viewer's probe comes back, so station data can be forged.
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QSignalSpy forgery(mirror.get(), &RemoteStation::forgeryPossible);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(mirror->anyWritable(), 20000);
    QCOMPARE(forgery.size(), 1);
    QCOMPARE(forgery.constFirst().constFirst().toString(), station);
    // The probe is not retained and leaves nothing; the station was not disturbed by it.
    const QHash<QString, QByteArray> retained = retainedMessages(m_broker->port(), QStringLiteral("jumo/#"), {}, 3);
    for (auto it = retained.cbegin(); it != retained.cend(); ++it)
        QVERIFY2(!it.key().contains(QLatin1String("/probe/")), qPrintable(it.key()));
    QCOMPARE(mirror->station(station)->status.restored, 0);
    QCOMPARE(mirror->station(station)->status.cleared, 0);
    QVERIFY(everythingCurrent(*mirror));
}

void TstMqtt::theShippedAclKeepsRoguesOut()
{
    // resources/mosquitto as shipped: its configuration, its ACL, and users made the way the
    // README's quick start makes them.
    const QString shipped = QStringLiteral(JUMO_MOSQUITTO_DIR);
    QVERIFY(QFile::copy(shipped + "/jumo.acl", m_broker->file("jumo.acl")));
    QFile users(m_broker->file("jumo.passwd"));
    QVERIFY(users.open(QIODevice::WriteOnly));
    users.write("publisher:station-secret\noperator:operator-secret\nviewer:viewer-secret\n");
    users.close();
    QProcess passwd;
    passwd.start(findTool(QStringLiteral("mosquitto_passwd")), {QStringLiteral("-U"), users.fileName()});
    QVERIFY(passwd.waitForFinished(10000));
    QCOMPARE(passwd.exitCode(), 0);
    QFile config(shipped + "/jumo-local.conf");
    QVERIFY(config.open(QIODevice::ReadOnly));
    QVERIFY(m_broker->startConfig(QString::fromUtf8(config.readAll())));

    const QString url = QStringLiteral("mqtt://publisher@127.0.0.1:%1").arg(m_broker->port());
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("JUMO_MQTT_PASSWORD"), QStringLiteral("station-secret"));
    QVERIFY(startPublisher(url, {}, environment));
    MqttSettings viewer = *MqttSettings::fromUrl(QStringLiteral("mqtt://viewer@127.0.0.1:%1").arg(m_broker->port()), nullptr);
    viewer.password = QStringLiteral("viewer-secret");
    auto mirror = startMirror(viewer);
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    const DeviceId id = *mirror->findDevice(station, "line1", "ipc300@1");
    int forgedSeen = 0;
    connect(mirror.get(), &RemoteStation::entriesUpdated, this, [&](DeviceId device, const QStringList &ids) {
        for (const QString &entry : ids)
            forgedSeen += device == id && mirror->published(id, entry) && mirror->published(id, entry)->text == "FORGED";
    });
    // The viewer's presence is let through; its probe is not, and it knows no more.
    QTRY_VERIFY_WITH_TIMEOUT(m_broker->log().contains(QLatin1String("/probe/")), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(m_broker->log().contains(QLatin1String("Denied PUBLISH")), 20000);
    QVERIFY(!mirror->anyWritable());
    const QStringList reader{"-u", "viewer", "-P", "viewer-secret"};
    QVERIFY(retainedMessages(m_broker->port(), QStringLiteral("jumo/%1/viewers/#").arg(station), reader, 3)
                    .contains(QStringLiteral("jumo/%1/viewers/%2").arg(station, mirror->viewerId())));

    // Anonymous: not let in at all.
    MqttClient anonymous;
    anonymous.setSettings(*MqttSettings::fromUrl(brokerUrl(), nullptr));
    QSignalSpy refused(&anonymous, &MqttClient::refused);
    QVERIFY(anonymous.connectToBroker());
    QVERIFY(refused.wait(20000));
    QVERIFY(!anonymous.isConnected());
    anonymous.disconnectFromBroker();

    // A viewer's or an operator's account: in, but nothing it publishes under a station
    // reaches anyone.
    const QString topic = QStringLiteral("jumo/%1/devices/line1/ipc300@1/values/device_name").arg(station);
    for (const auto &[user, password] : {std::pair{"viewer", "viewer-secret"}, {"operator", "operator-secret"}}) {
        MqttSettings settings = *MqttSettings::fromUrl(QStringLiteral("mqtt://%1@127.0.0.1:%2").arg(user).arg(m_broker->port()), nullptr);
        settings.password = QString::fromLatin1(password);
        auto rogue = connectClient(settings);
        QVERIFY2(rogue, user);
        const qsizetype deniedBefore = m_broker->log().count(QLatin1String("Denied PUBLISH"));
        QVERIFY(rogue->publish(topic, currentValue("FORGED"), true));
        QVERIFY(rogue->publish(QStringLiteral("jumo/%1/heartbeat").arg(station),
                               TopicScheme::heartbeatPayload(QDateTime::currentDateTimeUtc()), false));
        QVERIFY(rogue->publish(QStringLiteral("jumo/%1/status").arg(station), TopicScheme::statusOffline("x"), true));
        QTRY_VERIFY_WITH_TIMEOUT(m_broker->log().count(QLatin1String("Denied PUBLISH")) >= deniedBefore + 3, 20000);
        const QByteArray retained = retainedMessages(m_broker->port(), topic, reader, 3).value(topic);
        QVERIFY2(!retained.isEmpty() && !retained.contains("FORGED"), retained.constData());
        QTRY_VERIFY_WITH_TIMEOUT(mirror->isLive(station), 10000);
    }
    QCOMPARE(forgedSeen, 0);
    QCOMPARE(mirror->station(station)->status.restored, 0);
}

void TstMqtt::floodsDoNotHoldUpTheStatus()
{
    // Junk retained under 10000 other station names (50000 topics), 20000 junk values, ten
    // of 1 MB and one of 50 MB under the station's own tree: a viewer of every station
    // started after it still gets the station's status on its own connection, and takes
    // no more than its limits.
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    {
        auto mirror = startMirror();
        QVERIFY(mirror);
        QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    }
    auto junk = connectClient();
    QVERIFY(junk);
    const QByteArray value = currentValue("1 V");
    int sent = 0;
    auto flush = [&] {
        if (++sent % 1000 == 0)
            QTRY_VERIFY_WITH_TIMEOUT(!junk->hasPendingWrites(), 60000);
    };
    for (int i = 0; i < 10000; ++i) {
        const QString fake = QStringLiteral("jumo/fake%1/").arg(i);
        QVERIFY(junk->publish(fake + "status", TopicScheme::statusOnline("x", QDateTime::currentDateTimeUtc(), {"l"}), true, 0));
        flush();
        for (int t = 0; t < 4; ++t) {
            QVERIFY(junk->publish(fake + QStringLiteral("devices/l/ipc300@%1/values/load_voltage").arg(t + 1), value, true, 0));
            flush();
        }
    }
    const QString base = QStringLiteral("jumo/%1/devices/line1/ipc300@1/values/").arg(station);
    for (int i = 0; i < 20000; ++i) {
        QVERIFY(junk->publish(base + QStringLiteral("junk%1").arg(i), value, true, 0));
        flush();
    }
    const QByteArray big(1024 * 1024, 'x');
    for (int i = 0; i < 10; ++i)
        QVERIFY(junk->publish(base + QStringLiteral("big%1").arg(i), big, true, 0));
    QVERIFY(junk->publish(base + QStringLiteral("huge"), QByteArray(50 * 1024 * 1024, 'y'), true, 0));
    QTRY_VERIFY_WITH_TIMEOUT(!junk->hasPendingWrites(), 120000);
    // The broker has it all once a message sent after it comes back.
    junk->subscribe(QStringLiteral("flood/marker"), 0);
    QSignalSpy marker(junk.get(), &MqttClient::messageReceived);
    QVERIFY(junk->publish(QStringLiteral("flood/marker"), "1", false, 0));
    QVERIFY(marker.wait(120000));

    RemoteStation::monotonicMs();
    RemoteStation viewer(families());
    QString error;
    QVERIFY(viewer.start(*MqttSettings::fromUrl(brokerUrl(), nullptr), &error));
    QElapsedTimer waited;
    waited.start();
    // The event loop keeps turning: a timer's ticks are never far apart.
    QElapsedTimer sinceTick;
    sinceTick.start();
    qint64 longestGap = 0;
    QTimer tick;
    connect(&tick, &QTimer::timeout, this, [&] {
        longestGap = std::max(longestGap, sinceTick.restart());
    });
    tick.start(50);
    QTRY_VERIFY_WITH_TIMEOUT(viewer.station(station) && viewer.station(station)->statusKnown
                                     && viewer.station(station)->status.online,
                             120000);
    qInfo("the station's status reached a new viewer of every station after %lld ms", qint64(waited.elapsed()));
    QTRY_VERIFY_WITH_TIMEOUT(viewer.isLive(station), 300000);
    qInfo("the station was live in it after %lld ms; the longest stall of its event loop: %lld ms; %llu messages "
          "not taken, %llu over the size limit",
          qint64(waited.elapsed()), longestGap, viewer.refusedCount(), viewer.client().oversizeDropped());
    QVERIFY(viewer.stations().size() <= RemoteStation::maxStations);
    QVERIFY(viewer.stations().contains(station));
    QCOMPARE(viewer.client().oversizeDropped(), quint64(11));
    QVERIFY(everythingCurrent(viewer));
    QVERIFY(viewer.entryIds(*viewer.findDevice(station, "line1", "ipc300@1")).size() == publishedEntries("ipc300"));
}

void TstMqtt::lineLossPublishesEachConditionOnce()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    auto listener = connectClient();
    QVERIFY(listener);
    QHash<QString, QStringList> states;   // device -> condition states published
    connect(listener.get(), &MqttClient::messageReceived, this,
            [&](const QString &topic, const QByteArray &payload, bool retained) {
                if (!retained && topic.endsWith(QLatin1String("/condition")))
                    states[topic.section('/', -2, -2)] << json(payload).value("state").toString();
            });
    listener->subscribe(QStringLiteral("jumo/%1/devices/+/+/condition").arg(station), 0);
    QTRY_VERIFY_WITH_TIMEOUT(listener->isConnected(), 10000);
    m_line->stop();
    for (DeviceId id : mirror->devices())
        QTRY_COMPARE_WITH_TIMEOUT(mirror->condition(id).state, DeviceCondition::State::LineLost, 10000);
    m_peer->stop();
    QVERIFY(m_line->restart());
    QVERIFY(m_peer->reopen());
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    for (const QString &device : {QStringLiteral("ipc300@1"), QStringLiteral("tya200@2")}) {
        QVERIFY2(states.value(device).count(QStringLiteral("line_lost")) == 1,
                 qPrintable(device + ": " + states.value(device).join(' ')));
    }
}

void TstMqtt::ageIsOfTheLastRead()
{
    // A value read every cycle and never changed (an alarm word, read every round): its
    // age is that of the last cycle, not of the change the station last published.
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl(), {QStringLiteral("--heartbeat"), QStringLiteral("200")}));
    auto mirror = startMirror();
    QVERIFY(mirror);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    const DeviceId id = *mirror->findDevice(station, "line1", "ipc300@1");
    const QDateTime changed = mirror->published(id, "malfunction_signal_1")->read;
    QVERIFY(changed.isValid());
    const qint64 firstGood = mirror->entryState(id, "malfunction_signal_1")->goodMs;
    QSignalSpy read(mirror.get(), &RemoteStation::deviceRead);
    QTRY_VERIFY_WITH_TIMEOUT(mirror->entryState(id, "malfunction_signal_1")->goodMs >= firstGood + 2000, 30000);
    QCOMPARE(mirror->published(id, "malfunction_signal_1")->read, changed);   // no new publication of it
    QVERIFY(!read.isEmpty());
    // The viewer's lines carry it to the live values' Age column.
    RemoteLines lines(mirror.get());
    MirroredLine *line = lines.lines().constFirst();
    const DeviceId mirrored = line->device("ipc300", 1);
    read.clear();
    QVERIFY(read.wait(10000));
    QVERIFY(line->clockMs() - line->entryState(mirrored, "malfunction_signal_1")->goodMs < 5000);
}

void TstMqtt::lostSinceIsWhenTheViewerLostContact()
{
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl()));
    auto mirror = startMirror();
    QVERIFY(mirror);
    RemoteLines lines(mirror.get());
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror), 30000);
    // Long enough after the station's start and its line's last change to tell them apart.
    const QDateTime started = mirror->station(station)->status.started;
    QTRY_VERIFY_WITH_TIMEOUT(mirror->station(station)->lastHeartbeat > started.addSecs(3), 30000);
    MirroredLine *line = lines.lines().constFirst();
    const DeviceId ipc = line->device("ipc300", 1);
    const QDateTime beforeKill = QDateTime::currentDateTime();
    m_publisher->kill();
    QVERIFY(m_publisher->waitForFinished(10000));
    QTRY_COMPARE_WITH_TIMEOUT(line->condition(ipc).state, DeviceCondition::State::LineLost, 10000);
    const QDateTime since = line->condition(ipc).since;
    // The last heartbeat heard: at most a heartbeat interval (1 s) before the kill.
    QVERIFY2(since >= beforeKill.addMSecs(-2500) && since <= QDateTime::currentDateTime(),
             qPrintable(since.toString(Qt::ISODateWithMs) + " " + beforeKill.toString(Qt::ISODateWithMs)));
    QVERIFY(since > started.toLocalTime().addSecs(2));
}

void TstMqtt::aNewRunIsNotSilentBeforeItsFirstHeartbeat()
{
    // A restarted station says "online" and sends its first heartbeat up to a heartbeat
    // interval later. Its last run's last heartbeat must not make it silent meanwhile: that
    // was a false loss and return of every device in every viewer at each restart.
    QVERIFY(m_broker->start());
    auto mirror = startMirror();
    QVERIFY(mirror);
    auto fake = connectClient();
    QVERIFY(fake);
    const QString prefix = QStringLiteral("jumo/%1/").arg(station);
    const QDateTime firstRun = QDateTime::currentDateTimeUtc();
    QVERIFY(fake->publish(prefix + QStringLiteral("status"), TopicScheme::statusOnline("x", firstRun, {}), true));
    QVERIFY(fake->publish(prefix + QStringLiteral("heartbeat"), TopicScheme::heartbeatPayload(firstRun), false));
    QTRY_VERIFY_WITH_TIMEOUT(mirror->isLive(station), 20000);
    QVERIFY(fake->publish(prefix + QStringLiteral("status"), TopicScheme::statusOffline("stopped"), true));
    // Long after its last heartbeat, as a restart that takes a while.
    QTRY_VERIFY_WITH_TIMEOUT(mirror->station(station)->silent, 20000);
    QVERIFY(!mirror->isLive(station));
    QVERIFY(fake->publish(prefix + QStringLiteral("status"), TopicScheme::statusOnline("x", firstRun.addSecs(5), {}),
                          true));
    QTRY_VERIFY_WITH_TIMEOUT(mirror->isLive(station), 20000);
    // Without its heartbeat, silent again after the limit.
    QTRY_VERIFY_WITH_TIMEOUT(mirror->station(station)->silent, 20000);
    QVERIFY(!mirror->isLive(station));
}

void TstMqtt::aDeviceTheNextRunDropsIsNeverRestored()
{
    // The station restarts without a line. Until it clears that line's topics (after its
    // "online"), its device's retained condition still says online: a viewer must not
    // take that as the device restored (a false row in every viewer's journal).
    TestLine second;
    QVERIFY(second.start());
    SimulatorPeer secondPeer(QStringLiteral("quantrol"));
    QVERIFY(secondPeer.start(second.deviceEnd(), {1}));
    const QString both = writeTwoLineStation(second, {"cabinet-a", {"ipc300@1"}}, {"cabinet-b", {"quantrol@1"}});
    QVERIFY(m_broker->start());
    QVERIFY(startPublisher(brokerUrl(), {QStringLiteral("--station"), both}));
    auto mirror = startMirror();
    QVERIFY(mirror);
    RemoteLines lines(mirror.get());
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror, 2), 30000);
    MirroredLine *cabinetB = lines.line(station, QStringLiteral("cabinet-b"));
    QVERIFY(cabinetB);
    const DeviceId quantrol = cabinetB->device(QStringLiteral("quantrol"), 1);
    QList<DeviceCondition::State> states;
    connect(cabinetB, &DeviceSource::conditionChanged, this,
            [&](DeviceId id, const DeviceCondition &condition) {
                if (id == quantrol)
                    states << condition.state;
            });
    QSignalSpy removing(&lines, &RemoteLines::deviceRemoving);

    m_publisher->terminate();
    QVERIFY(m_publisher->waitForFinished(10000));
    QFile file(m_broker->file(QStringLiteral("one.json")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QJsonDocument(QJsonObject{{"format", "jumo-station"}, {"version", 1}, {"name", station},
                                         {"lines", QJsonArray{QJsonObject{{"name", "cabinet-a"},
                                                                          {"port", m_line->masterEnd()},
                                                                          {"baud", 19200},
                                                                          {"devices", QJsonArray{"ipc300@1"}}}}}})
                       .toJson());
    file.close();
    QVERIFY(startPublisher(brokerUrl(), {QStringLiteral("--station"), file.fileName()}));
    QTRY_VERIFY_WITH_TIMEOUT(!removing.isEmpty(), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(everythingCurrent(*mirror, 1), 30000);
    QVERIFY(!states.isEmpty());
    QVERIFY2(!states.contains(DeviceCondition::State::Online), qPrintable(QString::number(states.size())));
}

QTEST_GUILESS_MAIN(TstMqtt)
#include "tst_mqtt.moc"
