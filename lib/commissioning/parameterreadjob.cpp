#include "commissioning/parameterreadjob.h"

namespace jumo {

ParameterReadJob::ParameterReadJob(Bus *bus, DeviceId device, QObject *parent)
    : Job(parent), m_bus(bus), m_device(device)
{
    connect(m_bus, &Bus::entriesRead, this, &ParameterReadJob::onEntriesRead);
}

void ParameterReadJob::start()
{
    begin();
    m_set = ParameterSet();
    m_failed.clear();
    const auto map = m_bus->deviceMap(m_device);
    if (!map) {
        finish(Result::Failed, tr("unknown device"));
        return;
    }
    m_ids = ParameterSet::parameterIds(*map);
    QStringList toRead = m_ids;
    for (const QString &id : map->identity) {
        if (!toRead.contains(id))
            toRead << id;
    }
    if (map->entry(QStringLiteral("software_version")) && !toRead.contains(QStringLiteral("software_version")))
        toRead << QStringLiteral("software_version");
    emit progressChanged(0, int(m_ids.size()));
    m_ticket = m_bus->readEntries(m_device, toRead);
}

void ParameterReadJob::onEntriesRead(int ticket, const QStringList &failed)
{
    if (ticket != m_ticket || !isRunning())
        return;
    m_ticket = -1;
    if (isCancelled()) {
        finish(Result::Cancelled);
        return;
    }
    const auto map = m_bus->deviceMap(m_device);
    if (!map) {
        finish(Result::Failed, tr("the device was removed"));
        return;
    }
    m_set.family = map->family;
    m_set.address = m_bus->deviceAddress(m_device);
    m_set.time = QDateTime::currentDateTimeUtc();
    for (const QString &id : std::as_const(m_ids)) {
        const EntryState *s = m_bus->entryState(m_device, id);
        const QString text = s && s->isCurrent() && !failed.contains(id)
                ? ValueCodec::exactText(*map->entry(id), *map, s->words)
                : QString();
        if (text.isNull())
            m_failed << id;
        else
            m_set.values.insert(id, text);
    }
    for (const QString &id : map->identity) {
        if (const EntryState *s = m_bus->entryState(m_device, id); s && s->isCurrent())
            m_set.identity.insert(id, s->value.display.trimmed());
    }
    if (const EntryState *s = m_bus->entryState(m_device, QStringLiteral("software_version")); s && s->isCurrent())
        m_set.softwareVersion = s->value.display.trimmed();
    emit progressChanged(int(m_set.values.size()), int(m_ids.size()));
    if (m_failed.isEmpty())
        finish(Result::Succeeded);
    else
        finish(Result::Failed, tr("could not be read: %1").arg(m_failed.join(QStringLiteral(", "))));
}

} // namespace jumo
