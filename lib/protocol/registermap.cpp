#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <limits>
#include <array>
#include <utility>

namespace jumo {

namespace {

template<typename E, std::size_t N>
std::optional<E> lookup(const std::array<std::pair<E, const char *>, N> &table, const QString &name)
{
    for (const auto &[value, text] : table) {
        if (name == QLatin1String(text))
            return value;
    }
    return std::nullopt;
}

template<typename E, std::size_t N>
QString nameOf(const std::array<std::pair<E, const char *>, N> &table, E value)
{
    for (const auto &[candidate, text] : table) {
        if (candidate == value)
            return QString::fromLatin1(text);
    }
    return {};
}

constexpr std::array<std::pair<ValueType, const char *>, 9> valueTypeNames{{
    {ValueType::Float, "float"},   {ValueType::Int16, "int16"}, {ValueType::UInt16, "uint16"},
    {ValueType::Int32, "int32"},   {ValueType::UInt32, "uint32"}, {ValueType::Bool, "bool"},
    {ValueType::Enum, "enum"},     {ValueType::Bitfield, "bitfield"}, {ValueType::Text, "text"},
}};

constexpr std::array<std::pair<Access, const char *>, 3> accessNames{{
    {Access::Read, "R"}, {Access::Write, "W"}, {Access::ReadWrite, "RW"},
}};

constexpr std::array<std::pair<Storage, const char *>, 3> storageNames{{
    {Storage::None, ""}, {Storage::Ram, "RAM"}, {Storage::Eeprom, "EEPROM"},
}};

constexpr std::array<std::pair<BitKind, const char *>, 4> bitKindNames{{
    {BitKind::Alarm, "alarm"}, {BitKind::Warning, "warning"},
    {BitKind::Status, "status"}, {BitKind::Command, "command"},
}};

constexpr std::array<std::pair<PollClass, const char *>, 3> pollClassNames{{
    {PollClass::Alarm, "alarm"}, {PollClass::Live, "live"}, {PollClass::Setting, "setting"},
}};

// "entry" or "entry.bit": the entry's id.
QString entryOf(const QString &reference)
{
    return reference.section(QLatin1Char('.'), 0, 0);
}

constexpr std::array<std::pair<WordOrder, const char *>, 4> wordOrderNames{{
    {WordOrder::ABCD, "ABCD"}, {WordOrder::CDAB, "CDAB"},
    {WordOrder::BADC, "BADC"}, {WordOrder::DCBA, "DCBA"},
}};

} // namespace

std::optional<double> leadingNumber(const QString &text)
{
    qsizetype end = 0;
    while (end < text.size() && (text.at(end).isDigit() || (end > 0 && text.at(end) == QLatin1Char('.'))))
        ++end;
    if (end == 0)
        return std::nullopt;
    bool ok = false;
    const double value = text.left(end).toDouble(&ok);
    return ok ? std::optional<double>(value) : std::nullopt;
}

QList<int> sectionNumber(const QString &group)
{
    static const QRegularExpression number(QStringLiteral("^(\\d+(?:\\.\\d+)*)(?:\\s|$)"));
    const QRegularExpressionMatch m = number.match(group);
    if (!m.hasMatch())
        return {std::numeric_limits<int>::max()};
    QList<int> parts;
    for (const QString &p : m.captured(1).split(QLatin1Char('.')))
        parts << p.toInt();
    return parts;
}

bool sectionBefore(const QString &a, const QString &b)
{
    return sectionNumber(a) < sectionNumber(b);
}

QString formatAddress(quint16 address)
{
    return QLatin1String("0x") + QString::number(address, 16).toUpper().rightJustified(4, QLatin1Char('0'));
}

QString valueTypeName(ValueType type) { return nameOf(valueTypeNames, type); }

bool isNumeric(ValueType type)
{
    switch (type) {
    case ValueType::Float:
    case ValueType::Int16:
    case ValueType::UInt16:
    case ValueType::Int32:
    case ValueType::UInt32:
        return true;
    default:
        return false;
    }
}
std::optional<ValueType> valueTypeFromName(const QString &name) { return lookup(valueTypeNames, name); }
QString accessName(Access access) { return nameOf(accessNames, access); }
std::optional<Access> accessFromName(const QString &name) { return lookup(accessNames, name); }
QString storageName(Storage storage) { return nameOf(storageNames, storage); }
QString bitKindName(BitKind kind) { return nameOf(bitKindNames, kind); }
std::optional<BitKind> bitKindFromName(const QString &name) { return lookup(bitKindNames, name); }
QString pollClassName(PollClass pollClass) { return nameOf(pollClassNames, pollClass); }
std::optional<PollClass> pollClassFromName(const QString &name) { return lookup(pollClassNames, name); }

PollClass shownClass(PollClass pollClass)
{
    return pollClass == PollClass::Setting ? PollClass::Live : pollClass;
}
QString wordOrderName(WordOrder order) { return nameOf(wordOrderNames, order); }
std::optional<WordOrder> wordOrderFromName(const QString &name) { return lookup(wordOrderNames, name); }

DisplayPrecision DisplayPrecision::defaultForUnit(const QString &unit)
{
    // As an engineer writes them: voltages to a tenth, currents, power and resistance
    // measured to four significant digits (0.512 A, 19.99 A, 1838 W), percentages,
    // temperatures and angles to a tenth, mains frequency to a hundredth.
    static const QHash<QString, DisplayPrecision> byUnit{
        {QStringLiteral("V"), decimals(1)},          {QStringLiteral("mV"), decimals(2)},
        {QStringLiteral("A"), significant(4)},       {QStringLiteral("mA"), decimals(2)},
        {QStringLiteral("W"), significant(4)},       {QStringLiteral("kW"), significant(4)},
        {QStringLiteral("Ω"), significant(4)},       {QStringLiteral("%"), decimals(1)},
        {QStringLiteral("°C"), decimals(1)},         {QStringLiteral("°F"), decimals(1)},
        {QStringLiteral("K"), decimals(1)},          {QStringLiteral("°"), decimals(1)},
        {QStringLiteral("Hz"), decimals(2)},         {QStringLiteral("s"), decimals(1)},
        {QStringLiteral("min"), decimals(1)},        {QStringLiteral("h"), decimals(1)},
    };
    // No unit, or one set on the device: a process value, shown as the controllers'
    // own displays show it by default, to a tenth. Anything else: four digits.
    if (unit.isEmpty())
        return decimals(1);
    return byUnit.value(unit, significant(4));
}

QString DisplayPrecision::name() const
{
    return QStringLiteral("%1:%2").arg(kind == Kind::Decimals ? QLatin1String("decimals") : QLatin1String("significant"))
            .arg(digits);
}

int RegisterEntry::wordCount() const
{
    if (reservedWords > 0)
        return reservedWords;
    switch (type) {
    case ValueType::Float:
    case ValueType::Int32:
    case ValueType::UInt32:
        return 2;
    case ValueType::Text:
        return (textBytes + 1) / 2;
    default:
        return 1;
    }
}

bool RegisterEntry::isCommand() const
{
    if (type != ValueType::Bitfield || bits.isEmpty())
        return false;
    return std::all_of(bits.cbegin(), bits.cend(),
                       [](const BitDefinition &b) { return b.kind == BitKind::Command; });
}

bool RegisterEntry::hasAlarmBits() const
{
    return std::any_of(bits.cbegin(), bits.cend(), [](const BitDefinition &b) {
        return !b.reserved && (b.kind == BitKind::Alarm || b.kind == BitKind::Warning);
    });
}

const BitDefinition *RegisterEntry::bitById(const QString &bitId) const
{
    for (const BitDefinition &b : bits) {
        if (b.id == bitId)
            return &b;
    }
    return nullptr;
}

void RegisterMap::setEntries(QList<RegisterEntry> entries)
{
    std::stable_sort(entries.begin(), entries.end(),
                     [](const RegisterEntry &a, const RegisterEntry &b) { return a.address < b.address; });
    m_entries = std::move(entries);
    m_indexById.clear();
    for (qsizetype i = 0; i < m_entries.size(); ++i)
        m_indexById.insert(m_entries.at(i).id, i);
}

const RegisterEntry *RegisterMap::entry(const QString &id) const
{
    const auto it = m_indexById.constFind(id);
    return it == m_indexById.cend() ? nullptr : &m_entries.at(*it);
}

QStringList RegisterMap::faceplateEntries(bool scales) const
{
    const FaceplateSpec &f = faceplate;
    QStringList ids = overview;
    ids << f.primary << f.programSegment << f.programSegments << f.programTimeLeft;
    for (const FaceplateValue &v : f.values) {
        ids << v.entry;
        if (scales)
            ids << v.scaleFrom;
    }
    for (const FaceplateState &s : f.modes)
        ids << entryOf(s.when);
    for (const FaceplateState &s : f.programStates)
        ids << entryOf(s.when);
    ids.removeAll(QString());
    ids.removeDuplicates();
    ids.removeIf([this](const QString &id) {
        const RegisterEntry *e = entry(id);
        return !e || !e->isReadable();
    });
    return ids;
}

PollClass RegisterMap::derivePollClass(const RegisterEntry &e) const
{
    if (e.pollOverride)
        return *e.pollOverride;
    if (e.hasAlarmBits())
        return PollClass::Alarm;
    // What the faceplate names as the device's mode or its program's state is read as
    // often as its alarms: an operator acts on it.
    for (const QList<FaceplateState> *states : {&faceplate.modes, &faceplate.programStates}) {
        for (const FaceplateState &s : *states) {
            if (entryOf(s.when) == e.id)
                return PollClass::Alarm;
        }
    }
    // A writable value changes only when somebody writes it, sets it on the front panel
    // or a program moves it; identity words and texts never change on their own.
    if (e.isWritable() || e.type == ValueType::Text || e.reserved || identity.contains(e.id))
        return PollClass::Setting;
    return PollClass::Live;
}

void RegisterMap::assignPollClasses()
{
    for (RegisterEntry &e : m_entries)
        e.pollClass = derivePollClass(e);
}

const RegisterEntry *RegisterMap::entryAt(quint16 address) const
{
    // Entries are sorted by address and do not overlap (aliases aside), so the
    // candidate is the last entry starting at or before the address.
    auto it = std::upper_bound(m_entries.cbegin(), m_entries.cend(), address,
                               [](quint16 a, const RegisterEntry &e) { return a < e.address; });
    while (it != m_entries.cbegin()) {
        --it;
        if (!it->alias.isEmpty())
            continue;
        return address <= it->lastAddress() ? &*it : nullptr;
    }
    return nullptr;
}

QString RegisterMap::displayName() const
{
    return QCoreApplication::translate("jumo::maps", name.toUtf8().constData());
}

QString RegisterMap::exceptionMeaning(int code) const
{
    const auto it = exceptions.constFind(code);
    // The Modbus specification gives 10 and 11 to gateways: no family documents them,
    // because a device never sends them.
    if (it == exceptions.cend() && code == 0x0A)
        return QCoreApplication::translate("jumo::RegisterMap",
                                           "the gateway's path to the device is unavailable (sent by the gateway, "
                                           "the request did not reach the device)");
    if (it == exceptions.cend() && code == 0x0B)
        return QCoreApplication::translate("jumo::RegisterMap",
                                           "the device behind the gateway did not respond (sent by the gateway)");
    if (it == exceptions.cend())
        return QCoreApplication::translate("jumo::RegisterMap", "exception %1 (not documented for this family)").arg(code);
    return QCoreApplication::translate("jumo::maps", it->toUtf8().constData());
}

} // namespace jumo
