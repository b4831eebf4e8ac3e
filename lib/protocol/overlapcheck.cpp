#include "protocol/overlapcheck.h"

#include <QSet>

#include <algorithm>

namespace jumo {

namespace {

// Entries whose word ranges chain into one another.
struct Group
{
    QList<const RegisterEntry *> members;
    int last = -1;   // the highest word address of any member

    // One entry and aliases of it: overlapping on purpose.
    bool isAliasing() const
    {
        const RegisterEntry *owner = nullptr;
        QSet<QString> aliasTargets;
        for (const RegisterEntry *e : members) {
            if (!e->alias.isEmpty()) {
                aliasTargets.insert(e->alias);
            } else if (owner) {
                return false;
            } else {
                owner = e;
            }
        }
        return owner && aliasTargets.size() == 1 && aliasTargets.contains(owner->id);
    }
};

QString describe(const RegisterEntry *e)
{
    return OverlapCheck::tr("'%1' (%2..%3)").arg(e->id, formatAddress(e->address), formatAddress(e->lastAddress()));
}

} // namespace

QList<QPair<QString, QString>> OverlapCheck::check(const QList<RegisterEntry> &entries)
{
    QList<const RegisterEntry *> sorted;
    sorted.reserve(entries.size());
    for (const RegisterEntry &e : entries)
        sorted << &e;
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const RegisterEntry *a, const RegisterEntry *b) { return a->address < b->address; });

    QList<QPair<QString, QString>> problems;
    int groupsFound = 0;
    auto report = [&](const Group &group) {
        if (group.members.size() < 2 || group.isAliasing())
            return;
        if (++groupsFound > maxGroups)
            return;
        // Named after the first entry that runs into an earlier one, as a user looks for it.
        const RegisterEntry *second = group.members.at(1);
        QStringList names;
        for (qsizetype i = 0; i < group.members.size() && i < maxNamesPerGroup; ++i) {
            if (group.members.at(i) != second)
                names << describe(group.members.at(i));
        }
        QString problem = tr("words %1..%2 overlap entry %3")
                                  .arg(formatAddress(second->address), formatAddress(second->lastAddress()),
                                       names.join(QStringLiteral(", ")));
        if (group.members.size() > maxNamesPerGroup)
            problem += tr(" and %n more entries", nullptr, int(group.members.size() - maxNamesPerGroup));
        problems << qMakePair(tr("entry '%1' (%2)").arg(second->id, formatAddress(second->address)), problem);
    };

    Group group;
    for (const RegisterEntry *e : std::as_const(sorted)) {
        if (int(e->address) > group.last) {
            report(group);
            group = Group();
        }
        group.members << e;
        group.last = std::max(group.last, int(e->address) + e->wordCount() - 1);
    }
    report(group);
    if (groupsFound > maxGroups)
        problems << qMakePair(QString(), tr("%n more group(s) of overlapping entries not listed", nullptr,
                                            groupsFound - maxGroups));
    return problems;
}

} // namespace jumo
