#include "mqtt/remotestation.h"

#include "protocol/familyregistry.h"
#include "protocol/valuecodec.h"

#include <QHostInfo>
#include <QLoggingCategory>
#include <QRegularExpression>
#include <QTimer>

#include <atomic>

Q_DECLARE_LOGGING_CATEGORY(lcMqtt)

namespace jumo {

namespace {

// Mirrored devices get ids of their own, far from those a Bus hands out, so a process
// with both never mixes them up.
std::atomic<DeviceId> nextRemoteId{1 << 24};

} // namespace

RemoteStation::RemoteStation(const FamilyRegistry &registry, QObject *parent)
    : QObject(parent), m_registry(registry)
{
    connect(&m_client, &MqttClient::connected, this, &RemoteStation::onConnected);
    connect(&m_client, &MqttClient::disconnected, this, [this](const QString &reason) {
        emit connectionChanged(false, reason);
        for (const QString &name : m_stations.keys())
            refresh(name);
    });
    connect(&m_client, &MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload, bool) { onMessage(topic, payload); });
}

qint64 RemoteStation::monotonicMs()
{
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
            .count();
}

RemoteStation::~RemoteStation() = default;

bool RemoteStation::start(const MqttSettings &broker, QString *error)
{
    m_client.setSettings(broker);
    if (!m_stationFilter.isEmpty())
        m_client.setWill(m_scheme.viewer(m_stationFilter, clientId()), TopicScheme::viewerGonePayload());
    // QoS 0: a broker holds at most max_queued_messages (Mosquitto: 1000) QoS 1 messages
    // for a client beyond the 20 in flight and drops the rest, which would cut a station's
    // retained state of some 100 topics per device short on subscribing. Over one TCP
    // connection QoS 1 adds nothing else for a mirror that starts clean on every connect.
    m_client.subscribe(m_scheme.stationFilter(m_stationFilter), 0);
    if (!m_client.connectToBroker()) {
        if (error)
            *error = m_client.lastError();
        return false;
    }
    return true;
}

void RemoteStation::stop()
{
    if (m_client.isConnected() && !m_stationFilter.isEmpty())
        m_client.publish(m_scheme.viewer(m_stationFilter, clientId()), TopicScheme::viewerGonePayload(), true);
    m_client.disconnectFromBroker();
}

QString RemoteStation::clientId() const
{
    return m_client.clientId();
}

void RemoteStation::onConnected()
{
    if (!m_stationFilter.isEmpty())
        m_client.publish(m_scheme.viewer(m_stationFilter, clientId()), TopicScheme::viewerPayload(QHostInfo::localHostName()),
                         true);
    emit connectionChanged(true, QString());
    for (const QString &name : m_stations.keys())
        refresh(name);
}

const RemoteStationState *RemoteStation::station(const QString &name) const
{
    auto it = m_stations.find(name);
    return it == m_stations.end() ? nullptr : &it->state;
}

bool RemoteStation::isLive(const QString &name) const
{
    auto it = m_stations.find(name);
    return it != m_stations.end() && it->live;
}

QStringList RemoteStation::lines(const QString &station) const
{
    auto it = m_stations.find(station);
    return it == m_stations.end() ? QStringList() : it->lines.keys();
}

const LineMessage *RemoteStation::line(const QString &station, const QString &line) const
{
    auto it = m_stations.find(station);
    if (it == m_stations.end())
        return nullptr;
    auto l = it->lines.find(line);
    return l == it->lines.end() ? nullptr : &*l;
}

const RemoteDevice *RemoteStation::device(DeviceId id) const
{
    auto it = m_devices.find(id);
    return it == m_devices.end() ? nullptr : &*it;
}

std::optional<DeviceId> RemoteStation::findDevice(const QString &station, const QString &line, const QString &name) const
{
    auto it = m_deviceByKey.find(station + QLatin1Char('/') + line + QLatin1Char('/') + name);
    if (it == m_deviceByKey.end())
        return std::nullopt;
    return *it;
}

std::shared_ptr<const RegisterMap> RemoteStation::deviceMap(DeviceId id) const
{
    const RemoteDevice *d = device(id);
    return d ? d->map : nullptr;
}

QString RemoteStation::deviceName(DeviceId id) const
{
    const RemoteDevice *d = device(id);
    return d ? d->name : QString();
}

