#include "protocol/jsonfieldreader.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QSet>

#include <cmath>

namespace jumo {

namespace {

// anchoredPattern: \A...\z. A plain "^...$" lets a trailing newline through.
const QRegularExpression &idPattern()
{
    static const QRegularExpression pattern(QRegularExpression::anchoredPattern(QStringLiteral("[a-z][a-z0-9_]*")));
    return pattern;
}

const QRegularExpression &hex16Pattern()
{
    static const QRegularExpression pattern(QRegularExpression::anchoredPattern(QStringLiteral("0x[0-9A-Fa-f]{4}")));
    return pattern;
}

const QRegularExpression &decimalPattern()
{
    static const QRegularExpression pattern(QRegularExpression::anchoredPattern(QStringLiteral("0|[1-9][0-9]{0,8}")));
    return pattern;
}

} // namespace

QString JsonFieldReader::shown(const QJsonValue &value)
{
    if (value.isString())
        return value.toString();
    return QString::fromUtf8(QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact)).mid(1).chopped(1);
}

void JsonFieldReader::fail(const QString &where, const QString &problem)
{
    const QString located = where.isEmpty() ? problem : QStringLiteral("%1: %2").arg(where, problem);
    m_errors << (m_source.isEmpty() ? located : QStringLiteral("%1: %2").arg(m_source, located));
}

void JsonFieldReader::checkKeys(const QJsonObject &object, const QStringList &allowed, const QString &where)
{
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!allowed.contains(it.key()))
            fail(where, tr("unknown key '%1'").arg(it.key()));
    }
}

QString JsonFieldReader::requireString(const QJsonObject &object, const QString &key, const QString &where)
{
    const QJsonValue v = object.value(key);
    if (!v.isString() || v.toString().isEmpty()) {
        fail(where, tr("'%1' is missing or not a non-empty string").arg(key));
        return {};
    }
    return v.toString();
}

QString JsonFieldReader::optionalString(const QJsonObject &object, const QString &key, const QString &where)
{
    const QJsonValue v = object.value(key);
    if (v.isUndefined())
        return {};
    if (!v.isString()) {
        fail(where, tr("'%1' must be a string, not %2").arg(key, shown(v)));
        return {};
    }
    return v.toString();
}

QStringList JsonFieldReader::stringList(const QJsonObject &object, const QString &key, const QString &where)
{
    QStringList out;
    const QJsonValue v = object.value(key);
    if (v.isUndefined())
        return out;
    if (!v.isArray()) {
        fail(where, tr("'%1' must be an array of strings").arg(key));
        return out;
    }
    for (const QJsonValue &item : v.toArray()) {
        if (item.isString())
            out << item.toString();
        else
            fail(where, tr("'%1' must contain only strings, not %2").arg(key, shown(item)));
    }
    return out;
}

bool JsonFieldReader::optionalBool(const QJsonObject &object, const QString &key, bool defaultValue,
                                   const QString &where)
{
    const QJsonValue v = object.value(key);
    if (v.isUndefined())
        return defaultValue;
    if (!v.isBool()) {
        fail(where, tr("'%1' must be true or false, not %2").arg(key, shown(v)));
        return defaultValue;
    }
    return v.toBool();
}

std::optional<int> JsonFieldReader::optionalInt(const QJsonObject &object, const QString &key, int minimum,
                                                int maximum, const QString &where)
{
    const QJsonValue v = object.value(key);
    if (v.isUndefined() || v.isNull())
        return std::nullopt;
    const double d = v.toDouble();
    if (!v.isDouble() || std::floor(d) != d || d < minimum || d > maximum) {
        fail(where, tr("'%1' must be a whole number %2..%3, not %4").arg(key).arg(minimum).arg(maximum).arg(shown(v)));
        return std::nullopt;
    }
    return int(d);
}

int JsonFieldReader::requireInt(const QJsonObject &object, const QString &key, int minimum, int maximum,
                                const QString &where)
{
    if (!object.contains(key) || object.value(key).isNull()) {
        fail(where, tr("'%1' is missing").arg(key));
        return minimum;
    }
    return optionalInt(object, key, minimum, maximum, where).value_or(minimum);
}

