// Before a station publishes anything: is a station of its name online at the broker now?
// Two publishers under one name overwrite each other's topics and clear each other's
// devices. The check reads the name's retained status and waits for its heartbeat, on a
// connection of its own with no will; it publishes nothing.
#pragma once

#include "mqtt/mqttclient.h"
#include "mqtt/topicscheme.h"

#include <QObject>
#include <QTimer>

namespace jumo {

class NameCheck : public QObject
{
    Q_OBJECT

public:
    // How long a station whose status says "online" has to send a heartbeat.
    static constexpr int heartbeatWaitMs = 3000;

    NameCheck(const MqttSettings &broker, const TopicScheme &scheme, const QString &station, QObject *parent = nullptr);

    void start();

signals:
    // online: a station of this name sends heartbeats. A broker that cannot be reached
    // cannot tell: the station starts (and keeps trying to connect).
    void finished(bool online);

private:
    void finish(bool online);

    MqttClient m_client;
    TopicScheme m_scheme;
    QString m_station;
    QTimer m_wait;
    bool m_statusOnline = false;
    bool m_done = false;
};

} // namespace jumo
