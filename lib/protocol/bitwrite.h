// A change of some bits of a bit field, and the word that carries it: every other bit
// keeps the state the device reports (the word itself when it is readable; for a
// write-only word, the bits its map names as their state source) and the activation bit
// is added. A word whose unchanged bits cannot be read can only be written whole.
#pragma once

#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QHash>
#include <QList>

#include <optional>

namespace jumo {

class BitWrite
{
    Q_DECLARE_TR_FUNCTIONS(jumo::BitWrite)

public:
    // Checks the change (bit id -> on). On a refusal, nullopt and the reason in *error.
    static std::optional<BitWrite> make(const RegisterMap &map, const RegisterEntry &entry,
                                        const QHash<QString, bool> &changes, QString *error);
    // Parses "bit=0|1" assignments as the CLI and scripts give them.
    static std::optional<bool> parseState(const QString &text);

    const RegisterEntry &entry() const { return *m_entry; }
    const QHash<QString, bool> &changes() const { return m_changes; }
    // The mask of the bits that change.
    quint16 changedMask() const;
    // The entries to read just before the write: the word itself, or the state sources of
    // the bits that keep their state. Empty when the change names every bit.
    QList<const RegisterEntry *> sources() const;
    // The word to send, from the words of sources() just read (entry id -> words).
    quint16 compose(const QHash<QString, QList<quint16>> &sourceWords) const;
    // The entries that report the changed bits afterwards (empty: nothing reports them).
    QList<const RegisterEntry *> reporters() const;
    // Whether the words read back from reporters() show every changed bit as asked.
    bool shows(const QHash<QString, QList<quint16>> &reportedWords) const;
    // "digital_output=1, external_inhibit_input=0", in bit order.
    QString describe() const;

    // Where the device reports a bit of a bit field: (entry, bit), or nulls when nothing
    // reports it (a write-only word without a state source).
    static std::pair<const RegisterEntry *, const BitDefinition *> reportOf(const RegisterMap &map,
                                                                             const RegisterEntry &entry,
                                                                             const BitDefinition &bit);
    // The bits an operator switches one by one: not reserved, one bit wide, not the
    // activation bit.
    static QList<const BitDefinition *> switchableBits(const RegisterEntry &entry);
    // Whether each switchable bit can be changed alone (the others are reported).
    static bool canSwitchBits(const RegisterMap &map, const RegisterEntry &entry);

private:
    BitWrite(const RegisterMap &map, const RegisterEntry &entry, QHash<QString, bool> changes)
        : m_map(&map), m_entry(&entry), m_changes(std::move(changes))
    {
    }
    std::pair<const RegisterEntry *, const BitDefinition *> reportOf(const BitDefinition &bit) const
    {
        return reportOf(*m_map, *m_entry, bit);
    }
    bool isActivation(const BitDefinition &bit) const;

    const RegisterMap *m_map;
    const RegisterEntry *m_entry;
    QHash<QString, bool> m_changes;
};

} // namespace jumo
