#include "protocol/valuecodec.h"

#include <QRegularExpression>
#include <QStringList>

#include <bit>
#include <cmath>
#include <limits>

namespace jumo {

namespace {

// Position of each big-endian byte (A=0 .. D=3) on the wire, per order.
constexpr int wirePositions[4][4] = {
    {0, 1, 2, 3},   // ABCD
    {2, 3, 0, 1},   // CDAB
    {1, 0, 3, 2},   // BADC
    {3, 2, 1, 0},   // DCBA
};

// "42", "-7", "+3" or "0x1F": the whole text, nothing Qt's own parsers let through
// besides ("0x-1", "0x0x7F", signs after the 0x).
std::optional<qint64> parseInteger(const QString &text)
{
    static const QRegularExpression decimal(QRegularExpression::anchoredPattern(QStringLiteral("[+-]?[0-9]{1,18}")));
    static const QRegularExpression hex(QRegularExpression::anchoredPattern(QStringLiteral("0[xX][0-9A-Fa-f]{1,15}")));
    const QString t = text.trimmed();
    if (hex.match(t).hasMatch())
        return t.mid(2).toLongLong(nullptr, 16);
    if (decimal.match(t).hasMatch())
        return t.toLongLong();
    return std::nullopt;
}

// The largest magnitude that still rounds to a finite float: FLT_MAX and half a unit
// in its last place. What exactText() writes for FLT_MAX (3.40282347e+38) lies above
// FLT_MAX as a double, and must come back as FLT_MAX.
const double floatLimit = double(std::numeric_limits<float>::max()) + std::ldexp(1.0, 103);

} // namespace

QString valueStatusName(ValueStatus status)
{
    switch (status) {
    case ValueStatus::Ok: return QStringLiteral("ok");
    case ValueStatus::Underrange: return QStringLiteral("underrange");
    case ValueStatus::Overrange: return QStringLiteral("overrange");
    case ValueStatus::Invalid: return QStringLiteral("invalid");
    case ValueStatus::DecodeError: return QStringLiteral("decode_error");
    }
    return {};
}

QList<quint16> ValueCodec::splitWords(quint32 value, WordOrder order)
{
    const quint8 be[4] = {quint8(value >> 24), quint8(value >> 16), quint8(value >> 8), quint8(value)};
    quint8 wire[4] = {};
    for (int i = 0; i < 4; ++i)
        wire[wirePositions[int(order)][i]] = be[i];
    return {quint16(wire[0] << 8 | wire[1]), quint16(wire[2] << 8 | wire[3])};
}

quint32 ValueCodec::joinWords(quint16 first, quint16 second, WordOrder order)
{
    const quint8 wire[4] = {quint8(first >> 8), quint8(first), quint8(second >> 8), quint8(second)};
    quint32 value = 0;
    for (int i = 0; i < 4; ++i)
        value = value << 8 | wire[wirePositions[int(order)][i]];
    return value;
}

QList<quint16> ValueCodec::encodeFloat(float value, WordOrder order)
{
    return splitWords(std::bit_cast<quint32>(value), order);
}

float ValueCodec::decodeFloat(quint16 first, quint16 second, WordOrder order)
{
    return std::bit_cast<float>(joinWords(first, second, order));
}

ValueStatus ValueCodec::classifyFloat(float value)
{
    if (std::isnan(value))
        return ValueStatus::Invalid;
    if (std::isinf(value))
        return value < 0 ? ValueStatus::Underrange : ValueStatus::Overrange;
    return ValueStatus::Ok;
}

QString ValueCodec::statusText(ValueStatus status)
{
    switch (status) {
    case ValueStatus::Underrange:
        return tr("Underrange");
    case ValueStatus::Overrange:
        return tr("Overrange");
    case ValueStatus::Invalid:
        return tr("Invalid");
    case ValueStatus::DecodeError:
        return tr("Decode error");
    case ValueStatus::Ok:
        break;
    }
    return {};
}

QString ValueCodec::statusDescription(ValueStatus status, const RegisterMap &map)
{
    if (map.errorValues) {
        const QString *wording = status == ValueStatus::Underrange ? &map.errorValues->underrange
                : status == ValueStatus::Overrange                 ? &map.errorValues->overrange
                : status == ValueStatus::Invalid                   ? &map.errorValues->invalid
                                                                   : nullptr;
        if (wording)
            return QCoreApplication::translate("jumo::maps", wording->toUtf8().constData());
    }
    return statusText(status);
}

QString ValueCodec::exactText(const RegisterEntry &entry, const RegisterMap &map, std::span<const quint16> words)
{
    const DecodedValue v = decode(entry, map, words);
    if (!v.isOk())
        return {};
    switch (entry.type) {
    case ValueType::Float:
        return QString::number(double(decodeFloat(words[0], words[1], map.protocol.floatWordOrder)), 'g', 9);
    case ValueType::Text:
        return v.value.toString();
    case ValueType::Bool:
        return v.value.toBool() ? QStringLiteral("1") : QStringLiteral("0");
    default:
        return QString::number(v.value.toLongLong());
    }
}

QString ValueCodec::formatFloat(double value)
{
    return QString::number(value, 'g', 7);
}

DecodedValue ValueCodec::decode(const RegisterEntry &entry, const RegisterMap &map, std::span<const quint16> words)
{
    DecodedValue out;
    if (qsizetype(words.size()) != entry.wordCount()) {
        out.display = tr("expected %1 words, got %2").arg(entry.wordCount()).arg(words.size());
        return out;
    }
    out.status = ValueStatus::Ok;
    switch (entry.type) {
    case ValueType::Float: {
        const float f = decodeFloat(words[0], words[1], map.protocol.floatWordOrder);
        out.raw = joinWords(words[0], words[1], map.protocol.floatWordOrder);
        out.status = classifyFloat(f);
        if (out.status == ValueStatus::Ok) {
            out.display = formatFloat(f);
            out.value = out.display.toDouble();   // the float's own precision, not 12.340000152
        } else {
            out.display = statusText(out.status);
        }
        break;
    }
    case ValueType::Int32:
    case ValueType::UInt32: {
        out.raw = joinWords(words[0], words[1], map.protocol.int32WordOrder);
        const qint64 v = entry.type == ValueType::Int32 ? qint64(qint32(out.raw)) : qint64(out.raw);
        out.value = v;
        out.display = QString::number(v);
        break;
    }
    case ValueType::Int16:
        out.raw = words[0];
        out.value = qint64(qint16(words[0]));
        out.display = QString::number(qint16(words[0]));
        break;
    case ValueType::UInt16:
        out.raw = words[0];
        out.value = qint64(words[0]);
        out.display = QString::number(words[0]);
        break;
    case ValueType::Bool:
        out.raw = words[0];
        if (words[0] > 1) {
            out.status = ValueStatus::DecodeError;
            out.display = tr("not a boolean: %1").arg(words[0]);
        } else {
            out.value = words[0] == 1;
            out.display = words[0] == 1 ? tr("on") : tr("off");
        }
        break;
    case ValueType::Enum: {
        out.raw = words[0];
        out.value = qint64(words[0]);
        const auto it = entry.enumValues.constFind(words[0]);
        out.display = it != entry.enumValues.cend()
                ? QCoreApplication::translate("jumo::maps", it->toUtf8().constData())
                : tr("unknown value %1").arg(words[0]);
        break;
    }
    case ValueType::Bitfield: {
        out.raw = words[0];
        out.value = qint64(words[0]);
        QStringList active;
        for (const BitDefinition &b : entry.bits) {
            if (b.width == 1 && !b.reserved && (words[0] & b.mask()))
                active << b.id;
        }
        out.display = QStringLiteral("0x%1").arg(QString::number(words[0], 16).toUpper().rightJustified(4, QLatin1Char('0')));
        if (!active.isEmpty())
            out.display += QStringLiteral(" (") + active.join(QLatin1Char('+')) + QLatin1Char(')');
        break;
    }
    case ValueType::Text: {
        QByteArray bytes;
        for (quint16 w : words) {
            bytes.append(char(w >> 8));
            bytes.append(char(w & 0xFF));
        }
        const qsizetype nul = bytes.indexOf('\0');
        if (nul >= 0)
            bytes.truncate(nul);
        // The devices send ASCII; Latin-1 shows any stray byte instead of refusing it.
        out.value = QString::fromLatin1(bytes);
        out.display = out.value.toString();
        break;
    }
    }
    return out;
}

EncodeResult ValueCodec::encode(const RegisterEntry &entry, const RegisterMap &map, const QString &text)
{
    EncodeResult r;
    const QString t = text.trimmed();
    if (!entry.isWritable()) {
        r.error = tr("'%1' is read-only").arg(entry.id);
        return r;
    }
    if (t.isEmpty() && entry.type != ValueType::Text) {
        r.error = tr("no value given for '%1'").arg(entry.id);
        return r;
    }

    auto checkRange = [&](double v) -> bool {
        if (entry.restoreValue && v == *entry.restoreValue)
            return true;
        if ((entry.minimum && v < *entry.minimum) || (entry.maximum && v > *entry.maximum)) {
            r.error = tr("%1 is outside the range of '%2' (%3 to %4)")
                              .arg(t, entry.id,
                                   entry.minimum ? formatFloat(*entry.minimum) : QStringLiteral("-"),
                                   entry.maximum ? formatFloat(*entry.maximum) : QStringLiteral("-"));
            return false;
        }
        return true;
    };
    auto integerIn = [&](qint64 lo, qint64 hi) -> std::optional<qint64> {
        const std::optional<qint64> v = parseInteger(t);
        if (!v) {
            r.error = tr("'%1' is not a whole number").arg(t);
            return std::nullopt;
        }
        if (*v < lo || *v > hi) {
            r.error = tr("%1 does not fit the type of '%2' (%3 to %4)").arg(t, entry.id).arg(lo).arg(hi);
            return std::nullopt;
        }
        if (!checkRange(double(*v)))
            return std::nullopt;
        return v;
    };

    switch (entry.type) {
    case ValueType::Float: {
        bool ok = false;
        const double v = t.toDouble(&ok);
        if (!ok || !std::isfinite(v)) {
            r.error = tr("'%1' is not a number").arg(t);
            break;
        }
        if (std::fabs(v) >= floatLimit) {
            r.error = tr("%1 is too large for a float").arg(t);
            break;
        }
        if (!checkRange(v))
            break;
        r.words = encodeFloat(float(v), map.protocol.floatWordOrder);
        break;
    }
    case ValueType::Int16:
        if (const auto v = integerIn(-32768, 32767))
            r.words = {quint16(qint16(*v))};
        break;
    case ValueType::UInt16:
        if (const auto v = integerIn(0, 65535))
            r.words = {quint16(*v)};
        break;
    case ValueType::Int32:
        if (const auto v = integerIn(std::numeric_limits<qint32>::min(), std::numeric_limits<qint32>::max()))
            r.words = splitWords(quint32(qint32(*v)), map.protocol.int32WordOrder);
        break;
    case ValueType::UInt32:
        if (const auto v = integerIn(0, std::numeric_limits<quint32>::max()))
            r.words = splitWords(quint32(*v), map.protocol.int32WordOrder);
        break;
    case ValueType::Bool: {
        const QString l = t.toLower();
        if (l == QLatin1String("1") || l == QLatin1String("true") || l == QLatin1String("on"))
            r.words = {1};
        else if (l == QLatin1String("0") || l == QLatin1String("false") || l == QLatin1String("off"))
            r.words = {0};
        else
            r.error = tr("'%1' is not a boolean (0/1, on/off, true/false)").arg(t);
        break;
    }
    case ValueType::Enum: {
        std::optional<qint64> v = parseInteger(t);
        if (!v) {
            for (auto it = entry.enumValues.cbegin(); it != entry.enumValues.cend(); ++it) {
                if (it.value().compare(t, Qt::CaseInsensitive) == 0)
                    v = it.key();
            }
        }
        if (!v || *v < 0 || *v > 0xFFFF || !entry.enumValues.contains(int(*v))) {
            QStringList allowed;
            for (auto it = entry.enumValues.cbegin(); it != entry.enumValues.cend(); ++it)
                allowed << QStringLiteral("%1 = %2").arg(it.key()).arg(it.value());
            r.error = tr("'%1' is not a value of '%2' (%3)").arg(t, entry.id, allowed.join(QStringLiteral(", ")));
            break;
        }
        r.words = {quint16(*v)};
        break;
    }
    case ValueType::Bitfield: {
        quint32 value = 0;
        if (const std::optional<qint64> v = parseInteger(t)) {
            if (*v < 0 || *v > 0xFFFF) {
                r.error = tr("%1 does not fit in 16 bits").arg(t);
                break;
            }
            value = quint32(*v);
        } else {
            for (const QString &part : t.split(QLatin1Char('+'))) {
                const BitDefinition *b = entry.bitById(part.trimmed());
                if (!b || b->reserved) {
                    r.error = tr("'%1' is not a bit of '%2'").arg(part.trimmed(), entry.id);
                    break;
                }
                value |= b->mask();
            }
            if (!r.error.isEmpty())
                break;
        }
        if (entry.activationMask)
            value |= *entry.activationMask;
        r.words = {quint16(value)};
        break;
    }
    case ValueType::Text: {
        const QByteArray bytes = t.toLatin1();
        if (bytes.size() > entry.textBytes - 1 || QString::fromLatin1(bytes) != t) {
            r.error = tr("the text for '%1' must be at most %2 Latin-1 characters").arg(entry.id).arg(entry.textBytes - 1);
            break;
        }
        QByteArray padded = bytes;
        padded.resize(entry.wordCount() * 2, '\0');
        for (qsizetype i = 0; i < padded.size(); i += 2)
            r.words << quint16(quint8(padded[i]) << 8 | quint8(padded[i + 1]));
        break;
    }
    }
    return r;
}

} // namespace jumo
