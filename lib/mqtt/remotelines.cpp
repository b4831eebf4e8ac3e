#include "mqtt/remotelines.h"

#include "mqtt/remotestation.h"

#include <QLocale>
#include <QRegularExpression>

#include <limits>

namespace jumo {

namespace {

QString keyOf(const QString &station, const QString &line)
{
    return station + QLatin1Char('/') + line;
}

} // namespace

RemoteLines::RemoteLines(RemoteStation *station, QObject *parent) : QObject(parent), m_station(station)
{
    connect(station, &RemoteStation::deviceAdded, this, &RemoteLines::onDeviceAdded);
    connect(station, &RemoteStation::deviceRemoved, this, &RemoteLines::onDeviceRemoved);
    connect(station, &RemoteStation::entriesUpdated, this, &RemoteLines::onEntriesUpdated);
    connect(station, &RemoteStation::conditionChanged, this,
            [this](DeviceId id, const DeviceCondition &) { onConditionChanged(id); });
    connect(station, &RemoteStation::deviceRead, this, [this](DeviceId remote, qint64 goodMs) {
        const Mirrored m = m_mirrored.value(remote);
        if (m.line)
            m.line->setReadTime(m.id, goodMs);
    });
    connect(station, &RemoteStation::lineStateChanged, this,
            [this](const QString &stationName, const QString &line, LineState) {
                if (m_station->line(stationName, line))
                    ensureLine(stationName, line);
                updateLine(stationName, line);
            });
    connect(station, &RemoteStation::lineRemoved, this, &RemoteLines::removeLineIfGone);
    connect(station, &RemoteStation::orderChanged, this, &RemoteLines::orderChanged);
    connect(station, &RemoteStation::stationChanged, this, &RemoteLines::onStationChanged);
    connect(station, &RemoteStation::connectionChanged, this, [this] {
        for (const QString &name : m_station->stations())
            onStationChanged(name);
    });
    for (DeviceId id : station->devices())
        onDeviceAdded(id);
}

RemoteLines::~RemoteLines() = default;

QList<MirroredLine *> RemoteLines::lines() const
{
    QList<MirroredLine *> lines;
    for (const auto &line : m_lines)
        lines.append(line.get());
    return lines;
}

MirroredLine *RemoteLines::line(const QString &station, const QString &line) const
{
    return m_lineByKey.value(keyOf(station, line));
}

QString RemoteLines::stationOf(const MirroredLine *line) const
{
    return m_stationOf.value(line);
}

QList<MirroredLine *> RemoteLines::orderedLines() const
{
    QList<MirroredLine *> ordered = lines();
    // The rank of a line within its station: as its status lists the lines, then as its
    // device order first names them, then by name.
    auto rank = [this](const MirroredLine *line) {
        const RemoteStationState *s = m_station->station(stationOf(line));
        qsizetype at = s ? s->status.lines.indexOf(line->name()) : -1;
        if (at < 0 && s) {
            const qsizetype inOrder = s->order.indexOf(QRegularExpression(
                    QStringLiteral("^%1/").arg(QRegularExpression::escape(line->name()))));
            at = inOrder < 0 ? -1 : 10000 + inOrder;
        }
        return at < 0 ? std::numeric_limits<qsizetype>::max() : at;
    };
    std::stable_sort(ordered.begin(), ordered.end(), [&](const MirroredLine *a, const MirroredLine *b) {
        const QString sa = stationOf(a);
        const QString sb = stationOf(b);
        if (sa != sb)
            return sa < sb;
        const qsizetype ra = rank(a);
        const qsizetype rb = rank(b);
        return ra != rb ? ra < rb : a->name() < b->name();
    });
    return ordered;
}

QList<DeviceId> RemoteLines::orderedDevices(const MirroredLine *line) const
{
    QList<DeviceId> ordered = line->devices();
    const RemoteStationState *s = m_station->station(stationOf(line));
    const QStringList order = s ? s->order : QStringList();
    auto rank = [&](DeviceId id) {
        const qsizetype at = order.indexOf(line->name() + QLatin1Char('/') + line->deviceName(id));
        return at < 0 ? std::numeric_limits<qsizetype>::max() : at;
    };
    std::stable_sort(ordered.begin(), ordered.end(), [&](DeviceId a, DeviceId b) {
        const qsizetype ra = rank(a);
        const qsizetype rb = rank(b);
        if (ra != rb)
            return ra < rb;
        if (line->deviceAddress(a) != line->deviceAddress(b))
            return line->deviceAddress(a) < line->deviceAddress(b);
        return line->deviceName(a) < line->deviceName(b);
    });
    return ordered;
}

MirroredLine *RemoteLines::ensureLine(const QString &station, const QString &line)
{
    if (MirroredLine *known = m_lineByKey.value(keyOf(station, line)))
        return known;
    m_lines.push_back(std::make_unique<MirroredLine>(line));
    MirroredLine *mirrored = m_lines.back().get();
    m_lineByKey.insert(keyOf(station, line), mirrored);
    m_stationOf.insert(mirrored, station);
    updateLine(station, line);
    emit lineAdded(mirrored);
    emit orderChanged();
    return mirrored;
}

void RemoteLines::removeLineIfGone(const QString &station, const QString &line)
{
    MirroredLine *mirrored = m_lineByKey.value(keyOf(station, line));
    // A line goes once the station has cleared it and every device on it: devices first.
    if (!mirrored || m_station->line(station, line) || !mirrored->devices().isEmpty())
        return;
    emit lineRemoving(mirrored);
    m_lineByKey.remove(keyOf(station, line));
    m_stationOf.remove(mirrored);
    for (auto it = m_lines.begin(); it != m_lines.end(); ++it) {
        if (it->get() == mirrored) {
            it->release()->deleteLater();
            m_lines.erase(it);
            break;
        }
    }
    emit orderChanged();
}

void RemoteLines::onDeviceAdded(DeviceId remote)
{
    const RemoteDevice *d = m_station->device(remote);
    if (!d || !d->map || m_mirrored.contains(remote))
        return;
    MirroredLine *line = ensureLine(d->station, d->line);
    const DeviceId id = line->addDevice(d->map, quint8(d->address));
    m_mirrored.insert(remote, {line, id});
    m_remoteOf.insert(id, remote);
    emit deviceAdded(line, id);
    onConditionChanged(remote);
    const QStringList ids = m_station->entryIds(remote);
    if (!ids.isEmpty())
        onEntriesUpdated(remote, ids);
    emit orderChanged();
}

void RemoteLines::onDeviceRemoved(DeviceId remote)
{
    const Mirrored m = m_mirrored.take(remote);
    if (!m.line)
        return;
    m_remoteOf.remove(m.id);
    emit deviceRemoving(m.line, m.id);
    m.line->removeDevice(m.id);
    const QString station = stationOf(m.line);
    const QString name = m.line->name();
    emit orderChanged();
    removeLineIfGone(station, name);
}

void RemoteLines::onEntriesUpdated(DeviceId remote, const QStringList &ids)
{
    const Mirrored m = m_mirrored.value(remote);
    if (!m.line)
        return;
    // Both keep times on the machine's monotonic clock: the states are taken as they are.
    QHash<QString, EntryState> states;
    for (const QString &entryId : ids) {
        const EntryState *s = m_station->entryState(remote, entryId);
        states.insert(entryId, s ? *s : EntryState{});
    }
    m.line->setEntries(m.id, states);
}

void RemoteLines::onConditionChanged(DeviceId remote)
{
    const Mirrored m = m_mirrored.value(remote);
    const RemoteDevice *d = m_station->device(remote);
    if (!m.line || !d)
        return;
    DeviceCondition condition = d->condition;
    const Silence silence = silenceOf(d->station);
    using State = DeviceCondition::State;
    if (silence.kind == Silence::Kind::Waiting && m.line->condition(m.id).state == State::Disconnected) {
        // Not seen live yet (the viewer has just started): nothing was lost.
        condition = {State::Disconnected, silence.since, silence.reason};
    } else if (silence.kind != Silence::Kind::Live) {
        condition = {State::LineLost, silence.since, silence.reason};
    } else if (m.line->condition(m.id).state == State::LineLost) {
        // Live again after a restart: a device the new run does not have (its order,
        // published before its "online", leaves it out) still has its last run's retained
        // condition until the station clears its topics. It leaves lost, never restored.
        const RemoteStationState *s = m_station->station(d->station);
        if (s && !s->order.isEmpty() && !s->order.contains(d->line + QLatin1Char('/') + d->name))
            return;
    }
    m.line->setCondition(m.id, condition);
}

void RemoteLines::onStationChanged(const QString &station)
{
    for (auto it = m_lineByKey.cbegin(); it != m_lineByKey.cend(); ++it) {
        if (m_stationOf.value(it.value()) == station)
            updateLine(station, it.value()->name());
    }
    for (auto it = m_mirrored.cbegin(); it != m_mirrored.cend(); ++it) {
        const RemoteDevice *d = m_station->device(it.key());
        if (d && d->station == station)
            onConditionChanged(it.key());
    }
    emit orderChanged();
}

void RemoteLines::updateLine(const QString &station, const QString &line)
{
    MirroredLine *mirrored = m_lineByKey.value(keyOf(station, line));
    if (!mirrored)
        return;
    const Silence silence = silenceOf(station);
    if (silence.kind == Silence::Kind::Waiting && mirrored->state() != LineState::Lost) {
        mirrored->setState(LineState::Disconnected, silence.reason);
        return;
    }
    if (silence.kind != Silence::Kind::Live) {
        mirrored->setState(LineState::Lost, silence.reason);
        return;
    }
    const LineMessage *published = m_station->line(station, line);
    if (!published) {
        mirrored->setState(LineState::Disconnected, tr("the station has not reported this line"));
        return;
    }
    mirrored->setState(published->state, published->error);
}

RemoteLines::Silence RemoteLines::silenceOf(const QString &station) const
{
    if (m_station->isLive(station))
        return {};
    const RemoteStationState *s = m_station->station(station);
    const QDateTime since = s && s->lostSince.isValid() ? s->lostSince : QDateTime::currentDateTime();
    if (!m_station->isConnected())
        return {Silence::Kind::Lost, tr("the broker cannot be reached: values are the last ones received"), since};
    if (!s || !s->statusKnown)
        return {Silence::Kind::Waiting, tr("station %1 has not said that it is online").arg(station), since};
    if (!s->status.online)
        return {Silence::Kind::Lost,
                s->status.reason == QLatin1String("stopped") ? tr("station %1 was stopped").arg(station)
                                                             : tr("station %1 is offline (%2)").arg(station, s->status.reason),
                since};
    if (s->silent)
        return {Silence::Kind::Lost,
                tr("station %1 has not been heard for %2 s")
                        .arg(station, QLocale().toString(m_station->silenceLimitMs() / 1000.0, 'g', 3)),
                since};
    return {Silence::Kind::Waiting, tr("receiving the state of station %1").arg(station), since};
}

} // namespace jumo
