#include "protocol/localtime.h"

#include <QSet>

#include <algorithm>
#include <cstdlib>

namespace jumo {

QList<QDateTime> LocalTime::instants(QDate date, QTime time, const QTimeZone &zone)
{
    const QDateTime fields(date, time, Qt::UTC);
    if (!fields.isValid())
        return {};
    if (!zone.isValid())
        return {fields};
    // Every offset in force within a day of it (a zone is never further than 14 hours
    // from UTC); the clocks show date and time at fields - offset where that offset is
    // the one in force then.
    constexpr qint64 day = 86400;
    QSet<int> offsets{zone.offsetFromUtc(fields.addSecs(-day)), zone.offsetFromUtc(fields.addSecs(day))};
    for (const QTimeZone::OffsetData &transition : zone.transitions(fields.addSecs(-day), fields.addSecs(day)))
        offsets.insert(transition.offsetFromUtc);
    QList<QDateTime> out;
    for (const int offset : std::as_const(offsets)) {
        const QDateTime at = fields.addSecs(-offset);
        if (zone.offsetFromUtc(at) == offset)
            out.append(at);
    }
    std::sort(out.begin(), out.end());
    return out;
}

QString LocalTime::offsetText(int offsetSeconds)
{
    const int minutes = std::abs(offsetSeconds) / 60;
    return QStringLiteral("%1%2:%3")
            .arg(offsetSeconds < 0 ? QLatin1Char('-') : QLatin1Char('+'))
            .arg(minutes / 60, 2, 10, QLatin1Char('0'))
            .arg(minutes % 60, 2, 10, QLatin1Char('0'));
}

QString LocalTime::withOffset(qint64 msSinceEpoch)
{
    const QDateTime local = QDateTime::fromMSecsSinceEpoch(msSinceEpoch);
    return local.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")) + offsetText(local.offsetFromUtc());
}

} // namespace jumo
