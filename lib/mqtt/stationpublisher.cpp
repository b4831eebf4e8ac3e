#include "mqtt/stationpublisher.h"

#include "bus/bus.h"
#include "jumoversion.h"
#include "protocol/valueformat.h"

#include <QCoreApplication>
#include <QLocale>
#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcMqtt)

namespace jumo {

StationPublisher::StationPublisher(const MqttSettings &broker, const QString &prefix, const QString &station,
                                   QObject *parent)
    : QObject(parent), m_scheme(prefix), m_station(station),
      m_sweep(broker, m_scheme, station, [this](const TopicScheme::Topic &topic) { return owns(topic); }),
      m_guard(broker, m_scheme, station, [this](const TopicScheme::Topic &topic) { return owns(topic); })
{
    m_client.setSettings(broker);
    m_uptime.start();
    m_heartbeat.setInterval(1000);
    connect(&m_heartbeat, &QTimer::timeout, this, [this] {
        const QByteArray payload = TopicScheme::heartbeatPayload(QDateTime::currentDateTimeUtc());
        if (!m_client.isConnected())
            return;
        m_sentHeartbeats.insert(payload);
        m_sentOrder.enqueue(payload);
        if (m_sentOrder.size() > 1000)
            m_sentHeartbeats.remove(m_sentOrder.dequeue());
        publish(m_scheme.heartbeat(m_station), payload, false);
    });
    // Two publishers given one station name (a copied unit file, a forgotten test run):
    // nothing in MQTT stops them, and viewers see a mix of both.
    connect(&m_client, &MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload, bool retained) {
                if (retained || m_rivalSaid || topic != m_scheme.heartbeat(m_station)
                    || m_sentHeartbeats.contains(payload))
                    return;
                m_rivalSaid = true;
                qCWarning(lcMqtt).noquote() << "another publisher sends heartbeats as station" << m_station << "to"
                                            << m_client.settings().url()
                                            << "- the two overwrite each other's topics: give each its own --name";
                emit rivalHeard();
            });
    connect(&m_sweep, &RetainedSweep::finished, this, [](int cleared, int left, int passes) {
        // A clear lost with a pass's connection is sent again in the next: the count is of
        // messages sent, not of topics.
        if (cleared > 0)
            qCInfo(lcMqtt).noquote() << "cleared what an earlier run left retained (lines, devices or values this "
                                        "station no longer publishes):"
                                     << cleared << "empty retained messages in" << passes << "passes";
        if (left > 0)
            qCWarning(lcMqtt).noquote() << left << "retained topics an earlier run left are still there after" << passes
                                        << "passes (someone keeps publishing them?); the next connect tries again";
    });
    connect(&m_guard, &StationGuard::restoreRequested, this, &StationPublisher::restore);
    connect(&m_guard, &StationGuard::otherPublisherOnline, this, &StationPublisher::stopTakenOver);
    m_statusDue.setSingleShot(true);
    m_statusDue.setInterval(2000);
    connect(&m_statusDue, &QTimer::timeout, this, &StationPublisher::publishStatus);
    connect(&m_guard, &StationGuard::countsChanged, this, [this] {
        if (!m_statusDue.isActive())
            m_statusDue.start();
    });
    connect(&m_client, &MqttClient::connected, this, &StationPublisher::onConnected);
    connect(&m_client, &MqttClient::disconnected, this, [this](const QString &reason) {
        if (m_stopping) {
            if (!m_stopSignalled) {
                m_stopDeadline.stop();
                m_stopSignalled = true;
                emit stopped();
            }
        } else if (reason != m_saidLoss) {
            // A broker that is down or refuses us is retried for days: said once per reason.
            m_saidLoss = reason;
            qCWarning(lcMqtt).noquote() << "broker" << m_client.settings().url() << "lost or not reached:" << reason;
        }
    });
    connect(&m_client, &MqttClient::refused, this, [](const QString &reason) {
        qCWarning(lcMqtt).noquote() << reason;
    });
    m_stopDeadline.setSingleShot(true);
    connect(&m_stopDeadline, &QTimer::timeout, this, [this] {
        qCWarning(lcMqtt).noquote() << "the broker did not take the stop in time";
        m_stopSignalled = true;
        m_client.disconnectFromBroker();
        emit stopped();
    });
}

