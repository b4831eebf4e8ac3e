// A station's watch over its own topics, on a connection of its own (as RetainedSweep has):
// on a broker that lets anyone publish, a retained fake value of an entry that never
// changes would stay "current" in every viewer, since the station publishes only changes.
// Every message published under the station is matched against what the station itself
// published there (its echo); what another client wrote on a topic the station owns is
// reported for the station to publish its own again, and what another client wrote on a
// topic it does not own is cleared. What was retained before the watch began is the
// sweep's: the watch takes live messages only.
#pragma once

#include "mqtt/mqttclient.h"
#include "mqtt/topicscheme.h"

#include <QHash>
#include <QObject>
#include <QTimer>

#include <functional>

namespace jumo {

class StationGuard : public QObject
{
    Q_OBJECT

public:
    using Owns = std::function<bool(const TopicScheme::Topic &)>;

    StationGuard(const MqttSettings &broker, const TopicScheme &scheme, const QString &station, Owns owns,
                 QObject *parent = nullptr);

    // started: the station's start time, as its status says it.
    void start(const QDateTime &started);
    void stop();
    bool isConnected() const { return m_client.isConnected(); }

    // The station publishes this retained payload on this topic now: its echo is no
    // stranger's. Called for every retained message the station sends (clears included).
    void expect(const QString &topic, const QByteArray &payload);

    quint64 restoredCount() const { return m_restored; }
    quint64 clearedCount() const { return m_cleared; }

signals:
    // Another client wrote on a topic the station owns: the station publishes its own again.
    void restoreRequested(const QString &topic);
    // Another client published an "online" status of this station: another publisher runs
    // under its name (one started with --take-over).
    void otherPublisherOnline();
    // A count changed (restored or cleared), for the station's status.
    void countsChanged();

private:
    struct Sent
    {
        size_t hash = 0;
        qint64 atMs = 0;
    };
    struct Watch
    {
        size_t latest = 0;      // the station's last payload
        size_t lastSeen = 0;    // the last payload the broker passed on
        QList<Sent> inFlight;   // published, echo not seen yet, oldest first
    };

    void onMessage(const QString &topic, const QByteArray &payload, bool retained);
    // Topics where a stranger's message came while the station's own was on its way:
    // once that echo is back or lost, the last one seen decides.
    void recheck();
    void restore(const QString &topic);
    void report(const QString &what, const QString &topic);

    MqttClient m_client;
    TopicScheme m_scheme;
    QString m_station;
    QString m_filter;
    Owns m_owns;
    QDateTime m_started;
    QHash<size_t, Watch> m_watches;   // by the topic's hash
    QHash<size_t, QString> m_suspects;
    QTimer m_recheck;
    quint64 m_restored = 0;
    quint64 m_cleared = 0;
    int m_said = 0;                   // messages logged one by one before they are only counted
};

} // namespace jumo
