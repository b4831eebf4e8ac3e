#include "models/livevaluesmodel.h"

#include "bus/valuetext.h"
#include "protocol/valueformat.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>

namespace jumo {

LiveValuesModel::LiveValuesModel(const DeviceSource *devices, DeviceId device, QObject *parent)
    : QAbstractTableModel(parent), m_devices(devices), m_device(device), m_map(devices->deviceMap(device)),
      m_interest(devices, device)
{
    if (m_map) {
        for (const RegisterEntry &e : m_map->entries()) {
            if (e.isReadable() && e.alias.isEmpty() && !e.reserved)
                m_rows << &e;
        }
        // The measured values first: they are what the tab is opened for (the identity
        // is above the table). A section counts as measured when its read-only values
        // outside the identity outnumber its identity words (the IPC 300's "5.1.1 ID"
        // has two such texts among nine identity words). Then the other sections; each
        // part in the manual's order of sections, the map's order within a section.
        QHash<QString, int> measured;
        for (const RegisterEntry *e : std::as_const(m_rows)) {
            if (m_map->identity.contains(e->id))
                --measured[e->group];
            else if (!e->isWritable())
                ++measured[e->group];
        }
        auto rank = [&measured](const RegisterEntry *e) { return measured.value(e->group) > 0 ? 0 : 1; };
        std::stable_sort(m_rows.begin(), m_rows.end(), [&rank](const RegisterEntry *a, const RegisterEntry *b) {
            if (rank(a) != rank(b))
                return rank(a) < rank(b);
            return sectionBefore(a->group, b->group);
        });
        for (int row = 0; row < m_rows.size(); ++row)
            m_rowOf.insert(m_rows.at(row)->id, row);
    }
    connect(m_devices, &DeviceSource::entriesUpdated, this, &LiveValuesModel::onEntriesUpdated);
    // Ages move on by themselves: one refresh a second. Validity changes come from the
    // bus, which turns values stale or unknown.
    m_ageTimer.setInterval(1000);
    connect(&m_ageTimer, &QTimer::timeout, this, [this] {
        if (!m_rows.isEmpty())
            emit dataChanged(index(0, StatusColumn), index(int(m_rows.size()) - 1, AgeColumn),
                             {Qt::DisplayRole, AgeMsRole});
    });
    m_ageTimer.start();
}

void LiveValuesModel::onEntriesUpdated(DeviceId device, const QStringList &ids)
{
    if (device != m_device)
        return;
    int first = int(m_rows.size());
    int last = -1;
    for (const QString &id : ids) {
        const int row = m_rowOf.value(id, -1);
        if (row >= 0) {
            first = std::min(first, row);
            last = std::max(last, row);
        }
    }
    if (last >= 0)
        emit dataChanged(index(first, 0), index(last, ColumnCount - 1));
}

void LiveValuesModel::setShown(const QObject *view, bool shown, const QStringList &entryIds)
{
    QStringList ids = entryIds;
    if (ids.isEmpty()) {
        for (const RegisterEntry *e : std::as_const(m_rows))
            ids << e->id;
    }
    m_interest.setShown(view, shown, ids);
}

int LiveValuesModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int LiveValuesModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString LiveValuesModel::entryId(int row) const
{
    return row >= 0 && row < m_rows.size() ? m_rows.at(row)->id : QString();
}

QVariant LiveValuesModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const RegisterEntry &e = *m_rows.at(index.row());
    const EntryState *state = m_devices->entryState(m_device, e.id);
    const qint64 age = state && state->hasValue() ? m_devices->clockMs() - state->goodMs : -1;
    const Validity validity = ValueText::validity(state);

    switch (role) {
    case EntryIdRole:
        return e.id;
    case StatusNameRole:
        return state ? state->statusName() : QString();
    case ValidityRole:
        return int(validity);
    case AgeMsRole:
        return age;
    case NumericRole: {
        if (!state || !state->isCurrent() || !state->value.isOk() || e.type == ValueType::Text)
            return {};
        bool ok = false;
        const double v = state->value.value.toDouble(&ok);
        return ok ? QVariant(v) : QVariant();
    }
    case ValueWithUnitRole:
        return ValueText::value(state, e);
    case ErrorValueRole:
        return state && state->isCurrent() && !state->value.isOk();
    case Qt::TextAlignmentRole:
        return index.column() == ValueColumn || index.column() == AgeColumn
                ? QVariant(Qt::AlignRight | Qt::AlignVCenter)
                : QVariant();
    case Qt::ToolTipRole: {
        // Whole texts first: a narrow column elides section, signal, value or status, and
        // the tooltip is where they are read in full.
        const QString label = QCoreApplication::translate("jumo::maps", e.label.toUtf8().constData());
        const QString section = QCoreApplication::translate("jumo::maps", e.group.toUtf8().constData());
        QStringList lines;
        if (index.column() == SectionColumn)
            lines << section << label;
        else
            lines << label << section;
        if (index.column() == ValueColumn && validity != Validity::Unknown)
            lines << tr("Value: %1").arg(ValueText::value(state, e));
        lines << tr("%1, register %2, %3").arg(e.id, formatAddress(e.address), valueTypeName(e.type));
        if (const QString note = ValueText::unitNote(e, *m_map); !note.isEmpty())
            lines << note;
        if (index.column() == StatusColumn || validity != Validity::Current || (state && !state->value.isOk()))
            lines << tr("Status: %1").arg(ValueText::status(state, *m_map, m_devices->clockMs()));
        if (validity == Validity::Unknown && state && state->hasValue())
            lines << tr("Last known value: %1, %2 s ago")
                             .arg(ValueFormat::withUnit(state->value, e))
                             .arg((m_devices->clockMs() - state->goodMs) / 1000);
        if (!e.notes.isEmpty())
            lines << e.notes;
        return lines.join(QLatin1Char('\n'));
    }
    case Qt::DisplayRole:
        break;
    default:
        return {};
    }

    switch (index.column()) {
    case SectionColumn:
        return QCoreApplication::translate("jumo::maps", e.group.toUtf8().constData());
    case LabelColumn:
        return QCoreApplication::translate("jumo::maps", e.label.toUtf8().constData());
    case ValueColumn:
        // Error values show as what they are, never as a number; an unknown value shows
        // no number at all.
        return ValueText::number(state, e);
    case UnitColumn:
        return ValueText::unit(e);
    case StatusColumn:
        return ValueText::status(state, *m_map, m_devices->clockMs());
    case AgeColumn:
        // In the language's way, as every other number: "2,5 s" in German.
        return age < 0 ? QString() : tr("%1 s").arg(QLocale().toString(age / 1000.0, 'f', 1));
    default:
        return {};
    }
}

QVariant LiveValuesModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case SectionColumn: return tr("Section");
    case LabelColumn: return tr("Signal");
    case ValueColumn: return tr("Value");
    case UnitColumn: return tr("Unit");
    case StatusColumn: return tr("Status");
    case AgeColumn: return tr("Age");
    default: return {};
    }
}

} // namespace jumo
