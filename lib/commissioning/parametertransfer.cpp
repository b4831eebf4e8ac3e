#include "commissioning/parametertransfer.h"

#include <QSet>

namespace jumo {

ParameterTransfer::ParameterTransfer(Bus *bus, DeviceId device, QObject *parent)
    : QObject(parent), m_bus(bus), m_device(device)
{
    connect(m_bus, &Bus::entriesUpdated, this, &ParameterTransfer::onEntriesUpdated);
    connect(m_bus, &Bus::writeFinished, this, [this](int ticket, const WriteOutcome &outcome) {
        if (ticket != m_ticket)
            return;
        m_ticket = -1;
        const ParameterDifference done = m_pending.takeFirst();
        outcome.succeeded() ? ++m_succeeded : ++m_failed;
        emit entryWritten(done.id, outcome);
        emit progress(m_succeeded + m_failed, m_total);
        writeNext();
    });
}

void ParameterTransfer::read()
{
    const auto map = m_bus->deviceMap(m_device);
    m_ids = map ? ParameterSet::parameterIds(*map) : QStringList();
    m_fresh.clear();
    m_startMs = m_bus->clockMs();
    m_reading = true;
    m_cancelled = false;
    emit progress(0, int(m_ids.size()));
    if (m_ids.isEmpty()) {
        finishRead();
        return;
    }
    m_bus->requestCycle(m_device);
}

void ParameterTransfer::onEntriesUpdated(DeviceId device, const QStringList &ids)
{
    if (!m_reading || device != m_device)
        return;
    for (const QString &id : ids) {
        const EntryState *s = m_bus->entryState(device, id);
        if (m_ids.contains(id) && s && s->updatedMs >= m_startMs)
            m_fresh.insert(id);
    }
    emit progress(int(m_fresh.size()), int(m_ids.size()));
    if (m_fresh.size() == m_ids.size())
        finishRead();
    else if (!m_bus->isPolling())
        m_bus->requestCycle(m_device);
}

void ParameterTransfer::finishRead()
{
    m_reading = false;
    const auto map = m_bus->deviceMap(m_device);
    ParameterSet set;
    QStringList failed;
    if (map) {
        set.family = map->family;
        set.address = m_bus->deviceAddress(m_device);
        set.time = QDateTime::currentDateTimeUtc();
        for (const QString &id : std::as_const(m_ids)) {
            const EntryState *s = m_bus->entryState(m_device, id);
            const QString text = s && s->isCurrent() ? ValueCodec::exactText(*map->entry(id), *map, s->words) : QString();
            if (text.isNull())
                failed << id;
            else
                set.values.insert(id, text);
        }
        for (const QString &id : map->identity) {
            if (const EntryState *s = m_bus->entryState(m_device, id); s && s->hasValue())
                set.identity.insert(id, s->value.display.trimmed());
        }
        if (const EntryState *s = m_bus->entryState(m_device, QStringLiteral("software_version")); s && s->hasValue())
            set.softwareVersion = s->value.display.trimmed();
    }
    emit readFinished(set, failed);
}

void ParameterTransfer::write(const QList<ParameterDifference> &differences)
{
    m_pending = differences;
    m_total = int(differences.size());
    m_succeeded = 0;
    m_failed = 0;
    m_cancelled = false;
    emit progress(0, m_total);
    writeNext();
}

void ParameterTransfer::writeNext()
{
    if (m_cancelled || m_pending.isEmpty()) {
        const bool cancelled = m_cancelled && !m_pending.isEmpty();
        m_pending.clear();
        emit writeFinished(m_succeeded, m_failed, cancelled);
        return;
    }
    m_ticket = m_bus->write(m_device, m_pending.first().id, m_pending.first().newValue);
}

void ParameterTransfer::cancel()
{
    // A write already on the line finishes; nothing after it is sent.
    m_cancelled = true;
    if (m_reading) {
        m_reading = false;
        emit readFinished(ParameterSet(), {tr("cancelled")});
    }
}

} // namespace jumo
