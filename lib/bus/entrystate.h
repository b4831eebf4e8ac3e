// The state of one entry of a polled device: its last value, and whether that value is
// current, stale (older than the device's cycle allows) or unknown (why, in error).
#pragma once

#include "protocol/valuecodec.h"

#include <QString>

namespace jumo {

// What a value is worth now. Views render this; they never infer it from an age.
enum class Validity {
    Current,   // read in the device's last cycle
    Stale,     // read once, but longer ago than the device's cycle allows
    Unknown,   // never read, or the line, the device or the read failed since
};

// Why a value is unknown (None while it is current or stale).
enum class ReadError {
    None,
    NotRead,        // not read yet
    Timeout,        // the block was not answered, after retries
    Exception,      // the device answered the block with an exception
    Mismatch,       // the reply did not fit the request
    DeviceOffline,  // the device stopped answering
    LineLost,       // the port went away
    LineClosed,     // the line was closed
    NotAvailable,   // exception 02 for this one entry: this model does not have it
    Unconfirmed,    // the device answers, but is not yet confirmed to be of its family
    WrongDevice,    // a device of another family answers at the address
};

struct EntryState
{
    DecodedValue value;      // the last value that decoded; kept as "last known"
    QList<quint16> words;    // the register words of that value
    Validity validity = Validity::Unknown;
    ReadError error = ReadError::NotRead;
    int exceptionCode = 0;
    qint64 updatedMs = -1;   // monotonic time of the last change of state, -1 = never
    qint64 goodMs = -1;      // monotonic time of the last good value, -1 = never

    bool hasValue() const { return goodMs >= 0; }
    bool isCurrent() const { return validity == Validity::Current; }
    // "ok", "underrange", "overrange", "invalid" for a current value; "stale";
    // "timeout", "exception:N", "offline", "line_lost", "disconnected", "unavailable",
    // "unconfirmed", "wrong_device", "not_read" when unknown: the words of the CLI's JSON contract.
    QString statusName() const;
};

QString validityName(Validity validity);

} // namespace jumo
