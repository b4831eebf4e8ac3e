#include "commissioning/parameterset.h"

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
    const QJsonObject root = doc.object();
    if (root.value("format").toString() != QLatin1String("jumo-parameters"))
        return fail(tr("not a parameter file (no \"format\": \"jumo-parameters\")"));
    if (root.value("version").toInt() != formatVersion)
        return fail(tr("parameter file version %1 is not supported (expected %2)")
                            .arg(root.value("version").toInt())
                            .arg(formatVersion));
    ParameterSet set;
    set.family = root.value("family").toString();
    set.address = root.value("address").toInt();
    set.time = QDateTime::fromString(root.value("time").toString(), Qt::ISODateWithMs);
    set.softwareVersion = root.value("softwareVersion").toString();
    if (set.family.isEmpty() || !root.value("values").isObject())
        return fail(tr("the parameter file lacks \"family\" or \"values\""));
    const QJsonObject identityObject = root.value("identity").toObject();
    for (auto it = identityObject.begin(); it != identityObject.end(); ++it)
        set.identity.insert(it.key(), it.value().toString());
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
                                   there ? shown(other.values.value(id)) : QString()};
    }
    return out;
}

} // namespace jumo
