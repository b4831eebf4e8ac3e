// The MQTT topic and JSON scheme (README, "MQTT"): topics built and parsed, every payload
// as a viewer reads it, and broker addresses.
#include "mqtt/mqttsettings.h"
#include "mqtt/topicscheme.h"
#include "protocol/familyregistry.h"
#include "protocol/valuecodec.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace jumo;

namespace {

const FamilyRegistry &registry()
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return r;
}

QJsonObject json(const QByteArray &payload)
{
    return QJsonDocument::fromJson(payload).object();
}

} // namespace

class TstTopicScheme : public QObject
{
    Q_OBJECT

private slots:
    void topics_data();
    void topics();
    void foreignTopics_data();
    void foreignTopics();
    void values_data();
    void values();
    void bitsForScada();
    void stationMessages();
    void brokerUrls_data();
    void brokerUrls();
};

void TstTopicScheme::topics_data()
{
    QTest::addColumn<QString>("built");
    QTest::addColumn<QString>("expected");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("device");
    QTest::addColumn<QString>("entry");
    const TopicScheme s(QStringLiteral("plant/jumo"));
    using K = TopicScheme::Kind;
    QTest::newRow("status") << s.status("hall-3") << "plant/jumo/hall-3/status" << int(K::Status) << "" << "" << "";
    QTest::newRow("heartbeat") << s.heartbeat("hall-3") << "plant/jumo/hall-3/heartbeat" << int(K::Heartbeat) << ""
                               << "" << "";
    QTest::newRow("line") << s.line("hall-3", "cabinet-a") << "plant/jumo/hall-3/lines/cabinet-a" << int(K::Line)
                          << "cabinet-a" << "" << "";
    QTest::newRow("device info") << s.deviceInfo("hall-3", "cabinet-a", "ipc300@1")
                                 << "plant/jumo/hall-3/devices/cabinet-a/ipc300@1/info" << int(K::DeviceInfo)
                                 << "cabinet-a" << "ipc300@1" << "";
    QTest::newRow("device condition") << s.deviceCondition("hall-3", "gw", "tya200@12")
                                      << "plant/jumo/hall-3/devices/gw/tya200@12/condition" << int(K::DeviceCondition)
                                      << "gw" << "tya200@12" << "";
    QTest::newRow("value") << s.value("hall-3", "gw", "tya200@12", "load_voltage")
                           << "plant/jumo/hall-3/devices/gw/tya200@12/values/load_voltage" << int(K::Value) << "gw"
                           << "tya200@12" << "load_voltage";
    QTest::newRow("viewer") << s.viewer("hall-3", "viewer-pc-1") << "plant/jumo/hall-3/viewers/viewer-pc-1"
                            << int(K::Viewer) << "" << "" << "";
}

void TstTopicScheme::topics()
{
    QFETCH(QString, built);
    QFETCH(QString, expected);
    QFETCH(int, kind);
    QCOMPARE(built, expected);
    const auto topic = TopicScheme(QStringLiteral("plant/jumo")).parse(built);
    QVERIFY(topic);
    QCOMPARE(int(topic->kind), kind);
    QCOMPARE(topic->station, QStringLiteral("hall-3"));
    QTEST(topic->line, "line");
    QTEST(topic->device, "device");
    QTEST(topic->entry, "entry");
}

void TstTopicScheme::foreignTopics_data()
{
    QTest::addColumn<QString>("topic");
    QTest::newRow("another prefix") << "other/hall-3/status";
    QTest::newRow("prefix only") << "jumo/hall-3";
    QTest::newRow("unknown level") << "jumo/hall-3/alarms";
    QTest::newRow("value without entry") << "jumo/hall-3/devices/l/ipc300@1/values";
    QTest::newRow("value too deep") << "jumo/hall-3/devices/l/ipc300@1/values/a/b";
    QTest::newRow("device without what") << "jumo/hall-3/devices/l/ipc300@1";
    QTest::newRow("status too deep") << "jumo/hall-3/status/x";
    QTest::newRow("prefix as a part of a level") << "jumox/hall-3/status";
}

void TstTopicScheme::foreignTopics()
{
    QFETCH(QString, topic);
    QVERIFY(!TopicScheme().parse(topic));
}

