// An MQTT client on libmosquitto, driven from the Qt event loop of its thread: socket
// notifiers and a timer call the library, which never blocks and needs no thread of its
// own. Connects asynchronously, reconnects by itself with a growing delay, publishes with
// QoS 1 and re-subscribes its subscriptions on every connect.
#pragma once

#include "mqtt/mqttsettings.h"

#include <QByteArray>
#include <QObject>
#include <QStringList>
#include <QTimer>

#include <memory>

struct mosquitto;
struct mosquitto_message;
class QSocketNotifier;

namespace jumo {

class MqttClient : public QObject
{
    Q_OBJECT

public:
    enum class State { Disconnected, Connecting, Connected };

    explicit MqttClient(QObject *parent = nullptr);
    ~MqttClient() override;

    void setSettings(const MqttSettings &settings) { m_settings = settings; }
    const MqttSettings &settings() const { return m_settings; }
    // Published by the broker (retained, QoS 1) when this client is gone without a clean
    // disconnect. Takes effect at the next connect.
    void setWill(const QString &topic, const QByteArray &payload);

    // Starts connecting and keeps the connection up until disconnectFromBroker(). Returns
    // false with the reason in lastError() for what no retry can mend (unreadable TLS
    // files, no such library feature); a broker that cannot be reached is retried.
    bool connectToBroker();
    // A clean disconnect: the broker drops the will. disconnected() follows.
    void disconnectFromBroker();

    // Retained or not, QoS 1 unless told. Returns false (and drops the message) while not
    // connected: the callers publish their whole state again on connected().
    // messageId, when given, is what delivered() names once the broker has the message.
    bool publish(const QString &topic, const QByteArray &payload, bool retain, int qos = 1, int *messageId = nullptr);
    // Kept and subscribed again on every connect.
    void subscribe(const QString &filter, int qos = 1);
    // Messages handed over that the socket has not taken yet.
    bool hasPendingWrites() const;
    // Ends a subscription (also for later reconnects).
    void unsubscribe(const QString &filter);

    // The settings' client id, or the program's name and 64 random bits, made once per
    // client: a broker drops a client whose id another connection takes, so an id must
    // not be guessable, and it is never published (README, "Client ids").
    QString clientId() const;
    // "PREFIX-" and 16 random hex digits, from the system's random source.
    static QString randomId(const QString &prefix);

    // Messages with a larger payload are dropped unread by the callers (counted and said
    // once): a flood of huge retained messages must not fill the program's memory. 0: no limit.
    void setMaximumPayload(int bytes) { m_maximumPayload = bytes; }
    quint64 oversizeDropped() const { return m_oversize; }

    State state() const { return m_state; }
    bool isConnected() const { return m_state == State::Connected; }
    QString lastError() const { return m_lastError; }
    // Messages handed to the library since the start (for statistics and benchmarks).
    quint64 publishedCount() const { return m_published; }

    // The delays between attempts: from the first to the longest, doubling.
    void setReconnectDelays(int firstMs, int longestMs);

signals:
    void connected();
    // The connection ended or an attempt failed; the client tries again unless it was
    // disconnectFromBroker(). reason is empty for a clean disconnect.
    void disconnected(const QString &reason);
    // The broker refused the connection (credentials, authorisation): said once per reason.
    void refused(const QString &reason);
    void messageReceived(const QString &topic, const QByteArray &payload, bool retained);
    // The broker acknowledged a message of QoS 1 (or a QoS 0 message was sent).
    void delivered(int messageId);
    // A message over setMaximumPayload() was dropped (its topic and size).
    void oversizeMessage(const QString &topic, qint64 bytes);

private:
    static void onConnect(mosquitto *, void *self, int rc);
    static void onDisconnect(mosquitto *, void *self, int rc);
    static void onMessage(mosquitto *, void *self, const mosquitto_message *message);
    static void onPublish(mosquitto *, void *self, int messageId);

    void handleConnect(int rc);
    void handleDisconnect(int rc);
    void attempt();
    void drainIncoming();
    void service();
    void syncNotifiers();
    void lost(const QString &reason);
    void scheduleReconnect();

    MqttSettings m_settings;
    mosquitto *m_mosq = nullptr;
    QString m_willTopic;
    QByteArray m_willPayload;
    QStringList m_subscriptions;
    QList<int> m_subscriptionQos;
    State m_state = State::Disconnected;
    QString m_lastError;
    QString m_refusal;        // the broker's reason for the current attempt's failure
    QString m_saidRefusal;    // the last refusal signalled, so a retry does not repeat it
    bool m_wanted = false;    // connectToBroker() until disconnectFromBroker()
    bool m_inLibrary = false; // inside mosquitto_loop(): its callbacks must not call it again
    int m_socket = -1;
    std::unique_ptr<QSocketNotifier> m_readNotifier;
    std::unique_ptr<QSocketNotifier> m_writeNotifier;
    QTimer m_misc;            // keepalive pings and their timeout
    QTimer m_reconnect;
    int m_firstDelayMs = 250;
    int m_longestDelayMs = 10000;
    int m_delayMs = 250;
    quint64 m_published = 0;
    QString m_randomId;
    int m_maximumPayload = 0;
    quint64 m_oversize = 0;
};

} // namespace jumo
