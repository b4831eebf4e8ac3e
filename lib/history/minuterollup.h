// Turns a station's raw samples into one-minute rows, pass by pass: for every minute in
// which a series changed, one row per run of one state (its start, min, time-weighted
// mean, max and the value it ended with). A minute of repeated samples of an unchanged
// value gives no row: the row before holds. A value held longer than maxHoldMs without
// a sample ends in a "not_recorded" row, so a recorder that died shows as a gap.
#pragma once

#include "history/historytypes.h"

#include <QHash>
#include <QList>

namespace jumo {

class MinuteRollup
{
public:
    struct Sample
    {
        qint64 series = 0;
        qint64 timeMs = 0;
        SampleState state = SampleState::NotRecorded;
        double value = qQNaN();
        QString text;
    };
    struct Row
    {
        qint64 series = 0;
        HistoryPoint point;
    };

    explicit MinuteRollup(qint64 maxHoldMs) : m_maxHoldMs(maxHoldMs) { }

    // The rows of a pass that ends at toMs (a whole minute) from its samples, ordered by
    // series and then time: each series' rows in time order. What each series holds at
    // toMs is kept for the next pass once accept()ed.
    QList<Row> roll(const QList<Sample> &samples, qint64 toMs);
    // The rows were stored: the next pass goes on from them. Without it (the transaction
    // failed) the next pass repeats this one from the same held states.
    void accept();

private:
    struct Held
    {
        qint64 timeMs = 0;
        SampleState state = SampleState::NotRecorded;
        double value = qQNaN();
        QString text;
    };
    struct Run
    {
        bool open = false;
        qint64 startMs = 0;
        qint64 minute = 0;
        SampleState state = SampleState::NotRecorded;
        qint64 lastMs = 0;
        double last = qQNaN();
        double minimum = qQNaN();
        double maximum = qQNaN();
        double weighted = 0;
        QString text;
    };

    void rollSeries(qint64 series, const Sample *first, const Sample *end, qint64 toMs, QList<Row> &rows);
    void closeRun(Run &run, qint64 endMs, qint64 series, QList<Row> &rows);

    qint64 m_maxHoldMs;
    QHash<qint64, Held> m_held;
    QHash<qint64, Held> m_pending;
};

} // namespace jumo
