#include "mqtt/remotelines.h"

#include "mqtt/remotestation.h"

#include <QLocale>

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
    connect(station, &RemoteStation::lineStateChanged, this,
            [this](const QString &stationName, const QString &line, LineState) {
                // A line the station cleared is not made again just to say it is gone.
                if (m_station->line(stationName, line))
                    ensureLine(stationName, line);
                updateLine(stationName, line);
            });
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
    return mirrored;
}

void RemoteLines::onDeviceAdded(DeviceId remote)
{
    const RemoteDevice *d = m_station->device(remote);
    if (!d || m_mirrored.contains(remote))
        return;
    if (!d->map) {
        emit unknownFamily(d->station, d->line, d->name);
        return;
    }
    MirroredLine *line = ensureLine(d->station, d->line);
    const DeviceId id = line->addDevice(d->map, quint8(d->address));
    m_mirrored.insert(remote, {line, id});
    emit deviceAdded(line, id);
    onConditionChanged(remote);
    const QStringList ids = m_station->entryIds(remote);
    if (!ids.isEmpty())
        onEntriesUpdated(remote, ids);
}

void RemoteLines::onDeviceRemoved(DeviceId remote)
{
    const Mirrored m = m_mirrored.take(remote);
    if (!m.line)
        return;
    emit deviceRemoving(m.line, m.id);
    m.line->removeDevice(m.id);
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
    const QString silence = silenceReason(d->station);
    if (!silence.isEmpty()) {
        condition.state = DeviceCondition::State::LineLost;
        condition.detail = silence;
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
}

void RemoteLines::updateLine(const QString &station, const QString &line)
{
    MirroredLine *mirrored = m_lineByKey.value(keyOf(station, line));
    if (!mirrored)
        return;
    const QString silence = silenceReason(station);
    if (!silence.isEmpty()) {
        mirrored->setState(LineState::Lost, silence);
        return;
    }
    const LineMessage *published = m_station->line(station, line);
    if (!published) {
        mirrored->setState(LineState::Disconnected, tr("the station has not reported this line"));
        return;
    }
    mirrored->setState(published->state, published->error);
}

QString RemoteLines::silenceReason(const QString &station) const
{
    if (!m_station->isConnected())
        return tr("the broker cannot be reached: values are the last ones received");
    if (m_station->isLive(station))
        return {};
    const RemoteStationState *s = m_station->station(station);
    if (!s || !s->statusKnown)
        return tr("station %1 has not said that it is online").arg(station);
    if (!s->status.online)
        return s->status.reason == QLatin1String("stopped")
                ? tr("station %1 was stopped").arg(station)
                : tr("station %1 is offline (%2)").arg(station, s->status.reason);
    return tr("station %1 has not been heard for %2 s")
            .arg(station, QLocale().toString(m_station->silenceLimitMs() / 1000.0, 'g', 3));
}

} // namespace jumo
