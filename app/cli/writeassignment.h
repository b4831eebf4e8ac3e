// One assignment of `jumoctl write`: a whole word (ENTRY=VALUE, which replaces every bit
// of a bit field) or some bits of a bit field (ENTRY.BIT=0|1, the other bits kept).
#pragma once

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>

#include <optional>

namespace jumo {

class RegisterMap;

class WriteAssignment
{
    Q_DECLARE_TR_FUNCTIONS(jumo::WriteAssignment)

public:
    QString entryId;
    QString value;                 // the whole-word form; empty for a bit change
    QHash<QString, bool> bits;     // bit id -> on; empty for the whole-word form

    bool isBitChange() const { return !bits.isEmpty(); }

    // Parses and checks the assignments before anything is sent. The bits of one entry
    // become one assignment, so they go out in one read-modify-write. A broadcast takes
    // whole words only (no device answers the read that keeps the other bits).
    // nullopt with the reason in *error.
    static std::optional<QList<WriteAssignment>> parse(const RegisterMap &map, const QStringList &texts, bool broadcast,
                                                       QString *error);
};

} // namespace jumo
