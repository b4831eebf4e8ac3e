// Clears what an earlier run of a station left retained under it and this run does not
// publish (a line or device no longer in the station, an entry no longer polled), so no
// viewer takes it for a current value of this station. It runs over a connection of its
// own: tens of thousands of leftover topics flood whoever subscribes to them, and the
// station's heartbeat and values must not wait behind that. Each pass connects,
// subscribes to the station's topics (QoS 0: see RemoteStation), clears every retained
// topic the station does not own (an empty retained message, QoS 0), and ends with the
// first message that is not retained (the station's heartbeat, an echo of a clear): the
// broker sends the retained ones first. A broker that drops messages to a slow client
// makes a pass miss some; passes follow until one finds nothing, at most maxPasses.
#pragma once

#include "mqtt/mqttclient.h"
#include "mqtt/topicscheme.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <functional>

namespace jumo {

class RetainedSweep : public QObject
{
    Q_OBJECT

public:
    static constexpr int maxPasses = 10;
    using Owns = std::function<bool(const TopicScheme::Topic &)>;

    RetainedSweep(const MqttSettings &broker, const TopicScheme &scheme, const QString &station, Owns owns,
                  QObject *parent = nullptr);

    // Sweeps (again, from the first pass). passMs: how long a pass may wait for the end
    // of the retained messages (a little more than the station's heartbeat interval).
    void start(int passMs);
    void stop();

signals:
    // cleared: empty retained messages sent; left: topics the last pass still found.
    void finished(int cleared, int left, int passes);

private:
    void beginPass();
    void onMessage(const QString &topic, const QByteArray &payload, bool retained);
    void endPass();
    // After a pass: the clears written out, then the connection closed.
    void drain();

    MqttClient m_client;
    TopicScheme m_scheme;
    QString m_station;
    QString m_filter;
    Owns m_owns;
    QTimer m_passEnd;
    QTimer m_drain;
    QElapsedTimer m_drainTime;
    bool m_running = false;
    bool m_inPass = false;
    int m_pass = 0;
    int m_found = 0;     // this pass
    int m_cleared = 0;   // all passes
    int m_failures = 0;  // connections lost or refused in a row
};

} // namespace jumo
