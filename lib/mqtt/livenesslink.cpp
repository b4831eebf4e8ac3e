#include "mqtt/livenesslink.h"

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcMqtt)

namespace jumo {

namespace {

// A status or a heartbeat is a few hundred bytes; a probe comes back as sent.
constexpr int maximumPayload = 16 * 1024;

} // namespace

LivenessLink::LivenessLink(QObject *parent) : QObject(parent), m_client(this)
{
    m_client.setMaximumPayload(maximumPayload);
    connect(&m_client, &MqttClient::connected, this, [this] {
        m_probed.clear();
        emit connectionChanged(true);
    });
    connect(&m_client, &MqttClient::disconnected, this, [this] {
        // Probes in flight are void with the connection; they are sent again on the next.
        for (auto it = m_probes.cbegin(); it != m_probes.cend(); ++it)
            m_client.unsubscribe(it.key());
        m_probes.clear();
        emit connectionChanged(false);
    });
    connect(&m_client, &MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload, bool) { onMessage(topic, payload); });
}

bool LivenessLink::start(const MqttSettings &broker, const TopicScheme &scheme, const QString &station,
                         QString *error)
{
    m_scheme = scheme;
    MqttSettings settings = broker;
    settings.clientId.clear();   // an id of its own: one id on two connections throws one off
    m_client.setSettings(settings);
    const QString name = station.isEmpty() ? QStringLiteral("+") : station;
    m_client.subscribe(m_scheme.status(name), 0);
    m_client.subscribe(m_scheme.heartbeat(name), 0);
    if (!m_client.connectToBroker()) {
        if (error)
            *error = m_client.lastError();
        return false;
    }
    return true;
}

void LivenessLink::stop()
{
    m_client.disconnectFromBroker();
}

void LivenessLink::probe(const QString &station)
{
    if (!m_client.isConnected() || m_probed.contains(station))
        return;
    m_probed.insert(station);
    // Subscribed before it is sent: the broker takes both in this order.
    const QString topic = m_scheme.probe(station, MqttClient::randomId(QStringLiteral("probe")));
    m_probes.insert(topic, station);
    m_client.subscribe(topic, 0);
    m_client.publish(topic, QByteArrayLiteral("{\"probe\":true}"), false, 1);
}

void LivenessLink::onMessage(const QString &topic, const QByteArray &payload)
{
    if (const auto probe = m_probes.find(topic); probe != m_probes.end()) {
        const QString station = probe.value();
        m_client.unsubscribe(topic);
        m_probes.erase(probe);
        qCWarning(lcMqtt).noquote() << "the broker" << m_client.settings().url()
                                    << "let this viewer publish into the tree of station" << station
                                    << "- anyone with the same access can forge its values and liveness";
        emit writable(station);
        return;
    }
    const std::optional<TopicScheme::Topic> parsed = m_scheme.parse(topic);
    if (!parsed)
        return;
    if (parsed->kind == TopicScheme::Kind::Status)
        emit statusReceived(parsed->station, payload);
    else if (parsed->kind == TopicScheme::Kind::Heartbeat)
        emit heartbeatReceived(parsed->station, payload);
}

} // namespace jumo