DeviceCondition RemoteStation::condition(DeviceId id) const
{
    const RemoteDevice *d = device(id);
    return d ? d->condition : DeviceCondition();
}

const EntryState *RemoteStation::entryState(DeviceId id, const QString &entryId) const
{
    auto it = m_entries.find(id);
    if (it == m_entries.end())
        return nullptr;
    auto e = it->find(entryId);
    return e == it->end() ? nullptr : &e->state;
}

const ValueMessage *RemoteStation::published(DeviceId id, const QString &entryId) const
{
    auto it = m_entries.find(id);
    if (it == m_entries.end())
        return nullptr;
    auto e = it->find(entryId);
    return e == it->end() ? nullptr : &e->published;
}

QStringList RemoteStation::entryIds(DeviceId id) const
{
    return m_entries.value(id).keys();
}

RemoteStation::Station &RemoteStation::stationNamed(const QString &name)
{
    auto it = m_stations.find(name);
    if (it != m_stations.end())
        return *it;
    Station &s = m_stations[name];
    s.state.name = name;
    // Heard of just now: it has the silence limit to send its first heartbeat.
    s.silence = new QTimer(this);
    s.silence->setSingleShot(true);
    connect(s.silence, &QTimer::timeout, this, [this, name] {
        auto st = m_stations.find(name);
        if (st == m_stations.end())
            return;
        if (!st->state.silent)
            qCInfo(lcMqtt).noquote() << "station" << name << "silent: no heartbeat for" << m_silenceLimitMs << "ms";
        st->state.silent = true;
        refresh(name);
    });
    s.silence->start(m_silenceLimitMs);
    return s;
}

DeviceId RemoteStation::deviceFor(const QString &station, const QString &line, const QString &name)
{
    const QString key = station + QLatin1Char('/') + line + QLatin1Char('/') + name;
    if (auto it = m_deviceByKey.find(key); it != m_deviceByKey.end())
        return *it;
    stationNamed(station);
    RemoteDevice d;
    d.id = nextRemoteId++;
    d.station = station;
    d.line = line;
    d.name = name;
    d.family = name.section(QLatin1Char('@'), 0, 0);
    d.address = name.section(QLatin1Char('@'), 1).toInt();
    d.map = m_registry.family(d.family);
    m_devices.insert(d.id, d);
    m_deviceByKey.insert(key, d.id);
    emit deviceAdded(d.id);
    return d.id;
}

void RemoteStation::removeDevice(DeviceId id)
{
    auto it = m_devices.find(id);
    if (it == m_devices.end())
        return;
    m_deviceByKey.remove(it->station + QLatin1Char('/') + it->line + QLatin1Char('/') + it->name);
    m_devices.erase(it);
    m_entries.remove(id);
    emit deviceRemoved(id);
}