std::optional<double> JsonFieldReader::optionalNumber(const QJsonObject &object, const QString &key,
                                                      const QString &where, double minimum, double maximum)
{
    const QJsonValue v = object.value(key);
    if (v.isUndefined() || v.isNull())
        return std::nullopt;
    if (!v.isDouble() || !std::isfinite(v.toDouble()) || v.toDouble() < minimum || v.toDouble() > maximum) {
        if (minimum <= -1e300)
            fail(where, tr("'%1' must be a number, not %2").arg(key, shown(v)));
        else
            fail(where, tr("'%1' must be a number %2..%3, not %4").arg(key).arg(minimum).arg(maximum).arg(shown(v)));
        return std::nullopt;
    }
    return v.toDouble();
}

QList<int> JsonFieldReader::intList(const QJsonObject &object, const QString &key, const QList<int> &allowed,
                                    const QString &where)
{
    QList<int> out;
    const QJsonValue v = object.value(key);
    if (!v.isArray() || v.toArray().isEmpty()) {
        fail(where, tr("'%1' must be a non-empty array of numbers").arg(key));
        return out;
    }
    QStringList allowedText;
    for (int a : allowed)
        allowedText << QString::number(a);
    for (const QJsonValue &item : v.toArray()) {
        const double d = item.toDouble();
        if (!item.isDouble() || std::floor(d) != d || !allowed.contains(int(d)) || int(d) != d)
            fail(where, tr("'%1' may contain only %2, not %3").arg(key, allowedText.join(QStringLiteral(", ")), shown(item)));
        else if (out.contains(int(d)))
            fail(where, tr("'%1' lists %2 twice").arg(key).arg(int(d)));
        else
            out << int(d);
    }
    return out;
}

std::optional<quint16> JsonFieldReader::parseHex16(const QJsonValue &value, const QString &key, const QString &where)
{
    const QString text = value.toString();
    if (!value.isString() || !hex16Pattern().match(text).hasMatch()) {
        fail(where, tr("'%1' must be 0x followed by 4 hex digits, not '%2'").arg(key, shown(value)));
        return std::nullopt;
    }
    return quint16(text.mid(2).toUInt(nullptr, 16));
}

std::optional<int> JsonFieldReader::decimalKey(const QString &key, int minimum, int maximum)
{
    if (!decimalPattern().match(key).hasMatch())
        return std::nullopt;
    const int value = key.toInt();
    if (value < minimum || value > maximum)
        return std::nullopt;
    return value;
}

qsizetype JsonFieldReader::controlCharacterAt(const QByteArray &json)
{
    for (qsizetype i = 0; i < json.size(); ++i) {
        const auto c = uchar(json[i]);
        if (c < 0x20 && c != '\t' && c != '\n' && c != '\r')
            return i;
    }
    return -1;
}

qsizetype JsonFieldReader::duplicateKeyAt(const QByteArray &json, QString *key)
{
    // The keys of each open object; an array holds none (std::nullopt).
    QList<std::optional<QSet<QString>>> open;
    for (qsizetype i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (c == '{') {
            open.append(QSet<QString>());
        } else if (c == '[') {
            open.append(std::nullopt);
        } else if ((c == '}' || c == ']') && !open.isEmpty()) {
            open.removeLast();
        } else if (c == '"') {
            const qsizetype begin = i;
            bool escaped = false;
            for (++i; i < json.size(); ++i) {
                if (escaped)
                    escaped = false;
                else if (json[i] == '\\')
                    escaped = true;
                else if (json[i] == '"')
                    break;
            }
            qsizetype next = i + 1;
            while (next < json.size() && (json[next] == ' ' || json[next] == '\t' || json[next] == '\n' || json[next] == '\r'))
                ++next;
            if (next >= json.size() || json[next] != ':' || open.isEmpty() || !open.last())
                continue;
            // "\u0061" and "a" are one key: let Qt unescape it.
            const QByteArray quoted = json.mid(begin, i + 1 - begin);
            const QString name = quoted.contains('\\')
                    ? QJsonDocument::fromJson("[" + quoted + "]").array().at(0).toString()
                    : QString::fromUtf8(quoted.mid(1, quoted.size() - 2));
            if (open.last()->contains(name)) {
                if (key)
                    *key = name;
                return begin;
            }
            open.last()->insert(name);
        }
    }
    return -1;
}

bool JsonFieldReader::isId(const QString &text)
{
    return idPattern().match(text).hasMatch();
}

} // namespace jumo
