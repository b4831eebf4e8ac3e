// Makes the steps a trend draws from what a query read: what held at the window's start
// moved there, repeated samples dropped, a value held past the store's limit without a
// sample ended as "not recorded", and, where there are more steps than the trend has
// room for, buckets of equal width (at most three points each: how the bucket starts,
// the other kind of state inside it, how it ends).
#pragma once

#include "history/historytypes.h"

#include <QList>

namespace jumo {

class TraceBuilder
{
public:
    struct Step
    {
        HistoryPoint point;
        // A raw sample (repeated every heartbeat while its value stays), or a one-minute
        // row (written only when something changed, so its value may hold for long).
        bool raw = true;
    };

    // steps in time order; the first may lie before fromMs (what held then). The last
    // step holds until endMs. bucketMs gets the width the steps were joined to, or 0.
    static QList<HistoryPoint> build(const QList<Step> &steps, qint64 fromMs, qint64 endMs, qint64 maxHoldMs,
                                     int maxPoints, qint64 *bucketMs);
};

} // namespace jumo
