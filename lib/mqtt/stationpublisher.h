// Publishes what the buses of a station know to an MQTT broker (README, "MQTT"): the
// station's status with a last will, a heartbeat, each line's state, each device's
// identity and condition, and every value when its text or status changes, straight from
// the buses' signals. Everything but the heartbeat is retained, and all of it is published
// again on every connect, so a broker restarted without persistence loses nothing. It
// only reads the buses.
#pragma once

#include "mqtt/mqttclient.h"
#include "mqtt/retainedsweep.h"
#include "mqtt/stationguard.h"
#include "mqtt/topicscheme.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QObject>
#include <QQueue>
#include <QSet>
#include <QPointer>
#include <QTimer>

#include <algorithm>

namespace jumo {

class Bus;

class StationPublisher : public QObject
{
    Q_OBJECT

public:
    StationPublisher(const MqttSettings &broker, const QString &prefix, const QString &station,
                     QObject *parent = nullptr);
    ~StationPublisher() override;

    // A line and its devices, under a name that is one topic level. The bus stays the
    // caller's; the publisher only reads it.
    void addLine(const QString &name, Bus *bus);
    // Clears the line's retained topics and those of its devices.
    void removeLine(const QString &name);
    // After devices were added to or removed from a line's bus: publishes the new ones
    // and clears the retained topics of those gone.
    void syncDevices(const QString &line);
    QStringList lines() const;

    // Connects (asynchronously, with retries); false with the reason for what no retry
    // can mend (unreadable TLS files).
    bool start(QString *error);
    // Publishes the clean "stopped" status and disconnects; stopped() follows, also when
    // the broker cannot be reached.
    void stop();

    QString station() const { return m_station; }
    const TopicScheme &scheme() const { return m_scheme; }
    MqttClient &client() { return m_client; }
    void setHeartbeatInterval(int ms) { m_heartbeat.setInterval(ms); }

signals:
    void stopped();
    // Every full publication of the state (after each connect), with its message count.
    void statePublished(int messages);
    // Heartbeats this publisher did not send came on its station's topic: another
    // publisher runs under the same name, and the two overwrite each other's topics (and a
    // clean stop of either says the whole station is offline). Said once.
    void rivalHeard();
    // Another publisher said "online" under this station's name (one started with
    // --take-over): this one has stopped publishing, without a word on the status.
    void takenOver();

private:
    struct Device
    {
        QString line;
        QString name;   // "family@address"
        std::shared_ptr<const RegisterMap> map;
        QStringList entries;                 // what it publishes: what its bus polls, in map order
        QSet<QString> entrySet;
        QHash<QString, QString> published;   // entry id -> text and status last published
        QByteArray condition;                // the condition last published, without its cycle
        QDateTime cycle;                     // the end of its last poll cycle
        qint64 cycleSentMs = -1;             // when a cycle was last published (monotonic)
    };
    struct Line
    {
        QString name;
        QPointer<Bus> bus;
        QDateTime since;
        QString error;
        QList<QMetaObject::Connection> connections;
        QByteArray lastPayload;
    };

    void onConnected();
    void publishAll();
    void publishStatus();
    void publishLine(Line &line, bool force);
    void publishDevice(DeviceId id);
    // force: also when only the cycle is new.
    void publishCondition(DeviceId id, bool force);
    void publishOrder();
    // Another client wrote on one of the station's topics: its own message again.
    void restore(const QString &topic);
    void stopTakenOver();
    void publishEntries(DeviceId id, const QStringList &entryIds, bool force);
    void forgetDevice(DeviceId id);
    // What this run publishes (or, status, heartbeat and viewers, leaves alone): after each
    // connect, m_sweep clears every other retained topic under the station.
    bool owns(const TopicScheme::Topic &topic) const;
    void clear(const QString &topic);
    Line *lineOf(const Bus *bus);
    Line *lineNamed(const QString &name);
    void publish(const QString &topic, const QByteArray &payload, bool retain = true);

    MqttClient m_client;
    TopicScheme m_scheme;
    QString m_station;
    QDateTime m_started;
    QList<Line> m_lines;
    QHash<DeviceId, Device> m_devices;
    QStringList m_pendingClears;   // retained topics to clear once connected again
    QTimer m_heartbeat;
    QTimer m_stopDeadline;
    bool m_stopping = false;
    bool m_stopSignalled = false;
    // Ours, to know them when they come back: also those a stalled broker passes on
    // late, after a reconnect (a QSet for the look-up, the queue for the order).
    QSet<QByteArray> m_sentHeartbeats;
    QQueue<QByteArray> m_sentOrder;
    bool m_rivalSaid = false;
    QString m_saidLoss;            // the broker's last reason logged: a retry every 10 s does not repeat it
    int m_messages = 0;            // counting the messages of one full publication
    RetainedSweep m_sweep;
    StationGuard m_guard;
    QTimer m_statusDue;
    QElapsedTimer m_uptime;            // the guard's counts go into the status, not more than every 2 s
};

} // namespace jumo
