// Numbers as an engineer writes them, for people: the entry's precision, the locale's
// decimal sign, no thousands separators, the unit ("91,9 V" in German). Machine outputs
// (CSV, JSON, parameter files) never come here: they keep the codec's own texts.
#pragma once

#include "protocol/registermap.h"
#include "protocol/valuecodec.h"

#include <QCoreApplication>
#include <QLocale>

#include <optional>

namespace jumo {

class ValueFormat
{
    Q_DECLARE_TR_FUNCTIONS(jumo::ValueFormat)

public:
    static QString number(double value, DisplayPrecision precision, const QLocale &locale = QLocale());
    // The value as number() shows it, as a number: rounded to the precision, so what
    // reads as zero is zero (a bar drawn from it agrees with the text beside it).
    static double rounded(double value, DisplayPrecision precision);
    // How many decimals number() writes this value with.
    static int decimalsFor(double value, DisplayPrecision precision);
    // A reading without its unit: numbers by the entry's precision and the locale; bit
    // fields by their bits' labels; enums, texts and error values as the codec words them.
    static QString value(const DecodedValue &v, const RegisterEntry &entry, const QLocale &locale = QLocale());
    // A bit field for people: "0x0005 (Output 1, Output 3)", "0x0A00 (Slot 1: 10, Slot 2: 0)",
    // "0x0000 (none set)"; the bits by the manual's labels, reserved ones left out.
    static QString bits(quint32 word, const RegisterEntry &entry);
    // The same with the entry's unit where it has one.
    static QString withUnit(const DecodedValue &v, const RegisterEntry &entry, const QLocale &locale = QLocale());
    // "12.5 %", "37.5°": a number and a unit, spaced as the unit wants.
    static QString joinUnit(const QString &number, const QString &unit);
    // A limit of the entry (its min or max) as the entry's values are shown.
    static QString limit(double value, const RegisterEntry &entry, const QLocale &locale = QLocale());
    // What a person typed for a number, in the locale's way ("42,5") or with a dot, as
    // the codec's text ("42.5"); nullopt when it is no number. Thousands separators are
    // refused, and so is what only a thousands separator makes sense of: "1.500" in
    // German may mean 1500 or 1.5, and either is a thousand times off the other.
    static std::optional<QString> parseNumber(const QString &text, const QLocale &locale = QLocale());
};

} // namespace jumo
