#include "models/parametereditmodel.h"

#include "bus/valuetext.h"
#include "protocol/valuecodec.h"
#include "protocol/valueformat.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>

namespace jumo {

namespace {

QString translated(const QString &text)
{
    return QCoreApplication::translate("jumo::maps", text.toUtf8().constData());
}

// What the type can hold at all, for whole-number types.
std::optional<std::pair<double, double>> typeBounds(ValueType type)
{
    switch (type) {
    case ValueType::Int16:
        return std::pair{-32768.0, 32767.0};
    case ValueType::UInt16:
        return std::pair{0.0, 65535.0};
    case ValueType::Int32:
        return std::pair{double(std::numeric_limits<qint32>::min()), double(std::numeric_limits<qint32>::max())};
    case ValueType::UInt32:
        return std::pair{0.0, double(std::numeric_limits<quint32>::max())};
    default:
        return std::nullopt;
    }
}

// As the device stores them, except that 0 and -0 are one value.
bool sameWords(const RegisterEntry &e, const RegisterMap &map, const QList<quint16> &a, const QList<quint16> &b)
{
    if (a == b)
        return true;
    if (e.type != ValueType::Float || a.size() != 2 || b.size() != 2)
        return false;
    const WordOrder order = map.protocol.floatWordOrder;
    return ValueCodec::decodeFloat(a[0], a[1], order) == ValueCodec::decodeFloat(b[0], b[1], order);
}

const QChar changedMark(0x25CF);   // a black circle: the row has a change, bold is not all that says so

} // namespace

ParameterEditModel::ParameterEditModel(Bus *bus, DeviceId device, QObject *parent)
    : QAbstractItemModel(parent), m_bus(bus), m_device(device), m_map(bus->deviceMap(device))
{
    if (m_map) {
        for (const RegisterEntry &e : m_map->entries()) {
            if (!isListed(e))
                continue;
            auto group = std::find_if(m_groups.begin(), m_groups.end(), [&](const Group &g) { return g.title == e.group; });
            if (group == m_groups.end()) {
                m_groups.append(Group{e.group, {}});
                group = m_groups.end() - 1;
            }
            group->entries << &e;
        }
        std::stable_sort(m_groups.begin(), m_groups.end(),
                         [](const Group &a, const Group &b) { return sectionBefore(a.title, b.title); });
        for (int g = 0; g < m_groups.size(); ++g) {
            for (int r = 0; r < m_groups[g].entries.size(); ++r)
                m_position.insert(m_groups[g].entries[r]->id, {g, r});
        }
    }
    connect(m_bus, &Bus::entriesUpdated, this, &ParameterEditModel::onEntriesUpdated);
}

bool ParameterEditModel::isListed(const RegisterEntry &e)
{
    return e.control == QLatin1String("parameter") && e.isWritable() && !e.reserved;
}

QModelIndex ParameterEditModel::index(int row, int column, const QModelIndex &parent) const
{
    if (column < 0 || column >= ColumnCount || row < 0)
        return {};
    if (!parent.isValid())
        return row < m_groups.size() ? createIndex(row, column, quintptr(0)) : QModelIndex();
    if (parent.internalId() != 0 || parent.column() != 0 || parent.row() >= m_groups.size())
        return {};
    return row < m_groups[parent.row()].entries.size() ? createIndex(row, column, quintptr(parent.row() + 1))
                                                       : QModelIndex();
}

QModelIndex ParameterEditModel::parent(const QModelIndex &child) const
{
    if (!child.isValid() || child.internalId() == 0)
        return {};
    return createIndex(int(child.internalId() - 1), 0, quintptr(0));
}

int ParameterEditModel::rowCount(const QModelIndex &parent) const
{
    if (!parent.isValid())
        return int(m_groups.size());
    if (parent.internalId() != 0 || parent.column() != 0)
        return 0;
    return int(m_groups.at(parent.row()).entries.size());
}

int ParameterEditModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

const RegisterEntry *ParameterEditModel::entry(const QString &id) const
{
    const auto it = m_position.constFind(id);
    return it == m_position.cend() ? nullptr : m_groups.at(it->first).entries.at(it->second);
}

QModelIndex ParameterEditModel::indexOf(const QString &id, int column) const
{
    const auto it = m_position.constFind(id);
    if (it == m_position.cend())
        return {};
    return createIndex(it->second, column, quintptr(it->first + 1));
}

QStringList ParameterEditModel::entryIds() const
{
    QStringList ids;
    for (const Group &g : m_groups) {
        for (const RegisterEntry *e : g.entries)
            ids << e->id;
    }
    return ids;
}

int ParameterEditModel::eepromCount() const
{
    int count = 0;
    for (const Group &g : m_groups)
        count += int(std::count_if(g.entries.cbegin(), g.entries.cend(),
                                   [](const RegisterEntry *e) { return e->storage == Storage::Eeprom; }));
    return count;
}

QStringList ParameterEditModel::changedIds() const
{
    QStringList ids;
    for (const QString &id : entryIds()) {
        if (m_changes.contains(id))
            ids << id;
    }
    return ids;
}

QString ParameterEditModel::displayOf(const RegisterEntry &e, const QString &exact) const
{
    const EncodeResult encoded = ValueCodec::encode(e, *m_map, exact);
    if (!encoded.ok())
        return exact;
    const DecodedValue v = ValueCodec::decode(e, *m_map, encoded.words);
    if (e.type == ValueType::Bool)
        return v.value.toBool() ? tr("On") : tr("Off");
    // Every digit that goes out: 12.34 stays 12.34 where the device shows one decimal.
    if (isNumeric(e.type) && v.isOk())
        return ValueFormat::limit(v.value.toDouble(), e);
    return ValueFormat::value(v, e);   // bit fields by their labels
}

QString ParameterEditModel::newValueText(const QString &id) const
{
    const RegisterEntry *e = entry(id);
    return e && m_changes.contains(id) ? displayOf(*e, m_changes.value(id)) : QString();
}

QString ParameterEditModel::deviceValueText(const QString &id) const
{
    const RegisterEntry *e = entry(id);
    if (!e)
        return {};
    if (!e->isReadable())
        return tr("write-only");
    const EntryState *state = m_bus->entryState(m_device, id);
    // The value just read back is the device's value now, not the poll's of a moment ago.
    if (const DecodedValue *readBack = newerReadBack(id, state))
        return ValueFormat::value(*readBack, *e);
    // A value that is not current is never shown as if it were.
    if (ValueText::validity(state) == Validity::Stale)
        return tr("%1 (stale)").arg(ValueText::number(state, *e));
    return ValueText::number(state, *e);
}

const DecodedValue *ParameterEditModel::newerReadBack(const QString &id, const EntryState *state) const
{
    const auto it = m_results.constFind(id);
    if (it == m_results.cend() || it->readBackMs < 0 || (state && state->hasValue() && state->goodMs > it->readBackMs))
        return nullptr;
    return &it->readBackValue;
}

QString ParameterEditModel::editText(const QString &id) const
{
    const RegisterEntry *e = entry(id);
    if (!e)
        return {};
    if (m_changes.contains(id)) {
        const QString exact = m_changes.value(id);
        return e->type == ValueType::Enum || e->type == ValueType::Bool ? exact : displayOf(*e, exact);
    }
    const EntryState *state = m_bus->entryState(m_device, id);
    if (!state || state->validity == Validity::Unknown || !state->hasValue() || !state->value.isOk())
        return {};
    if (e->type == ValueType::Enum || e->type == ValueType::Bool)
        return QString::number(state->value.value.toLongLong());
    if (isNumeric(e->type))
        return ValueFormat::limit(state->value.value.toDouble(), *e);
    return state->value.display;
}

QString ParameterEditModel::resultText(const QString &id) const
{
    const Result r = m_results.value(id);
    switch (r.state) {
    case WriteCommand::State::Idle:
        return r.message.isEmpty() ? QString() : tr("Not written: %1").arg(r.message);
    case WriteCommand::State::Pending:
        return tr("Writing...");
    case WriteCommand::State::Confirmed:
        return r.readBack.isEmpty() ? tr("Confirmed: %1").arg(r.message) : tr("Confirmed by read-back: %1").arg(r.readBack);
    case WriteCommand::State::Refused:
        return tr("Refused: %1").arg(r.message);
    case WriteCommand::State::Unknown:
        // Neither done nor refused: only the device can tell, and nothing was sent again.
        return tr("Unknown, check the device: %1").arg(r.message);
    }
    return {};
}

QVariant ParameterEditModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid())
        return {};
    if (index.internalId() == 0) {
        if (index.column() != NameColumn || (role != Qt::DisplayRole && role != Qt::ToolTipRole))
            return {};
        const Group &g = m_groups.at(index.row());
        const int changed = int(std::count_if(g.entries.cbegin(), g.entries.cend(),
                                              [this](const RegisterEntry *e) { return m_changes.contains(e->id); }));
        const QString title = translated(g.title);
        return changed ? tr("%1 (%n changed)", nullptr, changed).arg(title) : title;
    }
    const RegisterEntry &e = *m_groups.at(int(index.internalId() - 1)).entries.at(index.row());
    const EntryState *state = m_bus->entryState(m_device, e.id);
    const bool changed = m_changes.contains(e.id);

    switch (role) {
    case EntryIdRole:
        return e.id;
    case ValidityRole:
        return int(newerReadBack(e.id, state) ? Validity::Current : ValueText::validity(state));
    case ChangedRole:
        return changed;
    case WriteStateRole:
        return int(m_results.value(e.id).state);
    case ErrorValueRole:
        return state && state->isCurrent() && !state->value.isOk();
    case SearchTextRole:
        return QStringList{translated(e.label), e.label, e.id, formatAddress(e.address)}.join(QLatin1Char('\n'));
    case Qt::EditRole:
        return index.column() == NewValueColumn ? QVariant(editText(e.id)) : QVariant();
    case Qt::TextAlignmentRole:
        return index.column() == DeviceColumn || index.column() == NewValueColumn
                ? QVariant(Qt::AlignRight | Qt::AlignVCenter)
                : QVariant();
    case Qt::DisplayRole:
    case Qt::ToolTipRole:
        break;
    default:
        return {};
    }

    QString text;
    switch (index.column()) {
    case NameColumn:
        text = changed ? QStringLiteral("%1 %2").arg(changedMark, translated(e.label)) : translated(e.label);
        break;
    case DeviceColumn:
        text = deviceValueText(e.id);
        break;
    case NewValueColumn:
        text = newValueText(e.id);
        break;
    case UnitColumn:
        text = ValueText::unit(e);
        break;
    case StorageColumn:
        text = e.storage == Storage::Eeprom ? tr("EEPROM") : e.storage == Storage::Ram ? tr("RAM") : QString();
        break;
    case ResultColumn:
        text = resultText(e.id);
        break;
    default:
        break;
    }
    if (role == Qt::DisplayRole)
        return text;

    // Whole texts first: a narrow column elides, and the tooltip is where they are read in full.
    QStringList lines;
    switch (index.column()) {
    case NameColumn:
        lines << text << tr("%1, register %2, %3").arg(e.id, formatAddress(e.address), valueTypeName(e.type));
        if (changed)
            lines << tr("Changed: %1 waits to be written").arg(ValueFormat::joinUnit(newValueText(e.id), e.unit));
        if (!e.precondition.isEmpty())
            lines << tr("Precondition: %1").arg(translated(e.precondition));
        if (!e.notes.isEmpty())
            lines << e.notes;
        break;
    case DeviceColumn:
        if (!text.isEmpty())
            lines << text;
        if (e.isReadable()) {
            lines << tr("Status: %1").arg(ValueText::status(state, *m_map, m_bus->clockMs()));
            if (ValueText::validity(state) == Validity::Unknown && state && state->hasValue())
                lines << tr("Last known value: %1, %2 s ago")
                                 .arg(ValueFormat::withUnit(state->value, e))
                                 .arg((m_bus->clockMs() - state->goodMs) / 1000);
        } else {
            lines << tr("The device cannot report this value.");
        }
        break;
    case NewValueColumn:
        if (changed)
            lines << text << tr("Not written yet");
        break;
    case UnitColumn:
        lines << text << ValueText::unitNote(e, *m_map);
        break;
    case StorageColumn:
        if (e.storage == Storage::Eeprom)
            lines << text << tr("Stored in EEPROM: every write wears it (about 10,000 write cycles).");
        else if (e.storage == Storage::Ram)
            lines << text << tr("Kept in RAM: lost when the device is switched off.");
        break;
    case ResultColumn:
        lines << text;
        break;
    default:
        break;
    }
    lines.removeAll(QString());
    return lines.join(QLatin1Char('\n'));
}

