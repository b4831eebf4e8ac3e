// A mirror of one station (or of every station) from an MQTT broker, for viewers that
// have no Modbus access: stations, lines, devices and values as the station published
// them, values decoded again from their words through the family's register map. What
// a station published as current counts as stale while the station is offline (its last
// will), silent (no heartbeat for 2 s) or the broker cannot be reached, and counts again
// once it is back. Its signals are those of a Bus, so models can sit on it. It publishes
// nothing but its own presence.
#pragma once

#include "bus/bus.h"
#include "mqtt/mqttclient.h"
#include "mqtt/topicscheme.h"

#include <QElapsedTimer>
#include <QHash>
#include <QMap>
#include <QObject>

#include <memory>

namespace jumo {

class FamilyRegistry;

struct RemoteStationState
{
    QString name;
    bool statusKnown = false;
    StationStatusMessage status;
    QDateTime lastHeartbeat;     // the station's time in its last heartbeat
    bool silent = false;         // no heartbeat within the silence limit
};

struct RemoteDevice
{
    DeviceId id = 0;
    QString station;
    QString line;
    QString name;                // "family@address"
    QString family;
    int address = 0;
    QString model;
    std::shared_ptr<const RegisterMap> map;   // null for a family this program does not know
    DeviceCondition condition;
};

class RemoteStation : public QObject
{
    Q_OBJECT

public:
    explicit RemoteStation(const FamilyRegistry &registry, QObject *parent = nullptr);
    ~RemoteStation() override;

    void setPrefix(const QString &prefix) { m_scheme = TopicScheme(prefix); }
    // The station to mirror; empty (the default): every station under the prefix. The
    // viewer's presence is published for a named station only (one last will per client).
    void setStation(const QString &station) { m_stationFilter = station; }
    void setSilenceLimit(int ms) { m_silenceLimitMs = ms; }
    int silenceLimitMs() const { return m_silenceLimitMs; }

    bool start(const MqttSettings &broker, QString *error);
    // Says "gone" and disconnects cleanly.
    void stop();
    bool isConnected() const { return m_client.isConnected(); }
    MqttClient &client() { return m_client; }

    QStringList stations() const { return m_stations.keys(); }
    const RemoteStationState *station(const QString &name) const;
    // Online, heard within the silence limit and the broker connected: what it published
    // counts as it was published.
    bool isLive(const QString &station) const;
    QStringList lines(const QString &station) const;
    const LineMessage *line(const QString &station, const QString &line) const;

    QList<DeviceId> devices() const { return m_devices.keys(); }
    const RemoteDevice *device(DeviceId id) const;
    std::optional<DeviceId> findDevice(const QString &station, const QString &line, const QString &name) const;
    std::shared_ptr<const RegisterMap> deviceMap(DeviceId id) const;
    QString deviceName(DeviceId id) const;
    DeviceCondition condition(DeviceId id) const;
    bool isOnline(DeviceId id) const { return condition(id).isOnline(); }
    // The entry's state as a viewer should take it (validity downgraded while the station
    // is not live); null if nothing was published for it.
    const EntryState *entryState(DeviceId id, const QString &entryId) const;
    // The entry as published (text, status, bits).
    const ValueMessage *published(DeviceId id, const QString &entryId) const;
    QStringList entryIds(DeviceId id) const;
    // The monotonic clock of EntryState times (goodMs, updatedMs).
    // The machine's monotonic clock (ms since it started), the same for every mirror and
    // mirrored line in the process: a time taken here means the same there, and the age of
    // a value read long before this program started is still positive.
    qint64 clockMs() const { return monotonicMs(); }
    static qint64 monotonicMs();

signals:
    void connectionChanged(bool connected, const QString &reason);
    void stationChanged(const QString &station);
    void lineStateChanged(const QString &station, const QString &line, jumo::LineState state);
    void deviceAdded(jumo::DeviceId id);
    void deviceRemoved(jumo::DeviceId id);
    // Its identity (model, address) was published.
    void deviceChanged(jumo::DeviceId id);
    void entriesUpdated(jumo::DeviceId id, const QStringList &entryIds);
    void conditionChanged(jumo::DeviceId id, const jumo::DeviceCondition &condition);

private:
    struct Entry
    {
        ValueMessage published;
        EntryState state;
    };
    struct Station
    {
        RemoteStationState state;
        QMap<QString, LineMessage> lines;
        QTimer *silence = nullptr;
        bool live = false;
    };

    void onConnected();
    void onMessage(const QString &topic, const QByteArray &payload);
    Station &stationNamed(const QString &name);
    DeviceId deviceFor(const QString &station, const QString &line, const QString &name);
    void removeDevice(DeviceId id);
    void setValue(DeviceId id, const QString &entryId, const ValueMessage &message);
    void applyValidity(Entry &entry, bool live) const;
    QString clientId() const;
    // Recomputes whether a station is live and, when that changed, every value of it.
    void refresh(const QString &station);

    const FamilyRegistry &m_registry;
    MqttClient m_client;
    TopicScheme m_scheme;
    QString m_stationFilter;
    int m_silenceLimitMs = 2000;
    QMap<QString, Station> m_stations;
    QMap<DeviceId, RemoteDevice> m_devices;
    QHash<QString, DeviceId> m_deviceByKey;   // "station/line/family@address"
    QHash<DeviceId, QMap<QString, Entry>> m_entries;
};

} // namespace jumo
