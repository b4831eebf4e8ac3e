// A mirror of one station (or of every station) from an MQTT broker, for viewers that
// have no Modbus access: stations, lines, devices and values as the station published
// them, values decoded again from their words through the family's register map. A device
// exists while its `info` topic does; values alone make none. What a station published as
// current counts as stale while the station is offline (its last will), silent (no
// heartbeat for 2 s), not yet caught up with, or the broker cannot be reached. Everything
// it takes from the broker is bounded (README, "What a viewer takes"). It publishes
// nothing but its own presence and the write probe of its LivenessLink.
#pragma once

#include "bus/bus.h"
#include "mqtt/livenesslink.h"
#include "mqtt/mqttclient.h"
#include "mqtt/topicscheme.h"
#include "mqtt/waitingmessages.h"

#include <QHash>
#include <QMap>
#include <QObject>
#include <QSet>

#include <algorithm>
#include <chrono>
#include <memory>

class QTimer;

namespace jumo {

class FamilyRegistry;

struct RemoteStationState
{
    QString name;
    bool statusKnown = false;
    StationStatusMessage status;   // as the station's own connection (LivenessLink) said last
    QDateTime lastHeartbeat;       // the station's time in its last heartbeat
    bool silent = false;           // no heartbeat within the silence limit
    // The main connection has brought this run's "online", and with it everything the
    // station published before it: until then its values are not taken as current.
    bool caughtUp = false;
    QDateTime lostSince;           // this viewer's time of its last contact, while not live
    bool writable = false;         // this viewer's probe came back: station data can be forged
    QStringList order;             // the station's devices, "LINE/FAMILY@ADDRESS"
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
    std::shared_ptr<const RegisterMap> map;
    DeviceCondition condition;
    QDateTime cycle;             // the station's time of the device's last poll cycle
};

class RemoteStation : public QObject
{
    Q_OBJECT

public:
    // What a viewer takes from a broker at most (README, "What a viewer takes"); beyond
    // it, messages are dropped and the drop is said once.
    static constexpr int maxStations = 32;
    static constexpr int maxLinesPerStation = 32;
    static constexpr int maxDevicesPerStation = 256;
    static constexpr int maxPayloadBytes = 16 * 1024;
    // Retained messages of devices whose info has not come yet (the broker sends retained
    // topics in its own order), per station.
    static constexpr int maxWaitingMessages = 4096;
    static constexpr qint64 maxWaitingBytes = 2 * 1024 * 1024;

    explicit RemoteStation(const FamilyRegistry &registry, QObject *parent = nullptr);
    ~RemoteStation() override;

    void setPrefix(const QString &prefix) { m_scheme = TopicScheme(prefix); }
    // The station to mirror; empty (the default): every station under the prefix, as many
    // as maxStations. The viewer's presence is published for a named station only.
    void setStation(const QString &station) { m_stationFilter = station; }
    void setSilenceLimit(int ms) { m_silenceLimitMs = ms; }
    int silenceLimitMs() const { return m_silenceLimitMs; }

    bool start(const MqttSettings &broker, QString *error);
    // Says "gone" and disconnects cleanly; takes no message after it.
    void stop();
    // A message as the broker delivers it, on the main connection or on the LivenessLink's
    // (tests and the fuzz target hand messages in here).
    void takeMessage(const QString &topic, const QByteArray &payload, bool retained, bool liveness = false);
    bool isConnected() const { return m_client.isConnected() && m_liveness.isConnected(); }
    MqttClient &client() { return m_client; }
    LivenessLink &liveness() { return m_liveness; }
    // The topic level of this viewer's presence: random, and not its client id.
    QString viewerId() const { return m_viewerId; }

