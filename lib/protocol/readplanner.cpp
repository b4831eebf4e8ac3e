#include "protocol/readplanner.h"

#include <QCoreApplication>
#include <QHash>

#include <algorithm>

namespace jumo {

int ReadPlan::totalWords() const
{
    int words = 0;
    for (const ReadBlock &b : blocks)
        words += b.count;
    return words;
}

ReadPlan ReadPlanner::plan(const RegisterMap &map, const QStringList &ids)
{
    QList<const RegisterEntry *> wanted;
    ReadPlan failed;
    if (ids.isEmpty()) {
        for (const RegisterEntry &e : map.entries()) {
            if (e.isReadable() && e.alias.isEmpty())   // an alias repeats words read anyway
                wanted << &e;
        }
    } else {
        for (const QString &id : ids) {
            if (const RegisterEntry *e = map.entry(id))
                wanted << e;
            else
                failed.errors << tr("'%1' is not an entry of %2").arg(id, map.family);
        }
    }
    ReadPlan result = plan(map, wanted);
    result.errors = failed.errors + result.errors;
    return result;
}

ReadPlan ReadPlanner::plan(const RegisterMap &map, QList<const RegisterEntry *> wanted, int maxGapWords)
{
    ReadPlan result;

    // Runs of contiguous, readable, defined words; a request never leaves its run.
    QHash<quint16, int> runOf;
    int run = -1;
    int previousEnd = -2;
    bool previousReadable = false;
    for (const RegisterEntry &e : map.entries()) {
        if (!e.alias.isEmpty())
            continue;
        if (!e.isReadable()) {
            previousReadable = false;
            previousEnd = e.lastAddress();
            continue;
        }
        if (!previousReadable || int(e.address) != previousEnd + 1)
            ++run;
        for (int a = e.address; a <= e.lastAddress(); ++a)
            runOf.insert(quint16(a), run);
        previousReadable = true;
        previousEnd = e.lastAddress();
    }

    std::sort(wanted.begin(), wanted.end(), [](const RegisterEntry *a, const RegisterEntry *b) {
        return a->address != b->address ? a->address < b->address : a->wordCount() > b->wordCount();
    });
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());

    const int limit = map.protocol.effectiveMaxReadWords();
    ReadBlock current;
    int currentRun = -1;
    auto flush = [&] {
        if (current.count > 0)
            result.blocks << current;
        current = ReadBlock();
    };

    for (const RegisterEntry *e : std::as_const(wanted)) {
        if (!e->isReadable()) {
            result.errors << tr("'%1' (%2) is write-only").arg(e->id, formatAddress(e->address));
            continue;
        }
        const int firstRun = runOf.value(e->address, -1);
        if (firstRun < 0 || runOf.value(e->lastAddress(), -1) != firstRun) {
            result.errors << tr("'%1' (%2) spans words that are not all readable").arg(e->id, formatAddress(e->address));
            continue;
        }
        if (e->wordCount() > limit) {
            result.errors << tr("'%1' (%2) has %3 words, more than the %4 words one read may take")
                                     .arg(e->id, formatAddress(e->address))
                                     .arg(e->wordCount())
                                     .arg(limit);
            continue;
        }
        const int gap = int(e->address) - int(current.end()) - 1;
        if (current.count > 0 && firstRun == currentRun && (maxGapWords < 0 || gap <= maxGapWords)) {
            const int newEnd = std::max<int>(current.end(), e->lastAddress());
            if (newEnd - current.start + 1 <= limit) {
                current.count = quint16(newEnd - current.start + 1);
                current.entries << e;
                continue;
            }
        }
        flush();
        current.start = e->address;
        current.count = quint16(e->wordCount());
        current.entries << e;
        currentRun = firstRun;
    }
    flush();
    return result;
}

} // namespace jumo