StationPublisher::~StationPublisher()
{
    for (Line &line : m_lines) {
        for (const auto &c : line.connections)
            disconnect(c);
    }
}

QStringList StationPublisher::lines() const
{
    QStringList names;
    for (const Line &line : m_lines)
        names << line.name;
    return names;
}

void StationPublisher::addLine(const QString &name, Bus *bus)
{
    Line line;
    line.name = name;
    line.bus = bus;
    line.since = QDateTime::currentDateTimeUtc();
    line.error = bus->lastError();
    line.connections << connect(bus, &Bus::stateChanged, this, [this, bus](LineState) {
        if (Line *l = lineOf(bus)) {
            l->since = QDateTime::currentDateTimeUtc();
            if (bus->state() == LineState::Connected)
                l->error.clear();
            publishLine(*l, false);
        }
    });
    line.connections << connect(bus, &Bus::lineError, this, [this, bus](const QString &message) {
        if (Line *l = lineOf(bus)) {
            l->error = message;
            publishLine(*l, false);
        }
    });
    line.connections << connect(bus, &Bus::entriesUpdated, this, [this, bus](DeviceId id, const QStringList &ids) {
        if (!m_devices.contains(id)) {
            if (Line *l = lineOf(bus))
                syncDevices(l->name);
        }
        publishEntries(id, ids, false);
    });
    line.connections << connect(bus, &Bus::conditionChanged, this, [this, bus](DeviceId id, const DeviceCondition &) {
        if (!m_devices.contains(id)) {
            if (Line *l = lineOf(bus))
                syncDevices(l->name);
            return;
        }
        publishCondition(id, false);
    });
    // A viewer shows the age of the last read, and the station publishes only changes:
    // each device's last completed cycle goes into its condition, at most once per
    // heartbeat interval.
    line.connections << connect(bus, &Bus::pollCycleFinished, this, [this](DeviceId id) {
        auto d = m_devices.find(id);
        if (d == m_devices.end())
            return;
        d->cycle = QDateTime::currentDateTimeUtc();
        const qint64 now = m_uptime.elapsed();
        if (d->cycleSentMs < 0 || now - d->cycleSentMs >= m_heartbeat.interval())
            publishCondition(id, true);
    });
    m_lines << line;
    publishLine(m_lines.last(), true);
    syncDevices(name);
    publishStatus();
}

void StationPublisher::removeLine(const QString &name)
{
    for (qsizetype i = 0; i < m_lines.size(); ++i) {
        if (m_lines[i].name != name)
            continue;
        for (const auto &c : m_lines[i].connections)
            disconnect(c);
        const QList<DeviceId> ids = m_devices.keys();
        for (DeviceId id : ids) {
            if (m_devices[id].line == name)
                forgetDevice(id);
        }
        clear(m_scheme.line(m_station, name));
        m_lines.removeAt(i);
        publishOrder();
        publishStatus();
        return;
    }
}

void StationPublisher::syncDevices(const QString &lineName)
{
    Line *line = lineNamed(lineName);
    if (!line || !line->bus)
        return;
    const QList<DeviceId> present = line->bus->devices();
    const QList<DeviceId> known = m_devices.keys();
    for (DeviceId id : known) {
        if (m_devices[id].line == lineName && !present.contains(id))
            forgetDevice(id);
    }
    for (DeviceId id : present) {
        if (m_devices.contains(id))
            continue;
        Device d;
        d.line = lineName;
        d.name = line->bus->deviceName(id);
        d.map = line->bus->deviceMap(id);
        if (!d.map)
            continue;
        const QStringList polled = line->bus->pollEntries(id);
        for (const RegisterEntry &e : d.map->entries()) {
            // Reserves are read with their neighbours but mean nothing to anyone.
            if (!e.reserved && (polled.isEmpty() || polled.contains(e.id)))
                d.entries << e.id;
        }
        d.entrySet = QSet<QString>(d.entries.cbegin(), d.entries.cend());
        m_devices.insert(id, d);
        publishDevice(id);
    }
    publishOrder();
}

