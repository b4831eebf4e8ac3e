// Turns register words into values and values into register words, the way a family's
// map says: word orders, texts, enums, bit fields and the devices' NaN/Inf error values.
#pragma once

#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QVariant>

#include <span>

namespace jumo {

enum class ValueStatus { Ok, Underrange, Overrange, Invalid, DecodeError };

// "ok", "underrange", "overrange", "invalid", "decode_error": the words scripts see.
QString valueStatusName(ValueStatus status);

struct DecodedValue
{
    ValueStatus status = ValueStatus::DecodeError;
    // double (float), qint64 (integers, enums, bit fields), bool, QString (text);
    // invalid for error values and decode errors.
    QVariant value;
    QString display;   // what a person sees: "12.34", "Overrange", an enum label
    quint32 raw = 0;   // the raw 16 or 32 bits after word ordering (not for texts)

    bool isOk() const { return status == ValueStatus::Ok; }
};

struct EncodeResult
{
    QList<quint16> words;
    QString error;   // empty on success

    bool ok() const { return error.isEmpty(); }
};

class ValueCodec
{
    Q_DECLARE_TR_FUNCTIONS(jumo::ValueCodec)

public:
    static QList<quint16> splitWords(quint32 value, WordOrder order);
    static quint32 joinWords(quint16 first, quint16 second, WordOrder order);
    static QList<quint16> encodeFloat(float value, WordOrder order);
    static float decodeFloat(quint16 first, quint16 second, WordOrder order);

    // Classifies a float as a device error value (-Inf, +Inf, NaN) or Ok.
    static ValueStatus classifyFloat(float value);
    // Short text for a status: "Overrange".
    static QString statusText(ValueStatus status);
    // The family's own wording for an error value ("Measuring range overflow"), or the short text.
    static QString statusDescription(ValueStatus status, const RegisterMap &map);

    static DecodedValue decode(const RegisterEntry &entry, const RegisterMap &map, std::span<const quint16> words);

    // Encodes a value given as text (CLI, edit fields), with the map's type and range
    // checks. Enums take a number or a label; bit fields a number or bit ids joined by
    // '+'; command words get their activation bit added.
    static EncodeResult encode(const RegisterEntry &entry, const RegisterMap &map, const QString &text);

    // The value of the words as a text that encode() turns back into the same words
    // (floats with 9 significant digits, enums and bit fields as numbers); empty for
    // error values.
    static QString exactText(const RegisterEntry &entry, const RegisterMap &map, std::span<const quint16> words);

    // Formats a float with the precision the devices have (7 significant digits).
    static QString formatFloat(double value);
};

} // namespace jumo