bool ParameterEditModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::EditRole || index.column() != NewValueColumn || !index.isValid() || index.internalId() == 0)
        return false;
    return setNewValue(data(index, EntryIdRole).toString(), value.toString());
}

Qt::ItemFlags ParameterEditModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.internalId() == 0)
        return f;
    if (index.column() == NewValueColumn && !m_readOnly && !m_locked)
        f |= Qt::ItemIsEditable;
    return f | Qt::ItemNeverHasChildren;
}

QVariant ParameterEditModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case NameColumn: return tr("Parameter");
    case DeviceColumn: return tr("Device value");
    case NewValueColumn: return tr("New value");
    case UnitColumn: return tr("Unit");
    case StorageColumn: return tr("Storage");
    case ResultColumn: return tr("Last write");
    default: return {};
    }
}

const RegisterEntry *ParameterEditModel::editableEntry(const QString &id, QString *message) const
{
    QString why;
    const RegisterEntry *e = entry(id);
    if (!e)
        why = tr("'%1' is no parameter listed here").arg(id);
    else if (m_readOnly)
        why = tr("read-only mode: nothing is changed or written");
    else if (m_locked)
        why = tr("a write is under way: changes wait until it has ended");
    if (why.isEmpty())
        return e;
    if (message)
        *message = why;
    return nullptr;
}

