// CSV quoting shared by every CSV the tools write (map, monitor, logs, exports): a field
// with a comma, quote or line break (CR or LF) is quoted, its quotes doubled.
#pragma once

#include <QString>

namespace jumo {

inline QString csvField(QString text)
{
    if (text.contains(QLatin1Char(',')) || text.contains(QLatin1Char('"')) || text.contains(QLatin1Char('\n'))
        || text.contains(QLatin1Char('\r'))) {
        text.replace(QLatin1String("\""), QLatin1String("\"\""));
        return QLatin1Char('"') + text + QLatin1Char('"');
    }
    return text;
}

} // namespace jumo
