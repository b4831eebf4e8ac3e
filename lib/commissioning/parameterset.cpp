#include "commissioning/parameterset.h"

#include "protocol/jsonfieldreader.h"
#include "protocol/valuecodec.h"

#include <QJsonDocument>
#include <QJsonObject>

namespace jumo {

namespace {

// As the device stores them, except that 0 and -0 are one value (0.0 == -0.0).
bool sameValue(const RegisterEntry &e, const RegisterMap &map, const QList<quint16> &a, const QList<quint16> &b)
{
    if (a == b)
        return true;
    if (e.type != ValueType::Float)
        return false;
    const WordOrder order = map.protocol.floatWordOrder;
    return ValueCodec::decodeFloat(a[0], a[1], order) == ValueCodec::decodeFloat(b[0], b[1], order);
}

} // namespace

bool ParameterSet::isParameter(const RegisterEntry &e)
{
    static const QStringList processControls{"command", "override", "binary_outputs", "digital_output",
                                             "external_input", "analog_output"};
    return e.isReadable() && e.isWritable() && !e.reserved && e.alias.isEmpty() && !e.isCommand()
            && !e.activationMask && !processControls.contains(e.control);
}

QStringList ParameterSet::parameterIds(const RegisterMap &map)
{
    QStringList ids;
    for (const RegisterEntry &e : map.entries()) {
        if (isParameter(e))
            ids << e.id;
    }
    return ids;
}

QByteArray ParameterSet::toJson() const
{
    QJsonObject identityObject;
    for (auto it = identity.cbegin(); it != identity.cend(); ++it)
        identityObject.insert(it.key(), it.value());
    QJsonObject valueObject;
    for (auto it = values.cbegin(); it != values.cend(); ++it)
        valueObject.insert(it.key(), it.value());
    const QJsonObject root{{"format", "jumo-parameters"},
                           {"version", formatVersion},
                           {"family", family},
                           {"address", address},
                           {"time", time.toUTC().toString(Qt::ISODateWithMs)},
                           {"softwareVersion", softwareVersion},
                           {"identity", identityObject},
                           {"values", valueObject}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::optional<ParameterSet> ParameterSet::fromJson(const QByteArray &json, QString *error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    if (parseError.error != QJsonParseError::NoError)
        return fail(tr("not a parameter file: %1 at byte %2").arg(parseError.errorString()).arg(parseError.offset));
    if (const qsizetype at = JsonFieldReader::controlCharacterAt(json); at >= 0)
        return fail(tr("not a parameter file: a control character at byte %1").arg(at));
    // A hand-edited file that names a value twice would have one of them written silently.
    QString key;
    if (const qsizetype at = JsonFieldReader::duplicateKeyAt(json, &key); at >= 0)
        return fail(tr("the parameter file names '%1' twice (again at byte %2): which value is meant is not clear")
                            .arg(key)
                            .arg(at));
    const QJsonObject root = doc.object();
    if (root.value("format") != QJsonValue(QStringLiteral("jumo-parameters")))
        return fail(tr("not a parameter file (no \"format\": \"jumo-parameters\")"));
    if (root.value("version") != QJsonValue(formatVersion))
        return fail(tr("parameter file version %1 is not supported (expected %2)")
                            .arg(root.value("version").toVariant().toString())
                            .arg(formatVersion));
    if (!root.value("family").isString() || !root.value("values").isObject())
        return fail(tr("the parameter file lacks \"family\" or \"values\""));
    // Strict like the maps: a file that was edited wrongly is refused, not half-read.
    JsonFieldReader fields{QString()};   // no source: the caller names the file
    fields.checkKeys(root, {"format", "version", "family", "address", "time", "softwareVersion", "identity", "values"},
                     QString());
    ParameterSet set;
    set.family = fields.requireString(root, "family", QString());
    set.address = fields.optionalInt(root, "address", 0, 255, QString()).value_or(0);
    const QString time = fields.optionalString(root, "time", QString());
    set.time = QDateTime::fromString(time, Qt::ISODateWithMs);
    if (!time.isEmpty() && !set.time.isValid())
        fields.fail(QString(), tr("'time' is no ISO 8601 time: %1").arg(time));
    set.softwareVersion = fields.optionalString(root, "softwareVersion", QString());
    if (root.contains("identity") && !root.value("identity").isObject())
        fields.fail(QString(), tr("'identity' must be an object"));
    const QJsonObject identityObject = root.value("identity").toObject();
    for (auto it = identityObject.begin(); it != identityObject.end(); ++it)
        set.identity.insert(it.key(), fields.optionalString(identityObject, it.key(), QStringLiteral("identity")));
    if (!fields.errors().isEmpty())
        return fail(fields.errors().join(QStringLiteral("; ")));
    const QJsonObject valueObject = root.value("values").toObject();
    for (auto it = valueObject.begin(); it != valueObject.end(); ++it) {
        if (!it.value().isString())
            return fail(tr("the value of '%1' must be a text").arg(it.key()));
        set.values.insert(it.key(), it.value().toString());
    }
    return set;
}

QString ParameterSet::incompatibility(const RegisterMap &map, const QString &deviceSoftwareVersion) const
{
    if (family != map.family)
        return tr("the file is for the family %1, the device is %2").arg(family, map.family);
    const auto prefix = [](const QString &v) { return v.trimmed().section(QLatin1Char('.'), 0, 1); };
    if (!softwareVersion.isEmpty() && !deviceSoftwareVersion.isEmpty()
        && prefix(softwareVersion) != prefix(deviceSoftwareVersion))
        return tr("the file is from software version %1, the device runs %2").arg(softwareVersion, deviceSoftwareVersion);
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        const RegisterEntry *e = map.entry(it.key());
        if (!e || !isParameter(*e))
            return tr("'%1' in the file is no parameter of %2").arg(it.key(), map.family);
        const EncodeResult encoded = ValueCodec::encode(*e, map, it.value());
        if (!encoded.ok())
            return tr("'%1' in the file: %2").arg(it.key(), encoded.error);
    }
    return {};
}

QList<ParameterDifference> ParameterSet::differences(const ParameterSet &other, const RegisterMap &map) const
{
    QList<ParameterDifference> out;
    for (const QString &id : parameterIds(map)) {
        const bool here = values.contains(id);
        const bool there = other.values.contains(id);
        if (!here && !there)
            continue;
        const RegisterEntry *e = map.entry(id);
        bool same = here && there;
        if (same) {
            const EncodeResult a = ValueCodec::encode(*e, map, values.value(id));
            const EncodeResult b = ValueCodec::encode(*e, map, other.values.value(id));
            same = a.ok() && b.ok() ? sameValue(*e, map, a.words, b.words) : values.value(id) == other.values.value(id);
        }
        if (same)
            continue;
        auto shown = [&](const QString &text) {
            const EncodeResult r = ValueCodec::encode(*e, map, text);
            return r.ok() ? ValueCodec::decode(*e, map, r.words).display : text;
        };
        out << ParameterDifference{id,
                                   e->label,
                                   e->unit,
                                   values.value(id),
                                   other.values.value(id),
                                   here ? shown(values.value(id)) : QString(),
                                   there ? shown(other.values.value(id)) : QString(),
                                   there};
    }
    return out;
}

QList<ParameterDifference> ParameterSet::toRestore(const QList<ParameterDifference> &differences)
{
    QList<ParameterDifference> out;
    for (const ParameterDifference &d : differences) {
        if (d.newHeld)
            out << d;
    }
    return out;
}

} // namespace jumo
