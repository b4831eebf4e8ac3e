#include "mqtt/retainedsweep.h"

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcMqtt)

namespace jumo {

RetainedSweep::RetainedSweep(const MqttSettings &broker, const TopicScheme &scheme, const QString &station, Owns owns,
                             QObject *parent)
    : QObject(parent), m_client(this), m_scheme(scheme), m_station(station),
      m_filter(scheme.stationFilter(station)), m_owns(std::move(owns))
{
    MqttSettings settings = broker;
    if (!settings.clientId.isEmpty())
        settings.clientId += QStringLiteral("-sweep");   // else one is made, unique in the process
    m_client.setSettings(settings);
    m_passEnd.setSingleShot(true);
    connect(&m_passEnd, &QTimer::timeout, this, &RetainedSweep::endPass);
    m_drain.setInterval(50);
    connect(&m_drain, &QTimer::timeout, this, &RetainedSweep::drain);
    connect(&m_client, &MqttClient::connected, this, &RetainedSweep::beginPass);
    connect(&m_client, &MqttClient::messageReceived, this, &RetainedSweep::onMessage);
    connect(&m_client, &MqttClient::disconnected, this, [this](const QString &reason) {
        if (reason.isEmpty() || !m_running)
            return;
        // Lost during a pass, or not let in (a broker's connection limit): the client tries
        // again, and the pass begins again; after three failures in a row it is given up.
        m_inPass = false;
        m_passEnd.stop();
        if (++m_failures < 3)
            return;
        qCWarning(lcMqtt).noquote() << "the clean-up of retained topics gave up after three failed connections ("
                                           + reason + QStringLiteral("): what an earlier run left stays until the "
                                                                     "station connects again");
        stop();
    });
    connect(&m_client, &MqttClient::refused, this, [this](const QString &reason) {
        qCWarning(lcMqtt).noquote() << "the clean-up of retained topics cannot connect:" << reason;
        stop();
    });
}

void RetainedSweep::start(int passMs)
{
    stop();
    m_passEnd.setInterval(passMs);
    m_running = true;
    m_pass = 0;
    m_cleared = 0;
    m_failures = 0;
    if (!m_client.connectToBroker()) {
        qCWarning(lcMqtt).noquote() << "the clean-up of retained topics cannot connect:" << m_client.lastError();
        m_running = false;
    }
}

void RetainedSweep::stop()
{
    m_passEnd.stop();
    m_drain.stop();
    m_inPass = false;
    m_running = false;
    m_client.disconnectFromBroker();
}

void RetainedSweep::beginPass()
{
    if (!m_running)
        return;
    m_inPass = true;
    m_failures = 0;
    m_found = 0;
    ++m_pass;
    m_client.subscribe(m_filter, 0);
    m_passEnd.start();
}

void RetainedSweep::onMessage(const QString &topic, const QByteArray &payload, bool retained)
{
    if (!m_inPass || !topic.startsWith(m_filter.chopped(1)))
        return;
    if (!retained) {
        endPass();
        return;
    }
    const std::optional<TopicScheme::Topic> parsed = m_scheme.parse(topic);
    if (payload.isEmpty() || !parsed || parsed->station != m_station || m_owns(*parsed))
        return;
    if (m_client.publish(topic, QByteArray(), true, 0))
        ++m_found;
}

void RetainedSweep::endPass()
{
    if (!m_inPass)
        return;
    m_inPass = false;
    m_passEnd.stop();
    m_cleared += m_found;
    m_client.unsubscribe(m_filter);
    m_drainTime.start();
    m_drain.start();
}

void RetainedSweep::drain()
{
    // The clears are QoS 0: out of the library's queue into the socket before the
    // DISCONNECT, or they are lost with the connection (the next pass finds them again).
    if (m_client.hasPendingWrites() && m_drainTime.elapsed() < 10000)
        return;
    m_drain.stop();
    // A new connection for each pass: nothing of this one's subscription can arrive in
    // the next.
    m_client.disconnectFromBroker();
    if (m_found > 0 && m_pass < maxPasses) {
        if (!m_client.connectToBroker())
            m_running = false;
        return;
    }
    m_running = false;
    emit finished(m_cleared, m_found, m_pass);
}

} // namespace jumo
