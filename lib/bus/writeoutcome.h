// How a write ended: confirmed by read-back, accepted without one, or refused and why.
#pragma once

#include "protocol/valuecodec.h"

#include <QString>

namespace jumo {

struct WriteOutcome
{
    enum class Result {
        Confirmed,      // written and read back with the same value
        Accepted,       // the device acknowledged it; the entry cannot be read back
        Mismatch,       // acknowledged, but the read-back shows another value
        Refused,        // the device answered with an exception
        Failed,         // no answer, line lost, or the reply did not fit
        ReadOnlyMode,   // refused before reaching the line: read-only mode
        Invalid,        // refused before reaching the line: value, entry or range
    };

    Result result = Result::Failed;
    QString message;        // what a person reads, with the family's exception meaning
    int exceptionCode = 0;
    DecodedValue readBack;

    bool succeeded() const { return result == Result::Confirmed || result == Result::Accepted; }
};

} // namespace jumo
