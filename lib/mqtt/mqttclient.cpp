#include "mqtt/mqttclient.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QRandomGenerator>
#include <QSocketNotifier>

#include <mosquitto.h>

#include <sys/ioctl.h>

#include <cerrno>
#include <cstring>
#include <mutex>

Q_DECLARE_LOGGING_CATEGORY(lcMqtt)

namespace jumo {

namespace {

void initLibrary()
{
    static std::once_flag once;
    std::call_once(once, [] { mosquitto_lib_init(); });
}

QString errorText(int rc)
{
    // MOSQ_ERR_ERRNO: the system's error says more than "unknown error".
    if (rc == MOSQ_ERR_ERRNO)
        return QString::fromLocal8Bit(std::strerror(errno));
    // libmosquitto 2.0 has no text for it ("Unknown error."): a stopped or hung broker.
    if (rc == MOSQ_ERR_KEEPALIVE)
        return MqttClient::tr("the broker did not answer within the keepalive time");
    return QString::fromUtf8(mosquitto_strerror(rc));
}

} // namespace

MqttClient::MqttClient(QObject *parent)
    : QObject(parent),
      m_randomId(randomId(QCoreApplication::applicationName().isEmpty() ? QStringLiteral("jumo")
                                                                         : QCoreApplication::applicationName()))
{
    initLibrary();
    // The library sends keepalive pings and notices a silent broker only when called.
    m_misc.setInterval(500);
    connect(&m_misc, &QTimer::timeout, this, &MqttClient::service);
    m_reconnect.setSingleShot(true);
    connect(&m_reconnect, &QTimer::timeout, this, &MqttClient::attempt);
}

MqttClient::~MqttClient()
{
    if (m_readNotifier)
        m_readNotifier->setEnabled(false);
    if (m_writeNotifier)
        m_writeNotifier->setEnabled(false);
    if (m_mosq)
        mosquitto_destroy(m_mosq);
}

QString MqttClient::randomId(const QString &prefix)
{
    QString name = prefix.left(40);
    for (QChar &c : name) {
        if (!c.isLetterOrNumber() && c != QLatin1Char('-') && c != QLatin1Char('_'))
            c = QLatin1Char('_');
    }
    return QStringLiteral("%1-%2").arg(name).arg(QRandomGenerator::system()->generate64(), 16, 16, QLatin1Char('0'));
}

QString MqttClient::clientId() const
{
    if (!m_settings.clientId.isEmpty())
        return m_settings.clientId;
    return m_randomId;
}

void MqttClient::setWill(const QString &topic, const QByteArray &payload)
{
    m_willTopic = topic;
    m_willPayload = payload;
}

void MqttClient::setReconnectDelays(int firstMs, int longestMs)
{
    m_firstDelayMs = firstMs;
    m_longestDelayMs = longestMs;
    m_delayMs = firstMs;
}

bool MqttClient::connectToBroker()
{
    if (m_mosq) {
        m_readNotifier.reset();
        m_writeNotifier.reset();
        m_socket = -1;
        mosquitto_destroy(m_mosq);
        m_mosq = nullptr;
    }
    m_mosq = mosquitto_new(clientId().toUtf8().constData(), true, this);
    if (!m_mosq) {
        m_lastError = tr("cannot make an MQTT client: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    mosquitto_int_option(m_mosq, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
    mosquitto_connect_callback_set(m_mosq, &MqttClient::onConnect);
    mosquitto_disconnect_callback_set(m_mosq, &MqttClient::onDisconnect);
    mosquitto_message_callback_set(m_mosq, &MqttClient::onMessage);
    mosquitto_publish_callback_set(m_mosq, &MqttClient::onPublish);
    // Reconnects are ours (attempt()), with our delays; the library's own loop is not used.
    if (!m_settings.username.isEmpty()) {
        const int rc = mosquitto_username_pw_set(m_mosq, m_settings.username.toUtf8().constData(),
                                                 m_settings.password.isEmpty() ? nullptr
                                                                               : m_settings.password.toUtf8().constData());
        if (rc != MOSQ_ERR_SUCCESS) {
            m_lastError = tr("cannot use the user name: %1").arg(errorText(rc));
            return false;
        }
    }
    if (m_settings.tls) {
        for (const QString &file : {m_settings.caFile, m_settings.certFile, m_settings.keyFile}) {
            if (!file.isEmpty() && !QFileInfo(file).isReadable()) {
                m_lastError = tr("cannot read the TLS file %1").arg(file);
                return false;
            }
        }
        if (m_settings.certFile.isEmpty() != m_settings.keyFile.isEmpty()) {
            m_lastError = tr("a client certificate needs its key, and a key its certificate");
            return false;
        }
        auto bytes = [](const QString &file) { return file.isEmpty() ? QByteArray() : QFile::encodeName(file); };
        const QByteArray ca = bytes(m_settings.caFile);
        const QByteArray cert = bytes(m_settings.certFile);
        const QByteArray key = bytes(m_settings.keyFile);
        const int rc = mosquitto_tls_set(m_mosq, ca.isEmpty() ? nullptr : ca.constData(),
                                         ca.isEmpty() ? "/etc/ssl/certs" : nullptr,
                                         cert.isEmpty() ? nullptr : cert.constData(),
                                         key.isEmpty() ? nullptr : key.constData(), nullptr);
        if (rc != MOSQ_ERR_SUCCESS) {
            m_lastError = tr("cannot set up TLS: %1").arg(errorText(rc));
            return false;
        }
    }
    if (!m_willTopic.isEmpty()) {
        const int rc = mosquitto_will_set(m_mosq, m_willTopic.toUtf8().constData(), int(m_willPayload.size()),
                                          m_willPayload.constData(), 1, true);
        if (rc != MOSQ_ERR_SUCCESS) {
            m_lastError = tr("cannot set the last will: %1").arg(errorText(rc));
            return false;
        }
    }
    m_wanted = true;
    m_delayMs = m_firstDelayMs;
    m_saidRefusal.clear();
    m_misc.start();
    attempt();
    return true;
}

void MqttClient::disconnectFromBroker()
{
    if (m_inLibrary) {
        // Called from one of the library's callbacks: done once it has returned.
        QMetaObject::invokeMethod(this, &MqttClient::disconnectFromBroker, Qt::QueuedConnection);
        return;
    }
    m_wanted = false;
    m_reconnect.stop();
    if (!m_mosq)
        return;
    if (m_state == State::Connected) {
        // What the broker sent and nobody read yet is read first: a socket closed with
        // unread data is reset by the kernel, and the broker may lose the DISCONNECT
        // with it and send the will after all.
        drainIncoming();
        // Sends DISCONNECT now; the broker drops the will. onDisconnect(0) follows.
        mosquitto_disconnect(m_mosq);
        service();
    }
    if (m_state != State::Disconnected)
        lost(QString());
    m_misc.stop();
    syncNotifiers();
}

bool MqttClient::publish(const QString &topic, const QByteArray &payload, bool retain, int qos, int *messageId)
{
    if (m_state != State::Connected)
        return false;
    const int rc = mosquitto_publish(m_mosq, messageId, topic.toUtf8().constData(), int(payload.size()),
                                     payload.isEmpty() ? nullptr : payload.constData(), qos, retain);
    syncNotifiers();
    if (rc != MOSQ_ERR_SUCCESS) {
        qCDebug(lcMqtt).noquote() << "publish" << topic << "failed:" << errorText(rc);
        return false;
    }
    ++m_published;
    return true;
}

void MqttClient::drainIncoming()
{
    // Bounded in time as well: a flood that keeps coming must not hold up a stop.
    QElapsedTimer draining;
    draining.start();
    m_inLibrary = true;
    int available = 0;
    for (int i = 0; i < 100000 && draining.elapsed() < 1000 && m_socket >= 0
         && ::ioctl(m_socket, FIONREAD, &available) == 0 && available > 0;
         ++i) {
        if (mosquitto_loop_read(m_mosq, 1) != MOSQ_ERR_SUCCESS)
            break;
    }
    m_inLibrary = false;
}

bool MqttClient::hasPendingWrites() const
{
    return m_mosq && m_state == State::Connected && mosquitto_want_write(m_mosq);
}

void MqttClient::unsubscribe(const QString &filter)
{
    const qsizetype index = m_subscriptions.indexOf(filter);
    if (index < 0)
        return;
    m_subscriptions.removeAt(index);
    m_subscriptionQos.removeAt(index);
    if (m_state == State::Connected) {
        mosquitto_unsubscribe(m_mosq, nullptr, filter.toUtf8().constData());
        syncNotifiers();
    }
}

void MqttClient::subscribe(const QString &filter, int qos)
{
    if (m_subscriptions.contains(filter))
        return;
    m_subscriptions << filter;
    m_subscriptionQos << qos;
    if (m_state == State::Connected) {
        mosquitto_subscribe(m_mosq, nullptr, filter.toUtf8().constData(), qos);
        syncNotifiers();
    }
}

void MqttClient::attempt()
{
    if (!m_wanted || !m_mosq)
        return;
    m_state = State::Connecting;
    m_refusal.clear();
    // Resolving the host name blocks for as long as the resolver takes: with a name
    // from /etc/hosts or an address, no time at all.
    const int rc = mosquitto_connect_async(m_mosq, m_settings.host.toUtf8().constData(), m_settings.port,
                                           m_settings.keepAliveS);
    syncNotifiers();
    if (rc != MOSQ_ERR_SUCCESS)
        lost(errorText(rc));
}

void MqttClient::service()
{
    if (!m_mosq)
        return;
    // A poll with no timeout: reads, writes, completes the TLS handshake and sends the
    // keepalive as far as the socket allows, and returns at once.
    if (m_inLibrary)
        return;
    m_inLibrary = true;
    const int rc = mosquitto_loop(m_mosq, 0, 1);
    m_inLibrary = false;
    syncNotifiers();
    // A closed socket the callbacks did not report (an error before the connect).
    if (m_socket < 0 && m_state != State::Disconnected && rc != MOSQ_ERR_SUCCESS)
        lost(errorText(rc));
}

void MqttClient::syncNotifiers()
{
    const int fd = m_mosq ? mosquitto_socket(m_mosq) : -1;
    if (fd != m_socket) {
        // Possibly inside one of their own signals: deleted later.
        if (m_readNotifier) {
            m_readNotifier->setEnabled(false);
            m_readNotifier.release()->deleteLater();
        }
        if (m_writeNotifier) {
            m_writeNotifier->setEnabled(false);
            m_writeNotifier.release()->deleteLater();
        }
        m_socket = fd;
        if (fd >= 0) {
            m_readNotifier = std::make_unique<QSocketNotifier>(fd, QSocketNotifier::Read);
            connect(m_readNotifier.get(), &QSocketNotifier::activated, this, &MqttClient::service);
            m_writeNotifier = std::make_unique<QSocketNotifier>(fd, QSocketNotifier::Write);
            connect(m_writeNotifier.get(), &QSocketNotifier::activated, this, &MqttClient::service);
        }
    }
    if (m_writeNotifier)
        m_writeNotifier->setEnabled(mosquitto_want_write(m_mosq));
}

void MqttClient::lost(const QString &reason)
{
    const bool wasUp = m_state != State::Disconnected;
    m_state = State::Disconnected;
    if (!reason.isEmpty())
        m_lastError = reason;
    if (wasUp)
        emit disconnected(reason);
    scheduleReconnect();
}

void MqttClient::scheduleReconnect()
{
    if (!m_wanted || m_reconnect.isActive())
        return;
    m_reconnect.start(m_delayMs);
    m_delayMs = std::min(m_delayMs * 2, m_longestDelayMs);
}

void MqttClient::handleConnect(int rc)
{
    if (rc != 0) {
        // The library closes the connection next and reports it through onDisconnect.
        m_refusal = tr("the broker refused the connection: %1").arg(QString::fromUtf8(mosquitto_connack_string(rc)));
        return;
    }
    m_state = State::Connected;
    m_delayMs = m_firstDelayMs;
    m_saidRefusal.clear();
    m_lastError.clear();
    for (qsizetype i = 0; i < m_subscriptions.size(); ++i)
        mosquitto_subscribe(m_mosq, nullptr, m_subscriptions[i].toUtf8().constData(), m_subscriptionQos[i]);
    emit connected();
}

void MqttClient::handleDisconnect(int rc)
{
    QString reason;
    if (!m_refusal.isEmpty()) {
        reason = m_refusal;
        if (reason != m_saidRefusal) {
            m_saidRefusal = reason;
            emit refused(reason);
        }
    } else if (rc != 0 || m_wanted) {
        reason = rc == 0 ? tr("the broker closed the connection") : errorText(rc);
    }
    lost(reason);
}

void MqttClient::onConnect(mosquitto *, void *self, int rc)
{
    static_cast<MqttClient *>(self)->handleConnect(rc);
}

void MqttClient::onDisconnect(mosquitto *, void *self, int rc)
{
    static_cast<MqttClient *>(self)->handleDisconnect(rc);
}

void MqttClient::onMessage(mosquitto *, void *self, const mosquitto_message *message)
{
    auto *client = static_cast<MqttClient *>(self);
    if (client->m_maximumPayload > 0 && message->payloadlen > client->m_maximumPayload) {
        // Not even copied: the library frees it when this returns.
        ++client->m_oversize;
        emit client->oversizeMessage(QString::fromUtf8(message->topic), message->payloadlen);
        return;
    }
    emit client->messageReceived(QString::fromUtf8(message->topic),
                                 QByteArray(static_cast<const char *>(message->payload), message->payloadlen),
                                 message->retain);
}

void MqttClient::onPublish(mosquitto *, void *self, int messageId)
{
    emit static_cast<MqttClient *>(self)->delivered(messageId);
}

} // namespace jumo
