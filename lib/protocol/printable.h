// Texts from devices and files shown on a terminal: control characters (an escape
// sequence in a device name could rewrite the screen) are shown as \xHH instead.
#pragma once

#include <QString>

namespace jumo {

inline QString printable(const QString &text)
{
    QString out;
    out.reserve(text.size());
    for (const QChar c : text) {
        const char16_t u = c.unicode();
        if (u < 0x20 || u == 0x7F || (u >= 0x80 && u < 0xA0))
            out += QStringLiteral("\\x%1").arg(int(u), 2, 16, QLatin1Char('0'));
        else
            out += c;
    }
    return out;
}

} // namespace jumo