bool ParameterEditModel::setNewValue(const QString &id, const QString &typed, QString *message)
{
    const RegisterEntry *e = editableEntry(id, message);
    if (!e)
        return false;
    const QString t = typed.trimmed();
    if (t.isEmpty()) {
        revert(id);
        return true;
    }
    QString exact = t;
    if (isNumeric(e->type)) {
        const std::optional<QString> number = ValueFormat::parseNumber(t);
        // Never handed on as typed: the codec would read "1.500" as 1.5.
        if (!number) {
            if (message)
                *message = tr("'%1' is no number that can be read one way only: write it without thousands separators")
                                   .arg(t);
            return false;
        }
        exact = *number;
    } else if (e->type == ValueType::Enum) {
        for (auto it = e->enumValues.cbegin(); it != e->enumValues.cend(); ++it) {
            if (translated(it.value()).compare(t, Qt::CaseInsensitive) == 0 || it.value().compare(t, Qt::CaseInsensitive) == 0)
                exact = QString::number(it.key());
        }
    } else if (e->type == ValueType::Bool) {
        if (t.compare(tr("On"), Qt::CaseInsensitive) == 0)
            exact = QStringLiteral("1");
        else if (t.compare(tr("Off"), Qt::CaseInsensitive) == 0)
            exact = QStringLiteral("0");
    }
    return takeValue(*e, exact, message);
}

