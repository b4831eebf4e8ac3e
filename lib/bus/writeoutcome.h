// How a write ended: confirmed by read-back, accepted without one, refused and why, or
// explicitly unknown when its answer was lost. Every write ends in exactly one of these.
#pragma once

#include "protocol/valuecodec.h"

#include <QMetaType>
#include <QString>

namespace jumo {

struct WriteOutcome
{
    enum class Result {
        Confirmed,      // written and read back with the same value
        Accepted,       // the device acknowledged it; the entry cannot be read back
        Mismatch,       // acknowledged, but the read-back shows another value
        Refused,        // the device answered with an exception: nothing was changed
        Unknown,        // the answer was lost: the device may or may not have done it
        Unverified,     // acknowledged, but the read-back could not be made
        NotSent,        // nothing reached the line (not connected, closed, prerequisite read failed)
        ReadOnlyMode,   // refused before reaching the line: read-only mode
        Invalid,        // refused before reaching the line: value, entry or range
    };

    Result result = Result::NotSent;
    QString message;        // what a person reads, with the family's exception meaning
    int exceptionCode = 0;
    DecodedValue readBack;

    bool succeeded() const { return result == Result::Confirmed || result == Result::Accepted; }
    // "confirmed", "accepted", "mismatch", "refused", "unknown", "unverified", "not_sent",
    // "read_only", "invalid": the words of the audit log and the CLI.
    QString resultName() const;
};

} // namespace jumo

Q_DECLARE_METATYPE(jumo::WriteOutcome)
