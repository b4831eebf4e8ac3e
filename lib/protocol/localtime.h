// Local wall-clock times, read and shown without the two traps of daylight saving time:
// a time the clocks skip (spring) never happened, and one they show twice (autumn) is
// ambiguous without its UTC offset.
#pragma once

#include <QDateTime>
#include <QList>
#include <QString>
#include <QTimeZone>

namespace jumo {

class LocalTime
{
public:
    // The instants at which the clocks of zone showed date and time, earliest first (in
    // UTC): none in a gap the clocks skip, two in an hour they repeat.
    static QList<QDateTime> instants(QDate date, QTime time, const QTimeZone &zone = QTimeZone::systemTimeZone());
    // "2026-10-25 02:30:00.000+02:00": the local time with its offset, never ambiguous.
    static QString withOffset(qint64 msSinceEpoch);
    // "+02:00", "-03:30", "+00:00".
    static QString offsetText(int offsetSeconds);
};

} // namespace jumo
