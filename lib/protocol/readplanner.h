// Plans the read requests for a set of wanted entries of one device: as few requests as
// the family's word limit allows, bridging gaps only through defined readable registers
// and, where the line's wire time is known, only gaps that cost less than a request.
#pragma once

#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QList>
#include <QStringList>

namespace jumo {

struct ReadBlock
{
    quint16 start = 0;
    quint16 count = 0;
    QList<const RegisterEntry *> entries;   // the wanted entries inside, in address order
    PollClass pollClass = PollClass::Live;  // what the entries are read as
    bool shown = false;                     // live values a view shows: read before the others

    quint16 end() const { return quint16(start + count - 1); }
};

struct ReadPlan
{
    QList<ReadBlock> blocks;
    QStringList errors;   // wanted ids that cannot be read, with the reason

    int totalWords() const;
};

class ReadPlanner
{
    Q_DECLARE_TR_FUNCTIONS(jumo::ReadPlanner)

public:
    // Plans the given entries (ids); an empty list means every readable entry.
    static ReadPlan plan(const RegisterMap &map, const QStringList &ids = {});
    // maxGapWords: the most unwanted words read through between two wanted entries
    // (-1: any, within the word limit).
    static ReadPlan plan(const RegisterMap &map, QList<const RegisterEntry *> wanted, int maxGapWords = -1);
};

} // namespace jumo
