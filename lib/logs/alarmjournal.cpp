#include "logs/alarmjournal.h"

namespace jumo {

AlarmJournal::AlarmJournal(const DeviceSource *devices, EventLog *log, QObject *parent) : QObject(parent), m_devices(devices), m_log(log)
{
    connect(m_devices, &DeviceSource::entriesUpdated, this, &AlarmJournal::onEntriesUpdated);
    connect(m_devices, &DeviceSource::conditionChanged, this, &AlarmJournal::onConditionChanged);
}

void AlarmJournal::onConditionChanged(DeviceId device, const DeviceCondition &condition)
{
    const auto map = m_devices->deviceMap(device);
    if (!map)
        return;
    using State = DeviceCondition::State;
    if (condition.state == State::Identifying)
        return;   // on the way back: "restored" once confirmed, "lost" if another device answers
    const State before = m_condition.value(device, State::Disconnected);
    m_condition.insert(device, condition.state);
    QString state;
    if (condition.state == State::Offline && before != State::Offline)
        state = QStringLiteral("lost: device not answering");
    else if (condition.state == State::LineLost && before != State::LineLost)
        state = QStringLiteral("lost: line lost");
    else if (condition.state == State::WrongDevice && before != State::WrongDevice)
        state = QStringLiteral("lost: %1").arg(condition.detail);
    else if (condition.state == State::Online
             && (before == State::Offline || before == State::LineLost || before == State::WrongDevice))
        state = QStringLiteral("restored");
    else if (condition.state == State::Disconnected && before == State::Online)
        state = QStringLiteral("stopped: line closed");
    if (state.isEmpty())
        return;
    m_log->append(QJsonObject{{"device", m_prefix + QStringLiteral("%1@%2").arg(map->family).arg(m_devices->deviceAddress(device))},
                              {"register", QString()},
                              {"bit", QString()},
                              {"id", QStringLiteral("communication")},
                              {"label", QStringLiteral("Communication")},
                              {"kind", QStringLiteral("communication")},
                              {"state", state}});
}

QStringList AlarmJournal::columns()
{
    return {QStringLiteral("time"), QStringLiteral("device"), QStringLiteral("register"), QStringLiteral("bit"),
            QStringLiteral("id"),   QStringLiteral("label"),  QStringLiteral("kind"),     QStringLiteral("state")};
}

void AlarmJournal::onEntriesUpdated(DeviceId device, const QStringList &ids)
{
    const auto map = m_devices->deviceMap(device);
    if (!map)
        return;
    const QString deviceName = m_prefix + QStringLiteral("%1@%2").arg(map->family).arg(m_devices->deviceAddress(device));
    for (const QString &id : ids) {
        const RegisterEntry *e = map->entry(id);
        if (!e || e->type != ValueType::Bitfield || e->isCommand())
            continue;
        const EntryState *s = m_devices->entryState(device, id);
        if (!s || !s->isCurrent())
            continue;   // no reading, no event: a lost reply changes no bit
        // By id, not name: the name changes when a second line joins the station.
        const QString key = QString::number(device) + QLatin1Char('/') + id;
        const bool firstSight = !m_last.contains(key);
        const quint32 before = m_last.value(key);
        const quint32 now = s->value.raw;
        m_last.insert(key, now);
        for (const BitDefinition &b : e->bits) {
            if (b.reserved || b.width != 1 || b.kind == BitKind::Command)
                continue;
            const bool on = now & b.mask();
            const bool was = before & b.mask();
            // At the first reading only bits that are on are news.
            if (firstSight ? !on : on == was)
                continue;
            m_log->append(QJsonObject{{"device", deviceName},
                                      {"register", formatAddress(e->address)},
                                      {"bit", b.bit},
                                      {"id", id + QLatin1Char('.') + b.id},
                                      {"label", b.label},
                                      {"kind", bitKindName(b.kind)},
                                      {"state", on ? (firstSight ? QStringLiteral("set at first reading") : QStringLiteral("set"))
                                                   : QStringLiteral("cleared")}});
        }
    }
}

} // namespace jumo
