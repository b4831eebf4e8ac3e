// Reads the fields of a JSON document strictly and collects every problem with where it
// is: no coercion ("16" is no number, 2.5 no whole number, "yes" no boolean), every
// number within its range, text patterns matched as a whole. The map loader is built
// on it, so that a user fixing a file sees all that is wrong in one go.
#pragma once

#include <QCoreApplication>
#include <QJsonObject>
#include <QJsonValue>
#include <QStringList>

#include <optional>

namespace jumo {

class JsonFieldReader
{
    Q_DECLARE_TR_FUNCTIONS(jumo::MapLoader)

public:
    // Messages start with the source ("file: "), unless it is empty.
    explicit JsonFieldReader(QString source) : m_source(std::move(source)) { }

    const QString &source() const { return m_source; }
    const QStringList &errors() const { return m_errors; }
    void fail(const QString &where, const QString &problem);

    void checkKeys(const QJsonObject &object, const QStringList &allowed, const QString &where);
    // Strings: a missing optional one is empty.
    QString requireString(const QJsonObject &object, const QString &key, const QString &where);
    QString optionalString(const QJsonObject &object, const QString &key, const QString &where);
    QStringList stringList(const QJsonObject &object, const QString &key, const QString &where);
    bool optionalBool(const QJsonObject &object, const QString &key, bool defaultValue, const QString &where);
    // Whole numbers within [minimum, maximum]; null counts as missing.
    std::optional<int> optionalInt(const QJsonObject &object, const QString &key, int minimum, int maximum,
                                   const QString &where);
    int requireInt(const QJsonObject &object, const QString &key, int minimum, int maximum, const QString &where);
    std::optional<double> optionalNumber(const QJsonObject &object, const QString &key, const QString &where,
                                         double minimum = -1e300, double maximum = 1e300);
    // A non-empty array of whole numbers, each one of allowed.
    QList<int> intList(const QJsonObject &object, const QString &key, const QList<int> &allowed, const QString &where);
    // "0x" and four hex digits, as the manuals write addresses.
    std::optional<quint16> parseHex16(const QJsonValue &value, const QString &key, const QString &where);
    // A decimal key of an object ("2", not "02" or " 2"), within [minimum, maximum].
    static std::optional<int> decimalKey(const QString &key, int minimum, int maximum);
    // A JSON value as the file spells it, for messages.
    static QString shown(const QJsonValue &value);
    // Lower case letters, digits and '_', starting with a letter; the whole string.
    static bool isId(const QString &text);
    // Where the text has a raw control character (JSON allows only tab, CR and LF
    // between tokens, none in strings; Qt's parser lets a NUL through), or -1.
    static qsizetype controlCharacterAt(const QByteArray &json);
    // Where an object of the text names a key a second time, or -1; key: that key.
    // Qt's parser keeps one of the two values silently. For text Qt has parsed.
    static qsizetype duplicateKeyAt(const QByteArray &json, QString *key = nullptr);

private:
    QString m_source;
    QStringList m_errors;
};

} // namespace jumo