    QStringList stations() const { return m_stations.keys(); }
    const RemoteStationState *station(const QString &name) const;
    // Online, heard within the silence limit, caught up and the broker connected: what it
    // published counts as it was published.
    bool isLive(const QString &station) const
    {
        const auto it = m_stations.find(station);
        return it != m_stations.end() && it->live;
    }
    // This viewer's user may publish into some station's tree (the probe came back).
    bool anyWritable() const
    {
        return std::any_of(m_stations.cbegin(), m_stations.cend(), [](const Station &s) { return s.state.writable; });
    }
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
    QStringList entryIds(DeviceId id) const { return m_entries.value(id).keys(); }
    // Messages dropped for a limit or as malformed, since the start.
    quint64 refusedCount() const { return m_refused; }
    // The machine's monotonic clock (ms since it started), the same for every mirror and
    // mirrored line in the process: a time taken here means the same there, and the age of
    // a value read long before this program started is still positive.
    qint64 clockMs() const { return monotonicMs(); }
    static qint64 monotonicMs()
    {
        using namespace std::chrono;
        return duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count();
    }

signals:
    void connectionChanged(bool connected, const QString &reason);
    void stationChanged(const QString &station);
    void lineStateChanged(const QString &station, const QString &line, jumo::LineState state);
    // The station cleared the line's topic.
    void lineRemoved(const QString &station, const QString &line);
    void orderChanged(const QString &station);
    void deviceAdded(jumo::DeviceId id);
    void deviceRemoved(jumo::DeviceId id);
    // Its identity (model, address) was published.
    void deviceChanged(jumo::DeviceId id);
    void entriesUpdated(jumo::DeviceId id, const QStringList &entryIds);
    void conditionChanged(jumo::DeviceId id, const jumo::DeviceCondition &condition);
    // The device's current values were read again at goodMs (monotonic clock) by the
    // station's last poll cycle, unchanged.
    void deviceRead(jumo::DeviceId id, qint64 goodMs);
    // Something under a station was not taken, with the reason (said once per topic level).
    void refused(const QString &what, const QString &reason);
    // This viewer's user may publish into the station's tree.
    void forgeryPossible(const QString &station);

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
        bool everHeartbeat = false;
        QDateTime lastContact;        // this viewer's time of the last heartbeat
        QDateTime caughtUpStarted;    // "started" of the last "online" on the main connection
        WaitingMessages waiting{maxWaitingMessages, maxWaitingBytes};   // by "line/family@address"
    };

    const Entry *entry(DeviceId id, const QString &entryId) const;
    void onConnectionChanged();
    void onMessage(const QString &topic, const QByteArray &payload, bool retained);
    void onStatus(const QString &station, const QByteArray &payload, bool caughtUp);
    void onHeartbeat(const QString &station, const QByteArray &payload);
    void onDeviceMessage(Station &station, const TopicScheme::Topic &topic, const QByteArray &payload, bool retained);
    void applyDeviceMessage(DeviceId id, TopicScheme::Kind kind, const QString &entry, const QByteArray &payload);
    // The station, made if there is room (a live station takes the place of one that was
    // never heard alive); null if not.
    Station *admit(const QString &name, bool alive);
    void forget(const QString &name);
    DeviceId addDevice(const QString &station, const QString &line, const QString &device,
                       const DeviceInfoMessage &info, std::shared_ptr<const RegisterMap> map);
    void removeDevice(DeviceId id);
    void setValue(DeviceId id, const QString &entryId, const ValueMessage &message);
    void applyValidity(Entry &entry, bool live) const;
    // A station's wall-clock time as this machine's monotonic clock.
    qint64 monotonicOf(const QDateTime &time) const;
    void refuse(const QString &what, const QString &reason);
    // Recomputes whether a station is live and, when that changed, every value of it.
    void refresh(const QString &station);

    const FamilyRegistry &m_registry;
    MqttClient m_client;
    LivenessLink m_liveness;
    TopicScheme m_scheme;
    QString m_stationFilter;
    QString m_viewerId;
    int m_silenceLimitMs = 2000;
    bool m_stopping = false;
    QMap<QString, Station> m_stations;
    QMap<DeviceId, RemoteDevice> m_devices;
    QHash<QString, DeviceId> m_deviceByKey;   // "station/line/family@address"
    QHash<DeviceId, QMap<QString, Entry>> m_entries;
    QSet<QString> m_refusedSaid;
    quint64 m_refused = 0;
};

} // namespace jumo