bool ParameterEditModel::setExactValue(const QString &id, const QString &exact, QString *message)
{
    const RegisterEntry *e = editableEntry(id, message);
    if (!e)
        return false;
    return takeValue(*e, exact.trimmed(), message);
}

QString ParameterEditModel::rangeProblem(const RegisterEntry &e, double value, const QString &typed) const
{
    const QString label = translated(e.label);
    if (e.restoreValue && value == *e.restoreValue)
        return {};
    std::optional<double> lo = e.minimum;
    std::optional<double> hi = e.maximum;
    if (const auto bounds = typeBounds(e.type)) {
        if (value != std::floor(value))
            return tr("%1 is not a whole number: %2 takes whole numbers only").arg(typed, label);
        lo = std::max(lo.value_or(bounds->first), bounds->first);
        hi = std::min(hi.value_or(bounds->second), bounds->second);
    }
    if ((!lo || value >= *lo) && (!hi || value <= *hi))
        return {};
    QString range;
    if (lo && hi)
        range = tr("%1 to %2").arg(ValueFormat::limit(*lo, e), ValueFormat::limit(*hi, e));
    else if (lo)
        range = tr("%1 or more").arg(ValueFormat::limit(*lo, e));
    else
        range = tr("up to %1").arg(ValueFormat::limit(*hi, e));
    return tr("%1 is out of range: %2 takes %3").arg(typed, label, ValueFormat::joinUnit(range, e.unit));
}

bool ParameterEditModel::takeValue(const RegisterEntry &e, const QString &exact, QString *message)
{
    auto refuse = [message](const QString &why) {
        if (message)
            *message = why;
        return false;
    };
    if (isNumeric(e.type)) {
        bool ok = false;
        const double v = exact.toDouble(&ok);
        if (ok && std::isfinite(v)) {
            QLocale locale;
            locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
            const QString shown = locale.toString(v, 'g', QLocale::FloatingPointShortest);
            if (const QString problem = rangeProblem(e, v, shown); !problem.isEmpty())
                return refuse(problem);
        }
    }
    const EncodeResult encoded = ValueCodec::encode(e, *m_map, exact);
    if (!encoded.ok())
        return refuse(encoded.error);
    // The value the device holds now is no change: nothing to write, nothing to wear.
    const EntryState *state = m_bus->entryState(m_device, e.id);
    if (state && state->isCurrent() && state->value.isOk() && sameWords(e, *m_map, state->words, encoded.words)) {
        if (message)
            *message = tr("%1 already holds %2: no change").arg(translated(e.label), ValueFormat::joinUnit(displayOf(e, exact), e.unit));
        revert(e.id);
        return true;
    }
    if (message)
        message->clear();
    setChanged(e.id, exact);
    return true;
}