bool StationPublisher::start(QString *error)
{
    m_started = QDateTime::currentDateTimeUtc();
    m_stopping = false;
    m_stopSignalled = false;
    m_client.setWill(m_scheme.status(m_station), TopicScheme::statusOffline(QStringLiteral("connection lost")));
    m_client.subscribe(m_scheme.heartbeat(m_station), 0);
    if (!m_client.connectToBroker()) {
        if (error)
            *error = m_client.lastError();
        return false;
    }
    m_guard.start(m_started);
    qCInfo(lcMqtt).noquote() << "station" << m_station << "publishing to" << m_client.settings().url() << "under"
                             << m_scheme.status(m_station).section(QLatin1Char('/'), 0, -2) + QStringLiteral("/");
    return true;
}

void StationPublisher::stop()
{
    m_heartbeat.stop();
    m_sweep.stop();
    m_guard.stop();
    m_statusDue.stop();
    m_stopping = true;
    if (!m_client.isConnected()) {
        m_stopSignalled = true;
        m_client.disconnectFromBroker();
        emit stopped();
        return;
    }
    // Disconnected once the broker has the "stopped": closing a socket with its
    // acknowledgement still unread makes the kernel reset the connection, and the broker
    // loses the DISCONNECT with it and sends the will after all. Our own heartbeats would
    // come back meanwhile: no longer asked for.
    m_client.unsubscribe(m_scheme.heartbeat(m_station));
    int messageId = -1;
    if (!m_client.publish(m_scheme.status(m_station), TopicScheme::statusOffline(QStringLiteral("stopped")), true, 1,
                          &messageId)) {
        m_client.disconnectFromBroker();
        return;
    }
    m_stopDeadline.start(3000);
    connect(&m_client, &MqttClient::delivered, this, [this, messageId](int id) {
        if (id == messageId)
            m_client.disconnectFromBroker();
    });
}

void StationPublisher::onConnected()
{
    qCInfo(lcMqtt).noquote() << "connected to" << m_client.settings().url();
    m_saidLoss.clear();
    for (const QString &topic : std::as_const(m_pendingClears))
        m_client.publish(topic, QByteArray(), true);
    m_pendingClears.clear();
    publishAll();
    if (!m_stopping)
        m_sweep.start(std::max(3000, 2 * m_heartbeat.interval()));
    if (!m_stopping)
        m_heartbeat.start();
}

void StationPublisher::publishAll()
{
    m_messages = 0;
    // The status last: a viewer holds what an earlier run left retained as not live until
    // "online" comes, and by then every line, device and value of this run is there.
    for (Line &line : m_lines)
        publishLine(line, true);
    for (auto it = m_devices.begin(); it != m_devices.end(); ++it)
        publishDevice(it.key());
    publishOrder();
    publishStatus();
    emit statePublished(m_messages);
}

void StationPublisher::publishStatus()
{
    if (m_stopping)
        return;
    const QString software = QStringLiteral("%1 %2").arg(QCoreApplication::applicationName(), QStringLiteral(JUMO_VERSION));
    publish(m_scheme.status(m_station), TopicScheme::statusOnline(software, m_started, lines(),
                                                                  qint64(m_guard.restoredCount()),
                                                                  qint64(m_guard.clearedCount())));
}