void TstTopicScheme::values_data()
{
    QTest::addColumn<QString>("entry");
    QTest::addColumn<int>("validity");
    QTest::addColumn<int>("error");
    QTest::addColumn<int>("exception");
    QTest::addColumn<bool>("everRead");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("status");
    QTest::addColumn<QString>("validityName");

    const auto V = [](Validity v) { return int(v); };
    const auto E = [](ReadError e) { return int(e); };
    QTest::newRow("current float") << "load_voltage" << V(Validity::Current) << E(ReadError::None) << 0 << true
                                   << QJsonValue(230.5) << "230.5 V" << "ok" << "current";
    QTest::newRow("stale float keeps its value") << "load_voltage" << V(Validity::Stale) << E(ReadError::None) << 0
                                                 << true << QJsonValue(230.5) << "230.5 V" << "stale" << "stale";
    QTest::newRow("line lost: no value") << "load_voltage" << V(Validity::Unknown) << E(ReadError::LineLost) << 0
                                         << true << QJsonValue() << QString(QChar(0x2014)) << "line_lost" << "unknown";
    QTest::newRow("exception") << "load_voltage" << V(Validity::Unknown) << E(ReadError::Exception) << 2 << false
                               << QJsonValue() << QString(QChar(0x2014)) << "exception:2" << "unknown";
    QTest::newRow("never read") << "load_current" << V(Validity::Unknown) << E(ReadError::NotRead) << 0 << false
                                << QJsonValue() << QString(QChar(0x2014)) << "not_read" << "unknown";
    QTest::newRow("device offline") << "load_current" << V(Validity::Unknown) << E(ReadError::DeviceOffline) << 0
                                    << true << QJsonValue() << QString(QChar(0x2014)) << "offline" << "unknown";
}

void TstTopicScheme::values()
{
    QFETCH(QString, entry);
    QFETCH(int, validity);
    QFETCH(int, error);
    QFETCH(int, exception);
    QFETCH(bool, everRead);
    QFETCH(QJsonValue, value);
    const auto map = registry().family(QStringLiteral("ipc300"));
    QVERIFY(map);
    const RegisterEntry *e = map->entry(entry);
    QVERIFY(e);
    EntryState state;
    state.words = ValueCodec::encodeFloat(230.5f, map->protocol.floatWordOrder);
    state.value = ValueCodec::decode(*e, *map, state.words);
    state.validity = Validity(validity);
    state.error = ReadError(error);
    state.exceptionCode = exception;
    state.goodMs = everRead ? 1000 : -1;
    const QDateTime read = everRead ? QDateTime(QDate(2026, 12, 2), QTime(10, 20, 0, 123), Qt::UTC) : QDateTime();

    const QByteArray payload = TopicScheme::valuePayload(state, *e, read);
    const QJsonObject o = json(payload);
    QCOMPARE(o.value("value"), value);
    QTEST(o.value("text").toString(), "text");
    QTEST(o.value("status").toString(), "status");
    QTEST(o.value("validity").toString(), "validityName");
    QCOMPARE(o.value("unit").toString(), e->unit);
    QCOMPARE(o.value("words").toArray().size(), 2);
    QCOMPARE(o.contains("exception"), ReadError(error) == ReadError::Exception);
    if (everRead)
        QCOMPARE(o.value("read").toString(), QStringLiteral("2026-12-02T10:20:00.123Z"));
    else
        QVERIFY(o.value("read").isNull());
    QVERIFY(!o.contains("bits"));

    // What a viewer makes of it again.
    const auto parsed = TopicScheme::parseValue(payload);
    QVERIFY(parsed);
    QCOMPARE(int(parsed->validity), validity);
    QCOMPARE(int(parsed->error), ReadError(error) == ReadError::None ? int(ReadError::None) : error);
    QCOMPARE(parsed->exception, exception);
    QCOMPARE(parsed->words, state.words);
    QCOMPARE(parsed->read, read);
    QCOMPARE(parsed->status, state.statusName());
}

void TstTopicScheme::bitsForScada()
{
    const auto map = registry().family(QStringLiteral("ipc300"));
    const RegisterEntry *e = map->entry(QStringLiteral("malfunction_signal_1"));
    QVERIFY(e);
    QVERIFY(e->bits.size() >= 2);
    const BitDefinition &first = e->bits.constFirst();
    EntryState state;
    state.words = {quint16(first.mask())};
    state.value = ValueCodec::decode(*e, *map, state.words);
    state.validity = Validity::Current;
    state.error = ReadError::None;
    state.goodMs = 5;
    QJsonObject bits = json(TopicScheme::valuePayload(state, *e, QDateTime::currentDateTimeUtc())).value("bits").toObject();
    int named = 0;
    for (const BitDefinition &b : e->bits) {
        if (b.reserved) {
            QVERIFY(!bits.contains(b.id));
            continue;
        }
        ++named;
        QCOMPARE(bits.value(b.id), QJsonValue(b.id == first.id));
    }
    QCOMPARE(bits.size(), named);
    // Unknown: every bit null, none claimed off.
    state.validity = Validity::Unknown;
    state.error = ReadError::Timeout;
    bits = json(TopicScheme::valuePayload(state, *e, {})).value("bits").toObject();
    QCOMPARE(bits.size(), named);
    for (const QJsonValue &v : bits)
        QVERIFY(v.isNull());
    const auto parsed = TopicScheme::parseValue(TopicScheme::valuePayload(state, *e, {}));
    QVERIFY(parsed);
    QCOMPARE(parsed->bits.size(), named);
    QVERIFY(!parsed->bits.value(first.id).has_value());
}

