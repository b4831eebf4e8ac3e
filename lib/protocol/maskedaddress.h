// An address as typed ("mqtt://user:secret@host", "postgresql://user:secret@host/db")
// with whatever stands between "USER:" and the last '@' masked, for messages about an
// address Qt cannot parse (its error text would quote it whole).
#pragma once

#include <QString>

namespace jumo {

inline QString maskedAddress(const QString &text)
{
    const qsizetype scheme = text.indexOf(QLatin1String("://"));
    const qsizetype start = scheme < 0 ? 0 : scheme + 3;
    // The last '@': a password may hold '/' and '@' as typed.
    const qsizetype at = text.lastIndexOf(QLatin1Char('@'));
    if (at < start)
        return text;
    const qsizetype colon = text.indexOf(QLatin1Char(':'), start);
    if (colon < 0 || colon > at)
        return text;
    return text.left(colon + 1) + QStringLiteral("***") + text.mid(at);
}

} // namespace jumo