void StationPublisher::publishLine(Line &line, bool force)
{
    if (!line.bus)
        return;
    // A port that did not open says why in lastError(), with no lineError signal.
    const QString error = line.error.isEmpty() && line.bus->state() != LineState::Connected ? line.bus->lastError()
                                                                                          : line.error;
    const QByteArray payload =
            TopicScheme::linePayload(line.bus->settings().portName, line.bus->state(), line.since, error);
    // "since" changes only with the state: an equal payload is no news.
    if (!force && payload == line.lastPayload)
        return;
    line.lastPayload = payload;
    publish(m_scheme.line(m_station, line.name), payload);
}

void StationPublisher::publishDevice(DeviceId id)
{
    Device &d = m_devices[id];
    Line *line = lineNamed(d.line);
    if (!line || !line->bus)
        return;
    publish(m_scheme.deviceInfo(m_station, d.line, d.name),
            TopicScheme::deviceInfoPayload(d.line, *d.map, line->bus->deviceAddress(id)));
    publishCondition(id, true);
    publishEntries(id, d.entries, true);
}

void StationPublisher::publishCondition(DeviceId id, bool force)
{
    auto it = m_devices.find(id);
    if (it == m_devices.end())
        return;
    Device &d = *it;
    Line *line = lineNamed(d.line);
    if (!line || !line->bus || !m_client.isConnected())
        return;
    const DeviceCondition condition = line->bus->condition(id);
    // A bus may say the same condition twice (a line loss reaches each device by two
    // ways): once is news, twice is noise.
    const QByteArray key = TopicScheme::conditionPayload(condition);
    if (!force && key == d.condition)
        return;
    d.condition = key;
    if (d.cycle.isValid())
        d.cycleSentMs = m_uptime.elapsed();
    publish(m_scheme.deviceCondition(m_station, d.line, d.name), TopicScheme::conditionPayload(condition, d.cycle));
}

void StationPublisher::publishOrder()
{
    if (m_stopping)
        return;
    QStringList order;
    for (const Line &line : std::as_const(m_lines)) {
        if (!line.bus)
            continue;
        for (DeviceId id : line.bus->devices()) {
            if (const auto d = m_devices.constFind(id); d != m_devices.cend())
                order << line.name + QLatin1Char('/') + d->name;
        }
    }
    publish(m_scheme.order(m_station), TopicScheme::orderPayload(order));
}

void StationPublisher::restore(const QString &topic)
{
    if (m_stopping)
        return;
    const std::optional<TopicScheme::Topic> parsed = m_scheme.parse(topic);
    if (!parsed)
        return;
    using Kind = TopicScheme::Kind;
    switch (parsed->kind) {
    case Kind::Status:
        publishStatus();
        return;
    case Kind::Order:
        publishOrder();
        return;
    case Kind::Line:
        for (Line &line : m_lines) {
            if (line.name == parsed->line)
                publishLine(line, true);
        }
        return;
    case Kind::DeviceInfo:
    case Kind::DeviceCondition:
    case Kind::Value:
        for (auto it = m_devices.cbegin(); it != m_devices.cend(); ++it) {
            if (it->line != parsed->line || it->name != parsed->device)
                continue;
            if (parsed->kind == Kind::Value) {
                publishEntries(it.key(), {parsed->entry}, true);
            } else if (parsed->kind == Kind::DeviceCondition) {
                publishCondition(it.key(), true);
            } else {
                const Line *line = lineNamed(it->line);
                if (line && line->bus)
                    publish(topic, TopicScheme::deviceInfoPayload(it->line, *it->map, line->bus->deviceAddress(it.key())));
            }
            return;
        }
        return;
    default:
        return;
    }
}

void StationPublisher::stopTakenOver()
{
    if (m_stopping)
        return;
    qCWarning(lcMqtt).noquote() << "another publisher said it is station" << m_station << "at"
                                << m_client.settings().url() << "(started with --take-over): stopping";
    // Its status stands: no "stopped" over it, and a clean disconnect leaves no will.
    m_stopping = true;
    m_stopSignalled = true;
    m_heartbeat.stop();
    m_sweep.stop();
    m_guard.stop();
    m_statusDue.stop();
    m_client.disconnectFromBroker();
    emit takenOver();
}