void ParameterEditModel::setChanged(const QString &id, const QString &exact)
{
    const bool added = !m_changes.contains(id);
    if (!added && m_changes.value(id) == exact && m_results.value(id).state == WriteCommand::State::Idle)
        return;
    m_changes.insert(id, exact);
    // The last write's outcome was about another value.
    m_results.remove(id);
    emitRow(id);
    if (added) {
        emitGroupTitle(id);
        emit changeCountChanged(changeCount());
    }
}

void ParameterEditModel::revert(const QString &id)
{
    const bool removed = m_changes.remove(id) > 0;
    const bool hadResult = m_results.remove(id) > 0;
    if (!removed && !hadResult)
        return;
    emitRow(id);
    if (removed) {
        emitGroupTitle(id);
        emit changeCountChanged(changeCount());
    }
}

void ParameterEditModel::discardAll()
{
    if (m_changes.isEmpty())
        return;
    for (const QString &id : m_changes.keys())
        m_results.remove(id);
    m_changes.clear();
    for (int g = 0; g < m_groups.size(); ++g) {
        const QModelIndex group = index(g, 0);
        emit dataChanged(group, group);
        emit dataChanged(index(0, 0, group), index(int(m_groups[g].entries.size()) - 1, ColumnCount - 1, group));
    }
    emit changeCountChanged(0);
}

void ParameterEditModel::setReadOnly(bool readOnly)
{
    m_readOnly = readOnly;
}

void ParameterEditModel::setLocked(bool locked)
{
    m_locked = locked;
}

void ParameterEditModel::setWriting(const QStringList &ids)
{
    for (const QString &id : ids) {
        m_results.insert(id, {WriteCommand::State::Pending, QString(), QString(), DecodedValue{}, -1});
        emitRow(id);
    }
}

void ParameterEditModel::setOutcome(const QString &id, const WriteOutcome &outcome)
{
    if (!entry(id))
        return;
    const WriteCommand::State state = WriteCommand::stateOf(outcome);
    const bool readBack = outcome.result == WriteOutcome::Result::Confirmed && outcome.readBack.isOk();
    m_results.insert(id, {state, outcome.message, readBack ? ValueFormat::withUnit(outcome.readBack, *entry(id)) : QString(),
                          readBack ? outcome.readBack : DecodedValue{}, readBack ? m_bus->clockMs() : -1});
    const bool confirmed = state == WriteCommand::State::Confirmed && m_changes.remove(id) > 0;
    emitRow(id);
    if (confirmed) {
        emitGroupTitle(id);
        emit changeCountChanged(changeCount());
    }
}

void ParameterEditModel::setNotWritten(const QString &id, const QString &reason)
{
    if (!entry(id))
        return;
    m_results.insert(id, {WriteCommand::State::Idle, reason, QString(), DecodedValue{}, -1});
    emitRow(id);
}

void ParameterEditModel::emitRow(const QString &id)
{
    const QModelIndex first = indexOf(id, 0);
    if (first.isValid())
        emit dataChanged(first, first.siblingAtColumn(ColumnCount - 1));
}

void ParameterEditModel::emitGroupTitle(const QString &id)
{
    const QModelIndex group = indexOf(id).parent();
    if (group.isValid())
        emit dataChanged(group, group);
}

void ParameterEditModel::onEntriesUpdated(DeviceId device, const QStringList &ids)
{
    if (device != m_device)
        return;
    // One signal per group the block touched, never one per cell.
    QHash<int, QPair<int, int>> spans;
    for (const QString &id : ids) {
        const auto it = m_position.constFind(id);
        if (it == m_position.cend())
            continue;
        auto span = spans.find(it->first);
        if (span == spans.end())
            spans.insert(it->first, {it->second, it->second});
        else
            *span = {std::min(span->first, it->second), std::max(span->second, it->second)};
    }
    for (auto it = spans.cbegin(); it != spans.cend(); ++it) {
        const QModelIndex group = index(it.key(), 0);
        emit dataChanged(index(it->first, DeviceColumn, group), index(it->second, DeviceColumn, group));
    }
}

} // namespace jumo
