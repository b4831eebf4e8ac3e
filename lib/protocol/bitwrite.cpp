#include "protocol/bitwrite.h"

#include <algorithm>

namespace jumo {

std::optional<bool> BitWrite::parseState(const QString &text)
{
    const QString t = text.trimmed().toLower();
    if (t == QLatin1String("1") || t == QLatin1String("on") || t == QLatin1String("true"))
        return true;
    if (t == QLatin1String("0") || t == QLatin1String("off") || t == QLatin1String("false"))
        return false;
    return std::nullopt;
}

bool BitWrite::isActivation(const BitDefinition &bit) const
{
    return m_entry->activationMask && bit.mask() == *m_entry->activationMask;
}

std::pair<const RegisterEntry *, const BitDefinition *> BitWrite::reportOf(const RegisterMap &map,
                                                                          const RegisterEntry &entry,
                                                                          const BitDefinition &bit)
{
    if (entry.isReadable())
        return {&entry, &bit};
    if (bit.stateFrom.isEmpty())
        return {nullptr, nullptr};
    const RegisterEntry *source = map.entry(bit.stateFrom.section(QLatin1Char('.'), 0, 0));
    const BitDefinition *sourceBit = source ? source->bitById(bit.stateFrom.section(QLatin1Char('.'), 1)) : nullptr;
    return sourceBit ? std::pair{source, sourceBit} : std::pair<const RegisterEntry *, const BitDefinition *>{};
}

QList<const BitDefinition *> BitWrite::switchableBits(const RegisterEntry &entry)
{
    QList<const BitDefinition *> out;
    for (const BitDefinition &b : entry.bits) {
        if (!b.reserved && b.width == 1 && !(entry.activationMask && b.mask() == *entry.activationMask))
            out << &b;
    }
    return out;
}

bool BitWrite::canSwitchBits(const RegisterMap &map, const RegisterEntry &entry)
{
    if (entry.type != ValueType::Bitfield || !entry.isWritable() || entry.isAction())
        return false;
    for (const BitDefinition &b : entry.bits) {
        const bool activation = entry.activationMask && b.mask() == *entry.activationMask;
        if (!b.reserved && !activation && !reportOf(map, entry, b).first)
            return false;
    }
    return true;
}

std::optional<BitWrite> BitWrite::make(const RegisterMap &map, const RegisterEntry &entry,
                                       const QHash<QString, bool> &changes, QString *error)
{
    auto refuse = [error](const QString &text) {
        if (error)
            *error = text;
        return std::nullopt;
    };
    if (entry.type != ValueType::Bitfield || !entry.isWritable())
        return refuse(tr("'%1' is not a writable bit field").arg(entry.id));
    if (entry.isAction())
        return refuse(tr("'%1' is a command word: its bits are actions, sent one at a time, not states to keep")
                              .arg(entry.id));
    if (changes.isEmpty())
        return refuse(tr("no bit of '%1' given").arg(entry.id));
    BitWrite change(map, entry, changes);
    for (auto it = changes.cbegin(); it != changes.cend(); ++it) {
        const BitDefinition *b = entry.bitById(it.key());
        if (!b || b->reserved)
            return refuse(tr("'%1' is not a bit of '%2'").arg(it.key(), entry.id));
        if (b->width != 1)
            return refuse(tr("'%1.%2' is %3 bits wide; write the whole word").arg(entry.id, it.key()).arg(b->width));
        if (change.isActivation(*b))
            return refuse(tr("'%1.%2' is the activation bit, which every write sets").arg(entry.id, it.key()));
    }
    QStringList unknown;
    for (const BitDefinition &b : entry.bits) {
        if (b.reserved || change.isActivation(b) || changes.contains(b.id))
            continue;
        if (!change.reportOf(b).first)
            unknown << b.id;
    }
    if (!unknown.isEmpty())
        return refuse(tr("the device does not report the state of %1 of '%2', which a write of the word sets too: "
                         "give every bit, or write the whole word")
                              .arg(unknown.join(QStringLiteral(", ")), entry.id));
    return change;
}

quint16 BitWrite::changedMask() const
{
    quint16 mask = 0;
    for (auto it = m_changes.cbegin(); it != m_changes.cend(); ++it)
        mask |= m_entry->bitById(it.key())->mask();
    return mask;
}

QList<const RegisterEntry *> BitWrite::sources() const
{
    QList<const RegisterEntry *> out;
    for (const BitDefinition &b : m_entry->bits) {
        if (b.reserved || isActivation(b) || m_changes.contains(b.id))
            continue;
        const RegisterEntry *source = reportOf(b).first;
        if (source && !out.contains(source))
            out << source;
    }
    // A readable word is read even when every bit changes: its reserved bits are kept.
    if (m_entry->isReadable() && out.isEmpty())
        out << m_entry;
    return out;
}

quint16 BitWrite::compose(const QHash<QString, QList<quint16>> &sourceWords) const
{
    // A readable word keeps what it holds (reserved bits included); a write-only word
    // starts from nothing, every defined bit set from its source or the change.
    quint16 word = m_entry->isReadable() ? sourceWords.value(m_entry->id).value(0) : 0;
    for (const BitDefinition &b : m_entry->bits) {
        if (b.reserved || isActivation(b))
            continue;
        bool on = false;
        if (const auto c = m_changes.constFind(b.id); c != m_changes.cend()) {
            on = *c;
        } else {
            const auto [source, sourceBit] = reportOf(b);
            if (!source)
                continue;
            on = sourceWords.value(source->id).value(0) & sourceBit->mask();
        }
        word = on ? quint16(word | b.mask()) : quint16(word & ~b.mask());
    }
    if (m_entry->activationMask)
        word |= *m_entry->activationMask;
    return word;
}

QList<const RegisterEntry *> BitWrite::reporters() const
{
    QList<const RegisterEntry *> out;
    for (auto it = m_changes.cbegin(); it != m_changes.cend(); ++it) {
        const RegisterEntry *source = reportOf(*m_entry->bitById(it.key())).first;
        if (source && !out.contains(source))
            out << source;
    }
    return out;
}

bool BitWrite::shows(const QHash<QString, QList<quint16>> &reportedWords) const
{
    for (auto it = m_changes.cbegin(); it != m_changes.cend(); ++it) {
        const auto [source, sourceBit] = reportOf(*m_entry->bitById(it.key()));
        if (!source)
            continue;
        const bool on = reportedWords.value(source->id).value(0) & sourceBit->mask();
        if (on != *it)
            return false;
    }
    return true;
}

QString BitWrite::describe() const
{
    QStringList parts;
    for (const BitDefinition &b : m_entry->bits) {
        if (const auto c = m_changes.constFind(b.id); c != m_changes.cend())
            parts << QStringLiteral("%1=%2").arg(b.id).arg(*c ? 1 : 0);
    }
    return parts.join(QStringLiteral(", "));
}

} // namespace jumo
