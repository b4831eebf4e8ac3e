#include "mqtt/namecheck.h"

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcMqtt)

namespace jumo {

namespace {

// Retained messages follow the subscription at once; this is ample for a slow link.
constexpr int retainedWaitMs = 1000;
// A broker that cannot be reached at all cannot tell whether the name is taken.
constexpr int connectWaitMs = 10000;

} // namespace

NameCheck::NameCheck(const MqttSettings &broker, const TopicScheme &scheme, const QString &station, QObject *parent)
    : QObject(parent), m_client(this), m_scheme(scheme), m_station(station)
{
    MqttSettings settings = broker;
    settings.clientId.clear();
    m_client.setSettings(settings);
    m_client.setMaximumPayload(64 * 1024);
    m_client.subscribe(m_scheme.status(station), 0);
    m_client.subscribe(m_scheme.heartbeat(station), 0);
    m_wait.setSingleShot(true);
    connect(&m_wait, &QTimer::timeout, this, [this] {
        if (m_statusOnline)
            qCInfo(lcMqtt).noquote() << "the retained status of station" << m_station << "says online, but no heartbeat "
                                        "came for" << heartbeatWaitMs / 1000 << "s: taken as left over";
        finish(false);
    });
    connect(&m_client, &MqttClient::connected, this, [this] { m_wait.start(retainedWaitMs); });
    // Not reached or not let in: nothing can be told; the station starts and keeps trying.
    connect(&m_client, &MqttClient::disconnected, this, [this] { finish(false); });
    connect(&m_client, &MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload, bool retained) {
                if (topic == m_scheme.heartbeat(m_station)) {
                    if (!retained && TopicScheme::parseHeartbeat(payload))
                        finish(true);
                    return;
                }
                const std::optional<StationStatusMessage> status = TopicScheme::parseStatus(payload);
                if (!status || !status->online) {
                    finish(false);
                } else if (!m_statusOnline) {
                    m_statusOnline = true;
                    m_wait.start(heartbeatWaitMs);
                }
            });
}

void NameCheck::start()
{
    if (!m_client.connectToBroker()) {
        // Said by the station's own connection, which fails the same way; after start()
        // has returned, so whoever started it hears the end.
        QTimer::singleShot(0, this, [this] { finish(false); });
        return;
    }
    m_wait.start(connectWaitMs);
}

void NameCheck::finish(bool online)
{
    if (m_done)
        return;
    m_done = true;
    m_wait.stop();
    m_client.disconnectFromBroker();
    emit finished(online);
}

} // namespace jumo
