// The bus's sense of time: a monotonic millisecond clock and one-shot calls. The steady
// clock runs on QElapsedTimer and QTimer; the manual clock lets unit tests run the
// scheduler through minutes of line time in milliseconds.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>

#include <functional>
#include <map>

namespace jumo {

class Clock
{
public:
    virtual ~Clock() = default;
    virtual qint64 nowMs() const = 0;
    // Calls fn once, from the event loop and never from inside this call, at or after
    // atMs; not at all once context is gone.
    virtual void callAt(qint64 atMs, QObject *context, std::function<void()> fn) = 0;
    void callSoon(QObject *context, std::function<void()> fn) { callAt(nowMs(), context, std::move(fn)); }
};

class SteadyClock final : public Clock
{
public:
    SteadyClock() { m_timer.start(); }
    qint64 nowMs() const override { return m_timer.elapsed(); }
    void callAt(qint64 atMs, QObject *context, std::function<void()> fn) override;

private:
    QElapsedTimer m_timer;
};

class ManualClock final : public Clock
{
public:
    qint64 nowMs() const override { return m_now; }
    void callAt(qint64 atMs, QObject *context, std::function<void()> fn) override;

    // Runs the earliest pending call, moving the clock to its time; false when none is
    // pending.
    bool runNext();
    // Runs every call due up to atMs in time order (calls made meanwhile included), then
    // leaves the clock at atMs.
    void advanceTo(qint64 atMs);
    void advance(qint64 ms) { advanceTo(m_now + ms); }
    bool hasPending() const { return !m_calls.empty(); }
    // The time of the earliest pending call, or -1.
    qint64 nextCallMs() const { return m_calls.empty() ? -1 : m_calls.begin()->first; }

private:
    struct Call
    {
        QPointer<QObject> context;
        std::function<void()> fn;
    };

    qint64 m_now = 0;
    std::multimap<qint64, Call> m_calls;   // insertion order kept among equal times
};

} // namespace jumo