void TstTopicScheme::stationMessages()
{
    const QDateTime t(QDate(2026, 12, 2), QTime(10, 20, 0, 123), Qt::UTC);
    QCOMPARE(json(TopicScheme::statusOnline("jumo-publisher 0.1.0", t, {"a", "b"})),
             QJsonObject({{"state", "online"},
                          {"software", "jumo-publisher 0.1.0"},
                          {"started", "2026-12-02T10:20:00.123Z"},
                          {"lines", QJsonArray{"a", "b"}}}));
    const auto online = TopicScheme::parseStatus(TopicScheme::statusOnline("x", t, {"a"}));
    QVERIFY(online && online->online && online->started == t && online->lines == QStringList{"a"});
    const auto will = TopicScheme::parseStatus(TopicScheme::statusOffline("connection lost"));
    QVERIFY(will && !will->online);
    QCOMPARE(will->reason, QStringLiteral("connection lost"));
    QVERIFY(!TopicScheme::parseStatus("{\"state\":\"sleeping\"}"));
    QVERIFY(!TopicScheme::parseStatus("not json"));
    QCOMPARE(TopicScheme::parseHeartbeat(TopicScheme::heartbeatPayload(t)), t);

    for (const auto &[address, kind] : {std::pair{"/dev/ttyUSB0", "rtu"}, {"tcp://10.0.0.20:502", "tcp"},
                                        {"rtu+tcp://10.0.0.21:4001", "rtu+tcp"}}) {
        const QByteArray payload = TopicScheme::linePayload(address, LineState::Lost, t, "line lost: gone");
        QCOMPARE(json(payload).value("kind").toString(), QString::fromLatin1(kind));
        const auto line = TopicScheme::parseLine(payload);
        QVERIFY(line);
        QCOMPARE(line->state, LineState::Lost);
        QCOMPARE(line->address, QString::fromLatin1(address));
        QCOMPARE(line->error, QStringLiteral("line lost: gone"));
        QCOMPARE(line->since, t);
    }

    using S = DeviceCondition::State;
    for (S s : {S::Online, S::Offline, S::LineLost, S::Disconnected, S::Identifying, S::WrongDevice}) {
        DeviceCondition c{s, t, QStringLiteral("why")};
        const auto parsed = TopicScheme::parseCondition(TopicScheme::conditionPayload(c));
        QVERIFY(parsed);
        QCOMPARE(parsed->condition.state, s);
        QCOMPARE(parsed->condition.since, t);
        QCOMPARE(parsed->condition.detail, QStringLiteral("why"));
        QVERIFY(!parsed->cycle.isValid());
    }
    QCOMPARE(json(TopicScheme::conditionPayload({S::LineLost, t, {}})).value("state").toString(),
             QStringLiteral("line_lost"));

    const auto map = registry().family(QStringLiteral("tya200"));
    const auto info = TopicScheme::parseDeviceInfo(TopicScheme::deviceInfoPayload("cabinet-a", *map, 7));
    QVERIFY(info);
    QCOMPARE(info->family, QStringLiteral("tya200"));
    QCOMPARE(info->address, 7);
    QCOMPARE(info->line, QStringLiteral("cabinet-a"));
    QCOMPARE(info->model, map->name);

    QCOMPARE(json(TopicScheme::viewerPayload("pc-7")), QJsonObject({{"state", "watching"}, {"host", "pc-7"}}));
    QCOMPARE(json(TopicScheme::viewerGonePayload()), QJsonObject({{"state", "gone"}}));
}

void TstTopicScheme::brokerUrls_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<bool>("valid");
    QTest::addColumn<QString>("host");
    QTest::addColumn<int>("port");
    QTest::addColumn<bool>("tls");
    QTest::addColumn<QString>("user");
    QTest::newRow("plain") << "mqtt://broker.local" << true << "broker.local" << 1883 << false << "";
    QTest::newRow("bare host") << "localhost" << true << "localhost" << 1883 << false << "";
    QTest::newRow("tls default port") << "mqtts://broker" << true << "broker" << 8883 << true << "";
    QTest::newRow("user and port") << "mqtt://station@10.0.0.5:1884" << true << "10.0.0.5" << 1884 << false
                                   << "station";
    QTest::newRow("ipv6") << "mqtt://[::1]:1883" << true << "::1" << 1883 << false << "";
    QTest::newRow("password in the url") << "mqtt://u:secret@host" << false << "" << 0 << false << "";
    QTest::newRow("other scheme") << "http://host" << false << "" << 0 << false << "";
    QTest::newRow("no host") << "mqtt://" << false << "" << 0 << false << "";
    QTest::newRow("a path") << "mqtt://host/jumo" << false << "" << 0 << false << "";
}

void TstTopicScheme::brokerUrls()
{
    QFETCH(QString, url);
    QFETCH(bool, valid);
    QString error;
    const auto settings = MqttSettings::fromUrl(url, &error);
    QCOMPARE(bool(settings), valid);
    if (!valid) {
        QVERIFY(!error.isEmpty());
        QVERIFY(!error.contains(QLatin1String("secret")));
        return;
    }
    QTEST(settings->host, "host");
    QTEST(int(settings->port), "port");
    QTEST(settings->tls, "tls");
    QTEST(settings->username, "user");
    QVERIFY(!settings->url().isEmpty());
}

QTEST_GUILESS_MAIN(TstTopicScheme)
#include "tst_topicscheme.moc"
