#include "mqtt/remotestation.h"

#include "bus/stationconfig.h"
#include "protocol/familyregistry.h"
#include "protocol/valuecodec.h"

#include <QHostInfo>
#include <QLoggingCategory>
#include <QTimer>

#include <atomic>
#include <chrono>

Q_DECLARE_LOGGING_CATEGORY(lcMqtt)

namespace jumo {

namespace {

// Mirrored devices get ids of their own, far from those a Bus hands out, so a process
// with both never mixes them up.
std::atomic<DeviceId> nextRemoteId{1 << 24};

// Refusals said in words: one per topic level, up to this many (a flood is counted only).
constexpr int maxRefusalsSaid = 1000;

QString keyOf(const QString &station, const QString &line, const QString &device)
{
    return station + QLatin1Char('/') + line + QLatin1Char('/') + device;
}

} // namespace

RemoteStation::RemoteStation(const FamilyRegistry &registry, QObject *parent)
    : QObject(parent), m_registry(registry), m_client(this), m_liveness(this)
{
    m_client.setMaximumPayload(maxPayloadBytes);
    connect(&m_client, &MqttClient::connected, this, [this] {
        if (!m_stationFilter.isEmpty())
            m_client.publish(m_scheme.viewer(m_stationFilter, m_viewerId),
                             TopicScheme::viewerPayload(QHostInfo::localHostName()), true);
        onConnectionChanged();
    });
    connect(&m_client, &MqttClient::disconnected, this, &RemoteStation::onConnectionChanged);
    connect(&m_client, &MqttClient::messageReceived, this, &RemoteStation::onMessage);
    connect(&m_client, &MqttClient::oversizeMessage, this, [this](const QString &topic, qint64 bytes) {
        refuse(topic, tr("a message of %1 bytes, over the limit of %2").arg(bytes).arg(maxPayloadBytes));
    });
    connect(&m_liveness, &LivenessLink::connectionChanged, this, [this](bool connected) {
        if (connected) {
            for (const QString &name : m_stations.keys())
                m_liveness.probe(name);
        }
        onConnectionChanged();
    });
    connect(&m_liveness, &LivenessLink::statusReceived, this,
            [this](const QString &station, const QByteArray &payload) { onStatus(station, payload, false); });
    connect(&m_liveness, &LivenessLink::heartbeatReceived, this, &RemoteStation::onHeartbeat);
    connect(&m_liveness, &LivenessLink::writable, this, [this](const QString &name) {
        auto it = m_stations.find(name);
        if (it == m_stations.end() || it->state.writable)
            return;
        it->state.writable = true;
        emit forgeryPossible(name);
        emit stationChanged(name);
    });
}

RemoteStation::~RemoteStation() = default;

bool RemoteStation::start(const MqttSettings &broker, QString *error)
{
    m_stopping = false;
    m_viewerId = MqttClient::randomId(QStringLiteral("viewer"));
    m_client.setSettings(broker);
    if (!m_stationFilter.isEmpty()) {
        m_client.setWill(m_scheme.viewer(m_stationFilter, m_viewerId), TopicScheme::viewerGonePayload());
        // QoS 0: a broker holds at most max_queued_messages (Mosquitto: 1000) QoS 1
        // messages for a client beyond the 20 in flight and drops the rest, which would cut
        // a station's retained state of some 100 topics per device short on subscribing.
        m_client.subscribe(m_scheme.stationFilter(m_stationFilter), 0);
    }
    // Every station: each one's tree is subscribed to once the LivenessLink has heard of
    // it and there is room for it.
    if (!m_client.connectToBroker() || !m_liveness.start(broker, m_scheme, m_stationFilter, error)) {
        if (error && error->isEmpty())
            *error = m_client.lastError();
        if (error && error->isEmpty())
            *error = m_liveness.client().lastError();
        return false;
    }
    return true;
}

void RemoteStation::stop()
{
    m_stopping = true;
    if (m_client.isConnected() && !m_stationFilter.isEmpty())
        m_client.publish(m_scheme.viewer(m_stationFilter, m_viewerId), TopicScheme::viewerGonePayload(), true);
    m_client.disconnectFromBroker();
    m_liveness.stop();
}

void RemoteStation::takeMessage(const QString &topic, const QByteArray &payload, bool retained, bool liveness)
{
    if (!liveness) {
        onMessage(topic, payload, retained);
        return;
    }
    const std::optional<TopicScheme::Topic> parsed = m_scheme.parse(topic);
    if (parsed && parsed->kind == TopicScheme::Kind::Status)
        onStatus(parsed->station, payload, false);
    else if (parsed && parsed->kind == TopicScheme::Kind::Heartbeat)
        onHeartbeat(parsed->station, payload);
}

void RemoteStation::onConnectionChanged()
{
    // Stopping: its owner may be on its way out, nobody is to hear of it.
    if (m_stopping)
        return;
    const QString reason = !m_client.isConnected() ? m_client.lastError() : m_liveness.client().lastError();
    emit connectionChanged(isConnected(), isConnected() ? QString() : reason);
    for (const QString &name : m_stations.keys())
        refresh(name);
}

const RemoteStationState *RemoteStation::station(const QString &name) const
{
    auto it = m_stations.find(name);
    return it == m_stations.end() ? nullptr : &it->state;
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
    auto it = m_deviceByKey.find(keyOf(station, line, name));
    if (it == m_deviceByKey.end())
        return std::nullopt;
    return *it;
}

std::shared_ptr<const RegisterMap> RemoteStation::deviceMap(DeviceId id) const
{
    return device(id) ? device(id)->map : nullptr;
}

QString RemoteStation::deviceName(DeviceId id) const
{
    return device(id) ? device(id)->name : QString();
}

DeviceCondition RemoteStation::condition(DeviceId id) const
{
    return device(id) ? device(id)->condition : DeviceCondition();
}

const RemoteStation::Entry *RemoteStation::entry(DeviceId id, const QString &entryId) const
{
    auto it = m_entries.find(id);
    auto e = it == m_entries.end() ? QMap<QString, Entry>::const_iterator() : it->find(entryId);
    return it == m_entries.end() || e == it->end() ? nullptr : &*e;
}

const EntryState *RemoteStation::entryState(DeviceId id, const QString &entryId) const
{
    return entry(id, entryId) ? &entry(id, entryId)->state : nullptr;
}

const ValueMessage *RemoteStation::published(DeviceId id, const QString &entryId) const
{
    return entry(id, entryId) ? &entry(id, entryId)->published : nullptr;
}

void RemoteStation::refuse(const QString &what, const QString &reason)
{
    ++m_refused;
    if (m_refusedSaid.size() >= maxRefusalsSaid || m_refusedSaid.contains(what))
        return;
    m_refusedSaid.insert(what);
    qCWarning(lcMqtt).noquote() << "not taken:" << what << "-" << reason;
    emit refused(what, reason);
}

RemoteStation::Station *RemoteStation::admit(const QString &name, bool alive)
{
    if (auto it = m_stations.find(name); it != m_stations.end())
        return &*it;
    if (!m_stationFilter.isEmpty() && name != m_stationFilter)
        return nullptr;
    if (m_stations.size() >= maxStations) {
        // A station heard alive takes the place of one that never was: junk left under a
        // prefix cannot keep a working station out.
        auto never = std::find_if(m_stations.cbegin(), m_stations.cend(),
                                  [](const Station &s) { return !s.everHeartbeat; });
        if (!alive || never == m_stations.cend()) {
            refuse(m_scheme.status(name), tr("more than %1 stations publish under %2/: use --remote-station NAME")
                                                  .arg(maxStations)
                                                  .arg(m_scheme.prefix()));
            return nullptr;
        }
        forget(never.key());
    }
    Station &s = m_stations[name];
    s.state.name = name;
    s.state.lostSince = QDateTime::currentDateTime();
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
    if (m_stationFilter.isEmpty())
        m_client.subscribe(m_scheme.stationFilter(name), 0);
    m_liveness.probe(name);
    return &s;
}

void RemoteStation::forget(const QString &name)
{
    auto it = m_stations.find(name);
    if (it == m_stations.end())
        return;
    if (m_stationFilter.isEmpty())
        m_client.unsubscribe(m_scheme.stationFilter(name));
    QList<DeviceId> ids;
    for (auto d = m_devices.cbegin(); d != m_devices.cend(); ++d) {
        if (d->station == name)
            ids << d.key();
    }
    for (DeviceId id : std::as_const(ids))
        removeDevice(id);
    const QStringList lines = it->lines.keys();
    delete it->silence;
    m_stations.erase(it);
    for (const QString &line : lines)
        emit lineRemoved(name, line);
    emit stationChanged(name);
}

void RemoteStation::onStatus(const QString &name, const QByteArray &payload, bool caughtUp)
{
    if (m_stopping)
        return;
    std::optional<StationStatusMessage> status;
    if (!payload.isEmpty()) {
        status = TopicScheme::parseStatus(payload);
        if (!status) {
            refuse(m_scheme.status(name), tr("not a station status"));
            return;
        }
    }
    Station *s = admit(name, false);
    if (!s)
        return;
    if (caughtUp) {
        // In order with everything the station published before it, on the main connection.
        if (status && status->online)
            s->caughtUpStarted = status->started;
    } else if (status) {
        // Status and heartbeat are taken from the LivenessLink alone: two connections do
        // not keep each other's order.
        const bool newRun = status->online
                && !(s->state.statusKnown && s->state.status.online && s->state.status.started == status->started);
        s->state.statusKnown = true;
        s->state.status = *status;
        if (newRun) {
            // A station that has just started has the silence limit to send its first
            // heartbeat, as one heard of for the first time: the last run's heartbeat does
            // not make it silent meanwhile (a false loss and return in every viewer at each
            // restart). The same run's status again (retained, on a reconnect) is no sign
            // of life: a frozen station stays silent.
            s->state.silent = false;
            s->silence->start(m_silenceLimitMs);
        }
        if (!status->online)
            qCInfo(lcMqtt).noquote() << "station" << name << "offline:" << status->reason;
    } else {
        s->state.statusKnown = false;
    }
    emit stationChanged(name);
    refresh(name);
}

void RemoteStation::onHeartbeat(const QString &name, const QByteArray &payload)
{
    // Only a heartbeat is a sign of life: not whatever someone else sends on its topic.
    if (m_stopping || !TopicScheme::parseHeartbeat(payload))
        return;
    Station *s = admit(name, true);
    if (!s)
        return;
    s->state.lastHeartbeat = *TopicScheme::parseHeartbeat(payload);
    s->lastContact = QDateTime::currentDateTime();
    s->everHeartbeat = true;
    s->state.silent = false;
    s->silence->start(m_silenceLimitMs);
    refresh(name);
}

void RemoteStation::onMessage(const QString &topicText, const QByteArray &payload, bool retained)
{
    if (m_stopping)
        return;
    const std::optional<TopicScheme::Topic> topic = m_scheme.parse(topicText);
    if (!topic)
        return;
    using Kind = TopicScheme::Kind;
    switch (topic->kind) {
    case Kind::Viewer:
    case Kind::Probe:
        return;
    case Kind::Status:
        onStatus(topic->station, payload, true);
        return;
    case Kind::Heartbeat:
        onHeartbeat(topic->station, payload);
        return;
    default:
        break;
    }
    // Every station: only the trees of stations admitted are subscribed to.
    Station *s = m_stationFilter.isEmpty() ? (m_stations.contains(topic->station) ? &m_stations[topic->station] : nullptr)
                                           : admit(topic->station, false);
    if (!s)
        return;
    const bool cleared = payload.isEmpty();
    switch (topic->kind) {
    case Kind::Order: {
        if (cleared) {
            s->state.order.clear();
        } else if (const auto order = TopicScheme::parseOrder(payload, maxDevicesPerStation)) {
            s->state.order = *order;
        } else {
            refuse(topicText, tr("not a device order"));
            return;
        }
        emit orderChanged(topic->station);
        return;
    }
    case Kind::Line: {
        if (cleared) {
            if (s->lines.remove(topic->line))
                emit lineRemoved(topic->station, topic->line);
            return;
        }
        const auto line = TopicScheme::parseLine(payload);
        if (!line) {
            refuse(topicText, tr("not a line state"));
            return;
        }
        if (!s->lines.contains(topic->line) && s->lines.size() >= maxLinesPerStation) {
            refuse(topicText, tr("more than %1 lines in one station").arg(maxLinesPerStation));
            return;
        }
        s->lines[topic->line] = *line;
        emit lineStateChanged(topic->station, topic->line, line->state);
        return;
    }
    default:
        onDeviceMessage(*s, *topic, payload, retained);
        return;
    }
}

void RemoteStation::onDeviceMessage(Station &s, const TopicScheme::Topic &topic, const QByteArray &payload,
                                    bool retained)
{
    using Kind = TopicScheme::Kind;
    const QString what = keyOf(topic.station, topic.line, topic.device);
    QString error;
    const std::optional<DeviceSpec> spec = DeviceSpec::parse(topic.device, m_registry, &error);
    if (!spec) {
        refuse(what, error);
        return;
    }
    if (const auto known = m_deviceByKey.find(what); known != m_deviceByKey.end()) {
        applyDeviceMessage(*known, topic.kind, topic.entry, payload);
        return;
    }
    const QString waitingKey = topic.line + QLatin1Char('/') + topic.device;
    if (topic.kind == Kind::DeviceInfo) {
        if (payload.isEmpty()) {
            s.waiting.take(waitingKey);
            return;
        }
        const std::optional<DeviceInfoMessage> info = TopicScheme::parseDeviceInfo(payload);
        if (!info || info->family != spec->family || info->address != spec->address || info->line != topic.line) {
            refuse(what, tr("its info does not name this device"));
            return;
        }
        const auto onStation = std::count_if(m_devices.cbegin(), m_devices.cend(),
                                             [&](const RemoteDevice &d) { return d.station == topic.station; });
        if (onStation >= maxDevicesPerStation) {
            refuse(what, tr("more than %1 devices in one station").arg(maxDevicesPerStation));
            return;
        }
        const DeviceId id = addDevice(topic.station, topic.line, topic.device, *info, m_registry.family(spec->family));
        for (const WaitingMessages::Message &w : s.waiting.take(waitingKey)) {
            if (m_devices.contains(id))
                applyDeviceMessage(id, w.kind, w.entry, w.payload);
        }
        return;
    }
    // A value or condition of a device whose info has not come (yet): kept while it may
    // still come in the broker's retained burst, within bounds; live ones make nothing.
    if (retained && !s.waiting.keep(waitingKey, topic.kind, topic.entry, payload))
        refuse(what, tr("no info for this device, and too much waiting for one"));
}

DeviceId RemoteStation::addDevice(const QString &station, const QString &line, const QString &name,
                                  const DeviceInfoMessage &info, std::shared_ptr<const RegisterMap> map)
{
    RemoteDevice d;
    d.id = nextRemoteId++;
    d.station = station;
    d.line = line;
    d.name = name;
    d.family = info.family;
    d.address = info.address;
    d.model = info.model;
    d.map = std::move(map);
    m_devices.insert(d.id, d);
    m_deviceByKey.insert(keyOf(station, line, name), d.id);
    emit deviceAdded(d.id);
    return d.id;
}

void RemoteStation::applyDeviceMessage(DeviceId id, TopicScheme::Kind kind, const QString &entryId,
                                       const QByteArray &payload)
{
    using Kind = TopicScheme::Kind;
    RemoteDevice &d = m_devices[id];
    const QString what = keyOf(d.station, d.line, d.name);
    switch (kind) {
    case Kind::DeviceInfo: {
        if (payload.isEmpty()) {
            removeDevice(id);
            return;
        }
        const auto info = TopicScheme::parseDeviceInfo(payload);
        if (!info || info->family != d.family || info->address != d.address || info->line != d.line) {
            refuse(what, tr("its info does not name this device"));
            return;
        }
        d.model = info->model;
        emit deviceChanged(id);
        return;
    }
    case Kind::DeviceCondition: {
        if (payload.isEmpty())
            return;
        const auto message = TopicScheme::parseCondition(payload);
        if (!message) {
            refuse(what + QStringLiteral("/condition"), tr("not a device condition"));
            return;
        }
        const bool changed = message->condition.state != d.condition.state
                || message->condition.since != d.condition.since || message->condition.detail != d.condition.detail;
        d.condition = message->condition;
        if (message->cycle.isValid() && (!d.cycle.isValid() || message->cycle > d.cycle)) {
            // Its last cycle read every value again that it says is current.
            d.cycle = message->cycle;
            const qint64 goodMs = monotonicOf(d.cycle);
            for (Entry &e : m_entries[id]) {
                if (e.published.validity == Validity::Current && e.state.goodMs < goodMs)
                    e.state.goodMs = goodMs;
            }
            emit deviceRead(id, goodMs);
        }
        if (changed)
            emit conditionChanged(id, d.condition);
        return;
    }
    case Kind::Value: {
        if (payload.isEmpty()) {
            if (m_entries[id].remove(entryId))
                emit entriesUpdated(id, {entryId});
            return;
        }
        const RegisterEntry *entry = d.map->entry(entryId);
        if (!entry || !entry->isReadable()) {
            refuse(what + QStringLiteral("/values/") + entryId.left(64), tr("no entry of %1").arg(d.family));
            return;
        }
        const auto message = TopicScheme::parseValue(payload);
        if (!message) {
            refuse(what + QStringLiteral("/values/") + entryId, tr("not a value (or its validity and status disagree)"));
            return;
        }
        setValue(id, entryId, *message);
        return;
    }
    default:
        return;
    }
}

void RemoteStation::removeDevice(DeviceId id)
{
    auto it = m_devices.find(id);
    if (it == m_devices.end())
        return;
    m_deviceByKey.remove(keyOf(it->station, it->line, it->name));
    m_devices.erase(it);
    m_entries.remove(id);
    emit deviceRemoved(id);
}

qint64 RemoteStation::monotonicOf(const QDateTime &time) const
{
    return std::max<qint64>(0, clockMs() - std::max<qint64>(0, time.msecsTo(QDateTime::currentDateTimeUtc())));
}

void RemoteStation::setValue(DeviceId id, const QString &entryId, const ValueMessage &message)
{
    const RemoteDevice &d = m_devices[id];
    Entry &e = m_entries[id][entryId];
    e.published = message;
    EntryState s;
    const RegisterEntry *entry = d.map->entry(entryId);
    if (entry && message.words.size() == entry->wordCount()) {
        s.value = ValueCodec::decode(*entry, *d.map, message.words);
    } else {
        // Words that do not fit the map: the value as the station worded it.
        s.value.value = message.value.toVariant();
        s.value.display = message.text;
        s.value.status = message.value.isNull() ? ValueStatus::Invalid : ValueStatus::Ok;
    }
    s.words = message.words;
    s.error = message.error;
    s.exceptionCode = message.exception;
    s.updatedMs = clockMs();
    // A current value was read again by every cycle since the change that published it.
    QDateTime read = message.read;
    if (read.isValid() && message.validity == Validity::Current && d.cycle.isValid() && d.cycle > read)
        read = d.cycle;
    if (read.isValid())
        s.goodMs = monotonicOf(read);
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
    RemoteStationState &state = it->state;
    const bool caughtUp = state.statusKnown && state.status.online && it->caughtUpStarted.isValid()
            && it->caughtUpStarted == state.status.started;
    const bool live = isConnected() && state.statusKnown && state.status.online && !state.silent && caughtUp;
    const bool caughtUpChanged = caughtUp != state.caughtUp;
    state.caughtUp = caughtUp;
    if (live == it->live) {
        if (caughtUpChanged)
            emit stationChanged(name);
        return;
    }
    it->live = live;
    // The last sign of life this viewer had, not the station's start or its last change.
    state.lostSince = live ? QDateTime() : it->lastContact.isValid() ? it->lastContact : QDateTime::currentDateTime();
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
