#include "mqtt/stationguard.h"

#include <QLoggingCategory>

#include <chrono>

Q_DECLARE_LOGGING_CATEGORY(lcMqtt)

namespace jumo {

namespace {

// An echo not back within this long is taken as lost (a busy broker drops messages to a
// slow subscriber): the topic is judged by what comes next.
constexpr qint64 echoTimeoutMs = 5000;
// Echoes awaited per topic: a value changing faster than its echoes come back.
constexpr qsizetype maxInFlight = 64;
// Messages logged one by one; after that only counted (the status says how many).
constexpr int maxSaid = 20;

qint64 nowMs()
{
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
            .count();
}

} // namespace

StationGuard::StationGuard(const MqttSettings &broker, const TopicScheme &scheme, const QString &station, Owns owns,
                           QObject *parent)
    : QObject(parent), m_client(this), m_scheme(scheme), m_station(station), m_filter(scheme.stationFilter(station)),
      m_owns(std::move(owns))
{
    MqttSettings settings = broker;
    settings.clientId.clear();   // an id of its own
    m_client.setSettings(settings);
    // A station's own messages are small; a flood of huge ones is not read into memory.
    m_client.setMaximumPayload(64 * 1024);
    m_client.subscribe(m_filter, 0);
    connect(&m_client, &MqttClient::messageReceived, this, &StationGuard::onMessage);
    connect(&m_client, &MqttClient::connected, this, [this] {
        // Echoes of what was sent before this connection's subscription never come.
        for (Watch &w : m_watches)
            w.inFlight.clear();
    });
    m_recheck.setInterval(1000);
    connect(&m_recheck, &QTimer::timeout, this, &StationGuard::recheck);
}

void StationGuard::start(const QDateTime &started)
{
    m_started = started;
    if (!m_client.connectToBroker())
        qCWarning(lcMqtt).noquote() << "the watch over the station's topics cannot connect:" << m_client.lastError();
    m_recheck.start();
}

void StationGuard::stop()
{
    m_recheck.stop();
    m_client.disconnectFromBroker();
}

void StationGuard::expect(const QString &topic, const QByteArray &payload)
{
    Watch &w = m_watches[qHash(topic)];
    w.latest = qHash(payload);
    if (!m_client.isConnected())
        return;
    if (w.inFlight.size() >= maxInFlight)
        w.inFlight.removeFirst();
    w.inFlight.append({w.latest, nowMs()});
}

void StationGuard::onMessage(const QString &topic, const QByteArray &payload, bool retained)
{
    // Retained ones come on subscribing: what an earlier run or anyone left before, the
    // sweep's to clear; the station's own publishing overwrites the rest.
    if (retained)
        return;
    const std::optional<TopicScheme::Topic> parsed = m_scheme.parse(topic);
    using Kind = TopicScheme::Kind;
    if (!parsed || parsed->station != m_station || parsed->kind == Kind::Heartbeat || parsed->kind == Kind::Viewer
        || parsed->kind == Kind::Probe)
        return;
    const size_t key = qHash(topic);
    const size_t hash = qHash(payload);
    auto w = m_watches.find(key);
    if (w != m_watches.end()) {
        w->lastSeen = hash;
        const auto echo = std::find_if(w->inFlight.cbegin(), w->inFlight.cend(), [hash](const Sent &s) { return s.hash == hash; });
        if (echo != w->inFlight.cend()) {
            w->inFlight.erase(w->inFlight.cbegin(), echo + 1);
            return;
        }
        const qint64 now = nowMs();
        w->inFlight.removeIf([now](const Sent &s) { return now - s.atMs > echoTimeoutMs; });
    }
    if (!m_owns(*parsed)) {
        if (payload.isEmpty())
            return;
        // Not the station's: junk, or a device or entry it no longer has. Cleared.
        if (m_client.publish(topic, QByteArray(), true, 0)) {
            ++m_cleared;
            report(QStringLiteral("cleared"), topic);
        }
        return;
    }
    if (w != m_watches.end() && w->latest == hash)
        return;   // what the station published last (or the same again)
    if (parsed->kind == Kind::Status) {
        const std::optional<StationStatusMessage> status = TopicScheme::parseStatus(payload);
        // An "online" of another run (its own start time): another publisher of this name.
        if (status && status->online && status->started != m_started) {
            emit otherPublisherOnline();
            return;
        }
    }
    if (w != m_watches.end() && !w->inFlight.isEmpty()) {
        // The station's own message is on its way, behind this one: it overwrites it. If
        // its echo is lost, recheck() decides by what was seen last.
        m_suspects.insert(key, topic);
        return;
    }
    restore(topic);
}

void StationGuard::recheck()
{
    const qint64 now = nowMs();
    for (auto it = m_suspects.begin(); it != m_suspects.end();) {
        auto w = m_watches.find(it.key());
        if (w == m_watches.end()) {
            it = m_suspects.erase(it);
            continue;
        }
        w->inFlight.removeIf([now](const Sent &s) { return now - s.atMs > echoTimeoutMs; });
        if (!w->inFlight.isEmpty()) {
            ++it;
            continue;
        }
        const QString topic = it.value();
        const bool foreign = w->lastSeen != w->latest;
        it = m_suspects.erase(it);
        if (foreign)
            restore(topic);
    }
}

void StationGuard::restore(const QString &topic)
{
    ++m_restored;
    report(QStringLiteral("restored"), topic);
    emit restoreRequested(topic);
}

void StationGuard::report(const QString &what, const QString &topic)
{
    if (m_said < maxSaid) {
        ++m_said;
        if (what == QLatin1String("restored"))
            qCWarning(lcMqtt).noquote() << "another client wrote on" << topic << "- the station's own message is published again";
        else
            qCWarning(lcMqtt).noquote() << "another client published" << topic << "under this station - cleared";
        if (m_said == maxSaid)
            qCWarning(lcMqtt).noquote() << "further messages of other clients under this station are counted in its status, "
                                           "not logged one by one";
    }
    emit countsChanged();
}

} // namespace jumo