void StationPublisher::publishEntries(DeviceId id, const QStringList &entryIds, bool force)
{
    if (!m_client.isConnected())
        return;   // all of it goes out again on the next connect
    auto it = m_devices.find(id);
    if (it == m_devices.end())
        return;
    Device &d = *it;
    Line *line = lineNamed(d.line);
    if (!line || !line->bus)
        return;
    const Bus &bus = *line->bus;
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const qint64 clockNow = bus.clockMs();
    for (const QString &entryId : entryIds) {
        const EntryState *state = bus.entryState(id, entryId);
        const RegisterEntry *entry = d.map->entry(entryId);
        if (!state || !entry || !d.entrySet.contains(entryId))
            continue;
        const QDateTime read = state->goodMs >= 0 ? now.addMSecs(state->goodMs - clockNow) : QDateTime();
        const QByteArray payload = TopicScheme::valuePayload(*state, *entry, read);
        // What a viewer shows: the text and the status. A new read of the same value is
        // no news (the heartbeat says the station is alive).
        const QString key = ValueFormat::withUnit(state->value, *entry, QLocale::c()) + QChar(0x1F) + state->statusName();
        if (!force && d.published.value(entryId) == key)
            continue;
        d.published.insert(entryId, key);
        publish(m_scheme.value(m_station, d.line, d.name, entryId), payload);
    }
}

void StationPublisher::forgetDevice(DeviceId id)
{
    const Device d = m_devices.take(id);
    clear(m_scheme.deviceInfo(m_station, d.line, d.name));
    clear(m_scheme.deviceCondition(m_station, d.line, d.name));
    for (auto it = d.published.keyBegin(); it != d.published.keyEnd(); ++it)
        clear(m_scheme.value(m_station, d.line, d.name, *it));
}

bool StationPublisher::owns(const TopicScheme::Topic &topic) const
{
    switch (topic.kind) {
    case TopicScheme::Kind::Status:
    case TopicScheme::Kind::Heartbeat:
    case TopicScheme::Kind::Order:
    case TopicScheme::Kind::Viewer:
    case TopicScheme::Kind::Probe:
        return true;   // the station's own, or a viewer's
    case TopicScheme::Kind::Line:
        return std::any_of(m_lines.cbegin(), m_lines.cend(), [&](const Line &l) { return l.name == topic.line; });
    case TopicScheme::Kind::DeviceInfo:
    case TopicScheme::Kind::DeviceCondition:
    case TopicScheme::Kind::Value:
        for (const Device &d : m_devices) {
            if (d.line == topic.line && d.name == topic.device)
                return topic.kind != TopicScheme::Kind::Value || d.entrySet.contains(topic.entry);
        }
        return false;
    }
    return true;
}

void StationPublisher::clear(const QString &topic)
{
    // An empty retained message removes the retained one; a broker that cannot be
    // reached now gets it on the next connect.
    m_guard.expect(topic, QByteArray());
    if (!m_client.publish(topic, QByteArray(), true) && !m_pendingClears.contains(topic))
        m_pendingClears << topic;
}

StationPublisher::Line *StationPublisher::lineNamed(const QString &name)
{
    for (Line &l : m_lines) {
        if (l.name == name)
            return &l;
    }
    return nullptr;
}

StationPublisher::Line *StationPublisher::lineOf(const Bus *bus)
{
    for (Line &l : m_lines) {
        if (l.bus == bus)
            return &l;
    }
    return nullptr;
}

void StationPublisher::publish(const QString &topic, const QByteArray &payload, bool retain)
{
    // After "stopped", nothing: a value published behind it would be the last word.
    if (m_stopping)
        return;
    if (retain)
        m_guard.expect(topic, payload);
    if (m_client.publish(topic, payload, retain))
        ++m_messages;
}

} // namespace jumo
