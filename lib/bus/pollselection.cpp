#include "bus/pollselection.h"

#include "protocol/familyregistry.h"
#include "protocol/registermap.h"

#include <QSet>

#include <algorithm>

namespace jumo {

namespace {

QStringList alarmEntries(const RegisterMap &map)
{
    QStringList ids;
    for (const RegisterEntry &e : map.entries()) {
        if (e.hasAlarmBits() && e.isReadable() && e.alias.isEmpty())
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
            ids = map.faceplateEntries();
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