void RemoteStation::onMessage(const QString &topicText, const QByteArray &payload)
{
    const std::optional<TopicScheme::Topic> topic = m_scheme.parse(topicText);
    if (!topic)
        return;
    using Kind = TopicScheme::Kind;
    const bool cleared = payload.isEmpty();
    // A device level is FAMILY@ADDRESS: anything else names no device of a station.
    static const QRegularExpression deviceName(
            QRegularExpression::anchoredPattern(QStringLiteral("[a-z][a-z0-9_]*@[0-9]{1,3}")));
    if (!topic->device.isEmpty() && !deviceName.match(topic->device).hasMatch()) {
        qCDebug(lcMqtt).noquote() << "ignored" << topicText << "(no device)";
        return;
    }
    switch (topic->kind) {
    case Kind::Viewer:
        return;
    case Kind::Status: {
        Station &s = stationNamed(topic->station);
        if (cleared) {
            s.state.statusKnown = false;
        } else if (const auto status = TopicScheme::parseStatus(payload)) {
            s.state.statusKnown = true;
            s.state.status = *status;
            if (!status->online)
                qCInfo(lcMqtt).noquote() << "station" << topic->station << "offline:" << status->reason;
        } else {
            qCWarning(lcMqtt).noquote() << "ignored a malformed status on" << topicText;
            return;
        }
        emit stationChanged(topic->station);
        refresh(topic->station);
        return;
    }
    case Kind::Heartbeat: {
        // Only a heartbeat is a sign of life: not whatever someone else sends on its topic.
        const auto time = TopicScheme::parseHeartbeat(payload);
        if (!time)
            return;
        Station &s = stationNamed(topic->station);
        s.state.lastHeartbeat = *time;
        s.state.silent = false;
        s.silence->start(m_silenceLimitMs);
        refresh(topic->station);
        return;
    }
    case Kind::Line: {
        Station &s = stationNamed(topic->station);
        if (cleared) {
            s.lines.remove(topic->line);
            emit lineStateChanged(topic->station, topic->line, LineState::Disconnected);
            return;
        }
        const auto line = TopicScheme::parseLine(payload);
        if (!line)
            return;
        s.lines[topic->line] = *line;
        emit lineStateChanged(topic->station, topic->line, line->state);
        return;
    }
    case Kind::DeviceInfo: {
        if (cleared) {
            if (const auto id = findDevice(topic->station, topic->line, topic->device))
                removeDevice(*id);
            return;
        }
        const auto info = TopicScheme::parseDeviceInfo(payload);
        if (!info)
            return;
        const DeviceId id = deviceFor(topic->station, topic->line, topic->device);
        RemoteDevice &d = m_devices[id];
        d.model = info->model;
        d.address = info->address;
        emit deviceChanged(id);
        return;
    }
    case Kind::DeviceCondition: {
        if (cleared)
            return;
        const auto condition = TopicScheme::parseCondition(payload);
        if (!condition)
            return;
        const DeviceId id = deviceFor(topic->station, topic->line, topic->device);
        m_devices[id].condition = *condition;
        emit conditionChanged(id, *condition);
        return;
    }
    case Kind::Value: {
        if (cleared) {
            const auto id = findDevice(topic->station, topic->line, topic->device);
            if (id && m_entries[*id].remove(topic->entry))
                emit entriesUpdated(*id, {topic->entry});
            return;
        }
        // Malformed: ignored before it makes a device appear.
        const auto message = TopicScheme::parseValue(payload);
        if (!message) {
            qCWarning(lcMqtt).noquote() << "ignored a malformed value on" << topicText;
            return;
        }
        setValue(deviceFor(topic->station, topic->line, topic->device), topic->entry, *message);
        return;
    }
    }
}

void RemoteStation::setValue(DeviceId id, const QString &entryId, const ValueMessage &message)
{
    const RemoteDevice &d = m_devices[id];
    Entry &e = m_entries[id][entryId];
    e.published = message;
    EntryState s;
    const RegisterEntry *entry = d.map ? d.map->entry(entryId) : nullptr;
    if (entry && message.words.size() == entry->wordCount()) {
        s.value = ValueCodec::decode(*entry, *d.map, message.words);
    } else {
        // A family this program has no map of: the value as the station worded it.
        s.value.value = message.value.toVariant();
        s.value.display = message.text;
        s.value.status = message.value.isNull() ? ValueStatus::Invalid : ValueStatus::Ok;
    }
    s.words = message.words;
    s.error = message.error;
    s.exceptionCode = message.exception;
    const qint64 now = clockMs();
    s.updatedMs = now;
    if (message.read.isValid())
        s.goodMs = std::max<qint64>(0, now - std::max<qint64>(0, message.read.msecsTo(QDateTime::currentDateTimeUtc())));
    e.state = s;
    applyValidity(e, isLive(d.station));
    emit entriesUpdated(id, {entryId});
}

void RemoteStation::applyValidity(Entry &entry, bool live) const
{
    entry.state.validity = entry.published.validity;
    if (!live && entry.state.validity == Validity::Current)
        entry.state.validity = Validity::Stale;
}

void RemoteStation::refresh(const QString &name)
{
    auto it = m_stations.find(name);
    if (it == m_stations.end())
        return;
    const bool live = m_client.isConnected() && it->state.statusKnown && it->state.status.online && !it->state.silent;
    if (live == it->live)
        return;
    it->live = live;
    for (auto d = m_devices.cbegin(); d != m_devices.cend(); ++d) {
        if (d->station != name)
            continue;
        QMap<QString, Entry> &entries = m_entries[d.key()];
        QStringList changed;
        for (auto e = entries.begin(); e != entries.end(); ++e) {
            const Validity before = e->state.validity;
            applyValidity(*e, live);
            if (e->state.validity != before)
                changed << e.key();
        }
        if (!changed.isEmpty())
            emit entriesUpdated(d.key(), changed);
    }
    emit stationChanged(name);
}

} // namespace jumo
