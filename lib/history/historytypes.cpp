#include "history/historytypes.h"

#include <QHash>

#include <array>
#include <cmath>

namespace jumo {

namespace {

constexpr std::array<const char *, 16> stateNames{
    "ok",      "underrange", "overrange", "invalid", "stale",       "timeout",      "exception",    "offline",
    "line_lost", "disconnected", "unavailable", "unconfirmed", "wrong_device", "not_read", "not_recorded",
    "unknown_state",
};
static_assert(stateNames.size() == size_t(SampleState::UnknownState) + 1);

} // namespace

QString sampleStateName(SampleState state)
{
    return QString::fromLatin1(stateNames[size_t(state)]);
}

std::optional<SampleState> sampleStateFromName(const QString &name)
{
    for (size_t i = 0; i < stateNames.size(); ++i) {
        if (name == QLatin1String(stateNames[i]))
            return SampleState(i);
    }
    return std::nullopt;
}

std::optional<SampleState> sampleStateFromNumber(int number)
{
    if (number < 0 || number > int(SampleState::NotRecorded))
        return std::nullopt;
    return SampleState(number);
}

SampleState sampleStateFromStored(const QVariant &stored)
{
    // Integers only: QVariant reads a text as 0 (ok) and rounds 2.5 to 3.
    bool whole = false;
    switch (stored.typeId()) {
    case QMetaType::Int:
    case QMetaType::UInt:
    case QMetaType::LongLong:
    case QMetaType::ULongLong:
    case QMetaType::Short:
    case QMetaType::UShort:
        whole = true;
        break;
    case QMetaType::Double:
        whole = std::trunc(stored.toDouble()) == stored.toDouble();
        break;
    default:
        break;
    }
    if (!whole)
        return SampleState::UnknownState;
    const qint64 number = stored.toLongLong();
    if (number < 0 || number > int(SampleState::NotRecorded))
        return SampleState::UnknownState;
    return SampleState(number);
}

QString sampleValidityName(SampleState state)
{
    if (state == SampleState::Stale)
        return QStringLiteral("stale");
    return isGap(state) ? QStringLiteral("unknown") : QStringLiteral("current");
}

bool hasValue(SampleState state)
{
    return state == SampleState::Ok || state == SampleState::Stale;
}

bool isGap(SampleState state)
{
    return state >= SampleState::Timeout;
}

QString HistoryKey::name() const
{
    return station + QLatin1Char('/') + line + QLatin1Char('/') + device;
}

size_t qHash(const HistoryKey &key, size_t seed)
{
    return qHashMulti(seed, key.station, key.line, key.device);
}

QList<HistoryGap> HistoryTrace::gaps() const
{
    QList<HistoryGap> out;
    for (qsizetype i = 0; i < points.size(); ++i) {
        if (!isGap(points[i].state))
            continue;
        qsizetype next = i + 1;
        while (next < points.size() && isGap(points[next].state))
            ++next;
        out.append({points[i].timeMs, next < points.size() ? points[next].timeMs : endMs, points[i].state});
        i = next - 1;
    }
    return out;
}

} // namespace jumo
