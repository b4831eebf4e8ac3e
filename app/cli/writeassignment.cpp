#include "writeassignment.h"

#include "protocol/bitwrite.h"
#include "protocol/registermap.h"
#include "protocol/valuecodec.h"

#include <algorithm>

namespace jumo {

std::optional<QList<WriteAssignment>> WriteAssignment::parse(const RegisterMap &map, const QStringList &texts,
                                                             bool broadcast, QString *error)
{
    auto refuse = [error](const QString &text) {
        *error = text;
        return std::nullopt;
    };
    QList<WriteAssignment> out;
    auto assignmentOf = [&out](const QString &entryId) -> WriteAssignment & {
        for (WriteAssignment &a : out) {
            if (a.entryId == entryId)
                return a;
        }
        out.append(WriteAssignment{entryId, {}, {}});
        return out.last();
    };

    for (const QString &text : texts) {
        const qsizetype eq = text.indexOf(QLatin1Char('='));
        if (eq <= 0)
            return refuse(tr("'%1' is not ID=VALUE or ID.BIT=0|1").arg(text));
        const QString target = text.left(eq);
        const QString value = text.mid(eq + 1);
        const QString entryId = target.section(QLatin1Char('.'), 0, 0);
        const RegisterEntry *entry = map.entry(entryId);
        if (!entry)
            return refuse(tr("'%1' is not an entry of %2").arg(entryId, map.family));
        const bool bitForm = target.contains(QLatin1Char('.'));
        const bool known = std::any_of(out.cbegin(), out.cend(), [&entryId](const WriteAssignment &a) {
            return a.entryId == entryId;
        });
        if (known && assignmentOf(entryId).isBitChange() != bitForm)
            return refuse(tr("'%1' is given both whole and by bits: give one or the other").arg(entryId));

        if (!bitForm) {
            if (known)   // the second would report the first one's old value as its own
                return refuse(tr("'%1' is given twice").arg(entryId));
            // A bad value is refused before the line is opened: nothing is sent for a typo.
            const EncodeResult encoded = ValueCodec::encode(*entry, map, value);
            if (!encoded.ok())
                return refuse(encoded.error);
            out.append(WriteAssignment{entryId, value, {}});
            continue;
        }
        if (broadcast)
            return refuse(tr("'%1': a broadcast is not answered, so the bits it should keep cannot be read; "
                             "write the whole word").arg(text));
        const QString bitId = target.section(QLatin1Char('.'), 1);
        const std::optional<bool> on = BitWrite::parseState(value);
        if (!on)
            return refuse(tr("'%1' is not a bit state for '%2': give 0, 1, on, off, true or false").arg(value, target));
        WriteAssignment &assignment = assignmentOf(entryId);
        if (const auto it = assignment.bits.constFind(bitId); it != assignment.bits.cend() && *it != *on)
            return refuse(tr("'%1' is given twice, on and off").arg(target));
        assignment.bits.insert(bitId, *on);
    }

    for (const WriteAssignment &a : std::as_const(out)) {
        if (!a.isBitChange())
            continue;
        const RegisterEntry &entry = *map.entry(a.entryId);
        QString why;
        if (!BitWrite::make(map, entry, a.bits, &why)) {
            const auto command = std::find_if(entry.bits.cbegin(), entry.bits.cend(),
                                              [](const BitDefinition &b) { return !b.reserved; });
            if (entry.isAction() && command != entry.bits.cend())
                why += QLatin1Char('\n') + tr("send a command as %1=BIT, e.g. %1=%2; it is sent once")
                                                   .arg(entry.id, command->id);
            return refuse(why);
        }
    }
    return out;
}

} // namespace jumo
