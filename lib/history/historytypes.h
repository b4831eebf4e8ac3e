// What the history keeps and gives back: series named by strings (station, line,
// device, entry), the state a sample was recorded in, and a trend's steps and gaps.
#pragma once

#include <QList>
#include <QString>
#include <QVariant>
#include <QtNumeric>

#include <optional>

namespace jumo {

// The state of a recorded sample. The names are the words of EntryState::statusName()
// (the CLI's JSON contract; an exception without its code), and "not_recorded" for a
// time nobody recorded (the recorder stopped or crashed, the disk was full).
// Stored as these numbers: never renumber, only append.
enum class SampleState : quint8 {
    Ok = 0,         // current, with a value
    Underrange,     // current, the device's error value: no number
    Overrange,
    Invalid,
    Stale,          // the last value, read longer ago than the device's cycle allows
    Timeout,        // from here on: unknown, a gap
    Exception,
    Offline,
    LineLost,
    Disconnected,
    Unavailable,
    Unconfirmed,
    WrongDevice,
    NotRead,
    NotRecorded,
    // Never stored: a state read from a history that this version does not know (a
    // number of a newer version, a hand-made file's text). Unknown, a gap. Stays last.
    UnknownState,
};

// "ok", "underrange", ..., "line_lost", "not_recorded", "unknown_state".
QString sampleStateName(SampleState state);
std::optional<SampleState> sampleStateFromName(const QString &name);
std::optional<SampleState> sampleStateFromNumber(int number);
// A state column's value: a stored number, else UnknownState (never a 0 read as ok).
SampleState sampleStateFromStored(const QVariant &stored);
// "current", "stale" or "unknown": the validity of the bus (bus/entrystate.h).
QString sampleValidityName(SampleState state);
// A value to draw: ok or stale.
bool hasValue(SampleState state);
// Unknown: a gap in the trend (the line lost, the device silent, nobody recording).
bool isGap(SampleState state);

// A device of a station: "hall-3", "cabinet-a", "ipc300@1". Not the in-process DeviceId:
// the same key names the device in the HMI, the publisher, a viewer and jumoctl.
struct HistoryKey
{
    QString station;
    QString line;
    QString device;

    // "hall-3/cabinet-a/ipc300@1"
    QString name() const;
    bool operator==(const HistoryKey &other) const = default;
};
size_t qHash(const HistoryKey &key, size_t seed = 0);

// One recorded entry of a device. numeric: a number with a unit and a range (a float or
// an integer, not a bool, enum, bit field or text): the entries a trend offers.
struct HistorySeriesInfo
{
    HistoryKey key;
    QString entry;
    bool numeric = true;
    QString unit;
};

// A step of a trend: state and value hold from timeMs until the next point. Raw points
// have minimum == maximum == mean == value; aggregated points (one minute, or a bucket
// of a long span) give the range and time-weighted mean over their time, and in value
// what held at their end. Without a value (a gap, an error value) the numbers are NaN.
struct HistoryPoint
{
    qint64 timeMs = 0;   // ms since the epoch, UTC
    SampleState state = SampleState::NotRecorded;
    double value = qQNaN();
    double minimum = qQNaN();
    double maximum = qQNaN();
    double mean = qQNaN();
    QString text;   // text entries: the text that holds
};

// A time without values, from its start to the next point with a state of another kind.
struct HistoryGap
{
    qint64 startMs = 0;
    qint64 endMs = 0;
    SampleState state = SampleState::NotRecorded;
};

struct HistoryQuery
{
    HistoryKey key;
    QString entry;
    qint64 fromMs = 0;
    qint64 toMs = 0;
    int maxPoints = 1000;   // buckets; a bucket gives at most 3 points (start, gap, end)
};

// The answer to a query: the steps of one entry over [fromMs, toMs). The first point is
// what held at fromMs (moved there), when anything was recorded before; the last point
// holds until endMs (toMs, or the time of the query when that is earlier).
struct HistoryTrace
{
    enum class Resolution { Raw, Minute };

    HistoryQuery query;
    Resolution resolution = Resolution::Raw;
    qint64 endMs = 0;
    qint64 bucketMs = 0;   // 0: every recorded step; else the width the points were joined to
    QList<HistoryPoint> points;
    QString error;         // the query failed: why (points empty)

    bool ok() const { return error.isEmpty(); }
    QList<HistoryGap> gaps() const;
};

// A sample as the recorder hands it to a store: series is the handle the store gave
// for the series (HistoryStore::series).
struct HistorySample
{
    int series = -1;
    qint64 timeMs = 0;
    SampleState state = SampleState::NotRecorded;
    double value = qQNaN();
    QString text;
};

// What a store keeps and how it writes. Raw samples are kept rawRetentionMs; the
// one-minute min/mean/max of what changed, minuteRetentionMs.
struct HistorySettings
{
    qint64 rawRetentionMs = 7LL * 24 * 3600 * 1000;
    qint64 minuteRetentionMs = 365LL * 24 * 3600 * 1000;
    // A value that stays is recorded again this often; a value held longer than
    // maxHoldMs() without a sample is a time nobody recorded.
    qint64 heartbeatMs = 5 * 60 * 1000;
    int batchIntervalMs = 1000;        // samples gathered this long go in one transaction
    int maxBatchSamples = 20000;       // or sooner, when this many are waiting
    int maintenanceIntervalMs = 60000; // the one-minute rows and the thinning, in the background
    int retryIntervalMs = 30000;       // after a failed write (full disk, server gone)

    qint64 maxHoldMs() const { return 2 * heartbeatMs + 60000; }
};

} // namespace jumo
