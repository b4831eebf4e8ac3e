// A station's history that is being recorded: the recorder hands it samples, it keeps
// them (in batches, from a thread of its own) and answers trends. Recording stops with a
// message when the store cannot write (a full disk, a server gone) and resumes by itself
// when it can again; the time between is a gap ("not_recorded") in every series.
#pragma once

#include "history/historysource.h"

namespace jumo {

class HistoryStore : public HistorySource
{
    Q_OBJECT

public:
    using HistorySource::HistorySource;

    // The station whose history this is: the first part of every key recorded here.
    virtual QString station() const = 0;
    // A handle for record(); the same series gives the same handle.
    virtual int series(const HistorySeriesInfo &info) = 0;
    // Keeps a sample (the time of each series only goes forward: a sample at or before
    // the series' last one is moved just after it). Dropped while not recording.
    virtual void record(const HistorySample &sample) = 0;
    virtual bool isRecording() const = 0;
    // How often a value that stays is recorded again.
    virtual qint64 heartbeatMs() const = 0;

signals:
    // For the status bar and the journal: "History not recorded: cannot write ...".
    void recordingStopped(const QString &message);
    // Writing works again; a recorder records every value anew, since the gap.
    void recordingResumed(const QString &message);
};

} // namespace jumo
