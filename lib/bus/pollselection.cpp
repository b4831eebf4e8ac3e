#include "bus/pollselection.h"

#include "protocol/familyregistry.h"
#include "protocol/registermap.h"

#include <QSet>

#include <algorithm>

namespace jumo {

namespace {

// "entry" or "entry.bit": the entry's id.
QString entryOf(const QString &reference)
{
    return reference.section(QLatin1Char('.'), 0, 0);
}

QStringList faceplateEntries(const RegisterMap &map)
{
    const FaceplateSpec &f = map.faceplate;
    QStringList ids = map.overview;
    ids << f.primary << f.programSegment << f.programSegments << f.programTimeLeft;
    for (const FaceplateValue &v : f.values)
        ids << v.entry << v.scaleFrom;
    for (const FaceplateState &s : f.modes)
        ids << entryOf(s.when);
    for (const FaceplateState &s : f.programStates)
        ids << entryOf(s.when);
    ids.removeAll(QString());
    return ids;
}

QStringList alarmEntries(const RegisterMap &map)
{
    QStringList ids;
    for (const RegisterEntry &e : map.entries()) {
        const bool alarm = std::any_of(e.bits.cbegin(), e.bits.cend(), [](const BitDefinition &b) {
            return !b.reserved && (b.kind == BitKind::Alarm || b.kind == BitKind::Warning);
        });
        if (alarm && e.isReadable() && e.alias.isEmpty())
            ids << e.id;
    }
    return ids;
}

} // namespace

std::optional<QStringList> PollSelection::expand(const RegisterMap &map, const QStringList &words, QString *error)
{
    QSet<QString> wanted;
    for (const QString &raw : words) {
        const QString word = raw.trimmed();
        QStringList ids;
        if (word == QLatin1String("faceplate")) {
            ids = faceplateEntries(map);
        } else if (word == QLatin1String("alarms")) {
            ids = alarmEntries(map);
        } else {
            const RegisterEntry *entry = map.entry(word);
            if (!entry) {
                if (error)
                    *error = tr("'%1' is no entry of %2 (jumoctl map %2 lists them) nor 'faceplate' or 'alarms'")
                                     .arg(word, map.family);
                return std::nullopt;
            }
            if (!entry->isReadable()) {
                if (error)
                    *error = tr("%1 '%2' cannot be read").arg(map.family, word);
                return std::nullopt;
            }
            if (entry->reserved) {
                if (error)
                    *error = tr("%1 '%2' is a reserve: it means nothing and is never published").arg(map.family, word);
                return std::nullopt;
            }
            ids << word;
        }
        for (const QString &id : std::as_const(ids)) {
            const RegisterEntry *entry = map.entry(id);
            if (entry && entry->isReadable() && !entry->reserved)
                wanted.insert(id);
        }
    }
    QStringList ordered;
    for (const RegisterEntry &e : map.entries()) {
        if (wanted.contains(e.id))
            ordered << e.id;
    }
    if (ordered.isEmpty()) {
        if (error)
            *error = tr("name at least one entry of %1 to poll").arg(map.family);
        return std::nullopt;
    }
    return ordered;
}

std::optional<PollSelection> PollSelection::parse(const QString &text, const FamilyRegistry &registry, QString *error)
{
    const qsizetype colon = text.indexOf(QLatin1Char(':'));
    if (colon <= 0) {
        if (error)
            *error = tr("'%1' is not FAMILY:ENTRY[,ENTRY...] (entries, 'faceplate' or 'alarms')").arg(text);
        return std::nullopt;
    }
    PollSelection selection;
    selection.family = text.left(colon).trimmed();
    const auto map = registry.family(selection.family);
    if (!map) {
        if (error)
            *error = tr("unknown family '%1' (families: %2)")
                             .arg(selection.family, registry.familyIds().join(QLatin1String(", ")));
        return std::nullopt;
    }
    const std::optional<QStringList> entries =
            expand(*map, text.mid(colon + 1).split(QLatin1Char(','), Qt::SkipEmptyParts), error);
    if (!entries)
        return std::nullopt;
    selection.entries = *entries;
    return selection;
}

} // namespace jumo
