#include "models/alarmbitsmodel.h"

#include "bus/valuetext.h"

#include <QCoreApplication>

#include <algorithm>

namespace jumo {

AlarmBitsModel::AlarmBitsModel(const DeviceSource *devices, DeviceId device, QObject *parent)
    : QAbstractListModel(parent), m_devices(devices), m_device(device), m_map(devices->deviceMap(device))
{
    if (m_map) {
        for (const RegisterEntry &e : m_map->entries()) {
            if (e.type != ValueType::Bitfield || !e.isReadable() || e.isCommand())
                continue;
            for (const BitDefinition &b : e.bits) {
                // Reserved bits are hidden; multi-bit codes are no LEDs.
                if (!b.reserved && b.width == 1 && b.kind != BitKind::Command)
                    m_rows << Row{&e, &b};
            }
        }
    }
    connect(m_devices, &DeviceSource::entriesUpdated, this, &AlarmBitsModel::onEntriesUpdated);
    recount();
}

int AlarmBitsModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int AlarmBitsModel::rowOf(const QString &reference) const
{
    for (int i = 0; i < m_rows.size(); ++i) {
        if (m_rows[i].entry->id + QLatin1Char('.') + m_rows[i].bit->id == reference)
            return i;
    }
    return -1;
}

AlarmBitsModel::BitState AlarmBitsModel::bitState(const Row &row) const
{
    const EntryState *s = m_devices->entryState(m_device, row.entry->id);
    if (!s || s->validity == Validity::Unknown || !s->hasValue())
        return BitState::Unknown;
    return (s->value.raw & row.bit->mask()) ? BitState::On : BitState::Off;
}

void AlarmBitsModel::onEntriesUpdated(DeviceId device, const QStringList &ids)
{
    if (device != m_device)
        return;
    int first = int(m_rows.size());
    int last = -1;
    for (int i = 0; i < m_rows.size(); ++i) {
        if (ids.contains(m_rows[i].entry->id)) {
            first = std::min(first, i);
            last = std::max(last, i);
        }
    }
    if (last < 0)
        return;
    recount();   // first, so views that repaint on dataChanged see the new count
    emit dataChanged(index(first), index(last));
}

void AlarmBitsModel::recount()
{
    int count = 0;
    bool known = true;
    bool stale = false;
    // Known only while every word of the grid is: a device with warning and status
    // bits but no alarm bit must not say "0 active alarms" when nothing can be read.
    for (const Row &r : std::as_const(m_rows)) {
        const BitState state = bitState(r);
        known = known && state != BitState::Unknown;
        const EntryState *s = m_devices->entryState(m_device, r.entry->id);
        stale = stale || (s && s->validity == Validity::Stale);
        count += r.bit->kind == BitKind::Alarm && state == BitState::On;
    }
    m_alarmsStale = stale;
    if (count != m_activeAlarms) {
        m_activeAlarms = count;
        emit activeAlarmsChanged(count);
    }
    if (known != m_alarmsKnown) {
        m_alarmsKnown = known;
        emit alarmsKnownChanged(known);
    }
}

QVariant AlarmBitsModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const Row &row = m_rows.at(index.row());
    const EntryState *state = m_devices->entryState(m_device, row.entry->id);
    switch (role) {
    case Qt::DisplayRole:
        return QCoreApplication::translate("jumo::maps", row.bit->label.toUtf8().constData());
    case KindRole:
        return int(row.bit->kind);
    case BitStateRole:
        return int(bitState(row));
    case ValidityRole:
        return int(state ? state->validity : Validity::Unknown);
    case ReferenceRole:
        return row.entry->id + QLatin1Char('.') + row.bit->id;
    case GroupTitleRole:
        return tr("%1 (register %2)")
                .arg(QCoreApplication::translate("jumo::maps", row.entry->label.toUtf8().constData()),
                     formatAddress(row.entry->address));
    case Qt::ToolTipRole: {
        const QString kind = row.bit->kind == BitKind::Alarm ? tr("alarm")
                : row.bit->kind == BitKind::Warning         ? tr("warning")
                                                            : tr("status");
        QString tip = tr("%1\nRegister %2 (%3), bit %4, %5\nManual %6: \"%7\"")
                              .arg(QCoreApplication::translate("jumo::maps", row.bit->label.toUtf8().constData()),
                                   formatAddress(row.entry->address),
                                   QCoreApplication::translate("jumo::maps", row.entry->label.toUtf8().constData()))
                              .arg(row.bit->bit)
                              .arg(kind, row.entry->group, row.bit->label);
        if (!state || state->validity == Validity::Unknown)
            tip += QLatin1Char('\n') + tr("Unknown: the register could not be read (%1).")
                                              .arg(ValueText::reason(state ? state->error : ReadError::NotRead,
                                                                     state ? state->exceptionCode : 0, *m_map));
        else if (state->validity == Validity::Stale)
            tip += QLatin1Char('\n') + tr("Stale: not read within the device's cycle.");
        return tip;
    }
    default:
        return {};
    }
}

} // namespace jumo
