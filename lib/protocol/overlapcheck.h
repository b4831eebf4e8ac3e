// Finds entries of a map whose words overlap, in O(n log n): the entries sorted by
// address are swept once, and each group of overlapping entries is reported once, with
// a cap on the names in a message and on the number of messages, so that a file of
// thousands of entries at one address costs a few lines, not millions.
#pragma once

#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QPair>

namespace jumo {

class OverlapCheck
{
    Q_DECLARE_TR_FUNCTIONS(jumo::MapLoader)

public:
    static constexpr int maxNamesPerGroup = 5;
    static constexpr int maxGroups = 20;

    // (where, problem) per overlapping group. An entry and its aliases may overlap.
    static QList<QPair<QString, QString>> check(const QList<RegisterEntry> &entries);
};

} // namespace jumo
