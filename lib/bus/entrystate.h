// The last known state of one entry of a polled device: its value, or why there is
// none, and when it was last read.
#pragma once

#include "protocol/valuecodec.h"

#include <QString>

namespace jumo {

enum class ReadError { None, Timeout, Exception, Mismatch, Disconnected };

struct EntryState
{
    DecodedValue value;      // last value that decoded; kept while errors come in
    QList<quint16> words;    // the register words of that value
    ReadError error = ReadError::Timeout;
    int exceptionCode = 0;
    qint64 updatedMs = -1;   // monotonic time of the last attempt, -1 = never
    qint64 goodMs = -1;      // monotonic time of the last good value, -1 = never

    bool hasValue() const { return goodMs >= 0; }
    bool isCurrent() const { return error == ReadError::None; }
    // "ok", "underrange", "overrange", "invalid", "timeout", "exception:N": the words
    // of the CLI's JSON contract.
    QString statusName() const
    {
        switch (error) {
        case ReadError::None:
            return value.status == ValueStatus::DecodeError ? QStringLiteral("invalid") : valueStatusName(value.status);
        case ReadError::Exception:
            return QStringLiteral("exception:%1").arg(exceptionCode);
        case ReadError::Timeout:
        case ReadError::Mismatch:
        case ReadError::Disconnected:
            return QStringLiteral("timeout");
        }
        return {};
    }
};

} // namespace jumo
