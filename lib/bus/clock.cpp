#include "bus/clock.h"

#include <QTimer>

#include <algorithm>
#include <limits>

namespace jumo {

void SteadyClock::callAt(qint64 atMs, QObject *context, std::function<void()> fn)
{
    const qint64 delay = std::max<qint64>(0, atMs - nowMs());
    QTimer::singleShot(int(std::min<qint64>(delay, std::numeric_limits<int>::max())), Qt::PreciseTimer, context,
                       std::move(fn));
}

void ManualClock::callAt(qint64 atMs, QObject *context, std::function<void()> fn)
{
    m_calls.emplace(std::max(atMs, m_now), Call{context, std::move(fn)});
}

bool ManualClock::runNext()
{
    if (m_calls.empty())
        return false;
    const auto first = m_calls.begin();
    m_now = std::max(m_now, first->first);
    const Call call = first->second;
    m_calls.erase(first);
    if (call.context)
        call.fn();
    return true;
}

void ManualClock::advanceTo(qint64 atMs)
{
    while (!m_calls.empty() && m_calls.begin()->first <= atMs)
        runNext();
    m_now = std::max(m_now, atMs);
}

} // namespace jumo
