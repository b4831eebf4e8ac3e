// A viewer's second connection to the broker: the stations' status and heartbeat only,
// so they arrive however much is queued behind a flood on the main connection. It also
// runs the write probe: one message, never retained, on a topic of the station's tree that
// stations and viewers ignore; if it comes back, this viewer's user may publish station
// data, and so may anyone with the same access: values and liveness can be forged.
#pragma once

#include "mqtt/mqttclient.h"
#include "mqtt/topicscheme.h"

#include <QHash>
#include <QObject>
#include <QSet>

namespace jumo {

class LivenessLink : public QObject
{
    Q_OBJECT

public:
    explicit LivenessLink(QObject *parent = nullptr);

    // station empty: every station under the prefix.
    bool start(const MqttSettings &broker, const TopicScheme &scheme, const QString &station, QString *error);
    void stop();
    bool isConnected() const { return m_client.isConnected(); }
    MqttClient &client() { return m_client; }

    // Once per station and connection; writable() follows if the broker passes the probe
    // on. A broker that refuses it (an ACL) drops it without a word: then nothing follows,
    // and nothing is left behind either way.
    void probe(const QString &station);

signals:
    void connectionChanged(bool connected);
    void statusReceived(const QString &station, const QByteArray &payload);
    void heartbeatReceived(const QString &station, const QByteArray &payload);
    void writable(const QString &station);

private:
    void onMessage(const QString &topic, const QByteArray &payload);

    MqttClient m_client;
    TopicScheme m_scheme;
    QHash<QString, QString> m_probes;   // probe topic -> station
    QSet<QString> m_probed;             // stations probed on this connection
};

} // namespace jumo
