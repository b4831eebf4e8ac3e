#include "protocol/valueformat.h"

#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace jumo {

namespace {

QLocale withoutGroups(QLocale locale)
{
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator | QLocale::RejectGroupSeparator);
    return locale;
}

} // namespace

int ValueFormat::decimalsFor(double value, DisplayPrecision precision)
{
    if (precision.kind == DisplayPrecision::Kind::Decimals)
        return precision.digits;
    // Significant digits for readings over decades (0.512 A, 19.99 A, 1838 W), but never
    // more decimals than zero is shown with (0.000): below that a reading is noise around
    // zero, not a value with four digits ("-0.00007528 W").
    const int most = std::max(0, precision.digits - 1);
    if (value == 0 || !std::isfinite(value))
        return most;
    const int magnitude = int(std::floor(std::log10(std::fabs(value))));
    const int significant = precision.digits - 1 - magnitude;
    int decimals = std::clamp(significant, 0, most);
    // 9.9996 to four digits is 10.00, not 10.000: rounding may add a digit in front
    // (where the digits are counted, not where zero's decimals cap them).
    const double scale = std::pow(10.0, decimals);
    if (decimals > 0 && decimals == significant
        && std::fabs(std::round(value * scale) / scale) >= std::pow(10.0, magnitude + 1))
        --decimals;
    return decimals;
}

double ValueFormat::rounded(double value, DisplayPrecision precision)
{
    if (!std::isfinite(value))
        return value;
    const double scale = std::pow(10.0, decimalsFor(value, precision));
    const double r = std::round(value * scale) / scale;
    // The precision first, then the sign: what rounds to zero is zero, never -0.
    return r == 0 ? 0.0 : r;
}

QString ValueFormat::number(double value, DisplayPrecision precision, const QLocale &locale)
{
    if (!std::isfinite(value))
        return QString::number(value);
    const int decimals = decimalsFor(value, precision);
    // A value that rounds to zero shows no sign: "-0.0" is no reading anyone writes down.
    return withoutGroups(locale).toString(rounded(value, precision), 'f', decimals);
}

QString ValueFormat::bits(quint32 word, const RegisterEntry &entry)
{
    QStringList parts;
    for (const BitDefinition &b : entry.bits) {
        if (b.reserved)
            continue;
        const quint32 field = (word & b.mask()) >> b.bit;
        const QString label = QCoreApplication::translate("jumo::maps", b.label.toUtf8().constData());
        if (b.width > 1)
            parts << QStringLiteral("%1: %2").arg(label).arg(field);
        else if (field)
            parts << label;
    }
    const QString hex = QStringLiteral("0x%1").arg(QString::number(word & 0xFFFF, 16).toUpper().rightJustified(4, QLatin1Char('0')));
    return parts.isEmpty() ? tr("%1 (none set)").arg(hex) : QStringLiteral("%1 (%2)").arg(hex, parts.join(QStringLiteral(", ")));
}

QString ValueFormat::value(const DecodedValue &v, const RegisterEntry &entry, const QLocale &locale)
{
    // The codec names set bits by their ids, for scripts; people read the manual's words.
    if (v.isOk() && entry.type == ValueType::Bitfield)
        return bits(v.raw, entry);
    if (!v.isOk() || !isNumeric(entry.type))
        return v.display;
    if (entry.type == ValueType::Float)
        return number(v.value.toDouble(), entry.precision, locale);
    return withoutGroups(locale).toString(v.value.toLongLong());
}

QString ValueFormat::joinUnit(const QString &number, const QString &unit)
{
    if (unit.isEmpty())
        return number;
    // Angles sit on the number (37.5°); every other unit is spaced (91.9 V, 45.0 %, 20.0 °C).
    if (unit == QStringLiteral("°"))
        return number + unit;
    return number + QLatin1Char(' ') + unit;
}

QString ValueFormat::withUnit(const DecodedValue &v, const RegisterEntry &entry, const QLocale &locale)
{
    const QString text = value(v, entry, locale);
    return v.isOk() && isNumeric(entry.type) ? joinUnit(text, entry.unit) : text;
}

QString ValueFormat::limit(double value, const RegisterEntry &entry, const QLocale &locale)
{
    if (entry.type != ValueType::Float)
        return withoutGroups(locale).toString(qint64(value));
    // A limit is exact: 0.5 stays 0.5 where values show whole numbers, and 100 stays 100.
    const QString shown = number(value, entry.precision, locale);
    if (withoutGroups(locale).toDouble(shown) == value)
        return shown;
    return withoutGroups(locale).toString(value, 'g', 7);
}

std::optional<QString> ValueFormat::parseNumber(const QString &text, const QLocale &locale)
{
    const QString t = text.trimmed();
    // Where the dot groups thousands, "1.500" is what a person writes for 1500 as often
    // as for 1.5: neither reading may be written, a value a thousand times off either way.
    if (locale.groupSeparator() == QStringLiteral(".") && locale.decimalPoint() != QStringLiteral(".")) {
        static const QRegularExpression grouped(QStringLiteral("^[+-]?\\d{1,3}(\\.\\d{3})+$"));
        if (grouped.match(t).hasMatch())
            return std::nullopt;
    }
    bool ok = false;
    const double v = withoutGroups(locale).toDouble(t, &ok);
    if (ok && std::isfinite(v))
        return QString::number(v, 'g', QLocale::FloatingPointShortest);
    // The C locale's way works everywhere: 42.5 is never a German 425.
    const double c = withoutGroups(QLocale::c()).toDouble(t, &ok);
    if (ok && std::isfinite(c))
        return QString::number(c, 'g', QLocale::FloatingPointShortest);
    return std::nullopt;
}

} // namespace jumo
