#include "protocol/csv.h"
#include "mapcommands.h"

#include "commandparser.h"
#include "protocol/familyregistry.h"
#include "protocol/readplanner.h"
#include "protocol/valuecodec.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

namespace jumo {

namespace {


QString entryNotes(const RegisterEntry &e)
{
    QStringList parts;
    if (e.reserved)
        parts << QStringLiteral("reserved");
    if (e.alias.size())
        parts << QStringLiteral("alias of %1").arg(e.alias);
    if (!e.enumValues.isEmpty()) {
        QStringList values;
        for (auto it = e.enumValues.cbegin(); it != e.enumValues.cend(); ++it)
            values << QStringLiteral("%1 = %2").arg(it.key()).arg(it.value());
        parts << values.join(QStringLiteral("; "));
    }
    if (e.minimum || e.maximum)
        parts << QStringLiteral("range %1 to %2")
                         .arg(e.minimum ? ValueCodec::formatFloat(*e.minimum) : QStringLiteral("-"),
                              e.maximum ? ValueCodec::formatFloat(*e.maximum) : QStringLiteral("-"));
    if (!e.configuredUnit.isEmpty())
        parts << QStringLiteral("unit configured on the device: %1").arg(e.configuredUnit);
    if (e.activationMask)
        parts << QStringLiteral("activation %1").arg(formatAddress(*e.activationMask));
    if (e.restoreValue)
        parts << QStringLiteral("write %1 to return to the device's own value").arg(ValueCodec::formatFloat(*e.restoreValue));
    if (!e.precondition.isEmpty())
        parts << QStringLiteral("precondition: %1").arg(e.precondition);
    if (!e.notes.isEmpty())
        parts << e.notes;
    if (!e.erratum.isEmpty())
        parts << QStringLiteral("erratum: %1").arg(e.erratum);
    return parts.join(QStringLiteral(" | "));
}

QString bitNotes(const BitDefinition &b)
{
    QStringList parts{bitKindName(b.kind)};
    if (b.width > 1)
        parts << QStringLiteral("bits %1-%2").arg(b.bit).arg(b.bit + b.width - 1);
    if (b.reserved)
        parts << QStringLiteral("reserved");
    if (!b.notes.isEmpty())
        parts << b.notes;
    if (!b.erratum.isEmpty())
        parts << QStringLiteral("erratum: %1").arg(b.erratum);
    return parts.join(QStringLiteral(" | "));
}

// The manual's default as the map gives it: a number (an enum's value), true or false.
QString defaultText(const RegisterEntry &e)
{
    if (!e.defaultValue)
        return {};
    if (e.type == ValueType::Bool)
        return *e.defaultValue ? QStringLiteral("true") : QStringLiteral("false");
    return ValueCodec::formatFloat(*e.defaultValue);
}

QJsonObject entryJson(const RegisterEntry &e)
{
    QJsonObject o{{"address", formatAddress(e.address)}, {"id", e.id}, {"label", e.label},
                  {"type", valueTypeName(e.type)}, {"words", e.wordCount()}, {"access", accessName(e.access)},
                  {"storage", storageName(e.storage)}, {"unit", e.unit}, {"group", e.group}};
    if (!e.configuredUnit.isEmpty())
        o.insert("configuredUnit", e.configuredUnit);
    // The precision the values are shown with, the unit's default where the map names none.
    if (e.type == ValueType::Float)
        o.insert(e.precision.kind == DisplayPrecision::Kind::Decimals ? "decimals" : "significantDigits", e.precision.digits);
    if (e.type == ValueType::Text)
        o.insert("bytes", e.textBytes);
    if (e.minimum)
        o.insert("min", *e.minimum);
    if (e.maximum)
        o.insert("max", *e.maximum);
    if (e.defaultValue)
        o.insert("default", e.type == ValueType::Bool ? QJsonValue(*e.defaultValue != 0) : QJsonValue(*e.defaultValue));
    if (!e.enumValues.isEmpty()) {
        QJsonObject values;
        for (auto it = e.enumValues.cbegin(); it != e.enumValues.cend(); ++it)
            values.insert(QString::number(it.key()), it.value());
        o.insert("values", values);
    }
    if (!e.bits.isEmpty()) {
        QJsonArray bits;
        for (const BitDefinition &b : e.bits) {
            QJsonObject bo{{"bit", b.bit}, {"id", b.id}, {"label", b.label}, {"kind", bitKindName(b.kind)}};
            if (b.width > 1)
                bo.insert("width", b.width);
            if (b.reserved)
                bo.insert("reserved", true);
            if (!b.notes.isEmpty())
                bo.insert("notes", b.notes);
            if (!b.erratum.isEmpty())
                bo.insert("erratum", b.erratum);
            bits.append(bo);
        }
        o.insert("bits", bits);
    }
    if (e.activationMask)
        o.insert("activation", formatAddress(*e.activationMask));
    if (!e.control.isEmpty())
        o.insert("control", e.control);
    if (e.restoreValue)
        o.insert("restoreValue", *e.restoreValue);
    if (!e.precondition.isEmpty())
        o.insert("precondition", e.precondition);
    if (e.reserved)
        o.insert("reserved", true);
    if (!e.alias.isEmpty())
        o.insert("alias", e.alias);
    if (!e.notes.isEmpty())
        o.insert("notes", e.notes);
    if (!e.erratum.isEmpty())
        o.insert("erratum", e.erratum);
    return o;
}

} // namespace

MapCommands::MapCommands(const FamilyRegistry &registry, QTextStream &out, QTextStream &err)
    : m_registry(registry), m_out(out), m_err(err)
{
}

const RegisterMap *MapCommands::requireFamily(const QString &id)
{
    const auto map = m_registry.family(id);
    if (!map) {
        m_err << tr("unknown family '%1' (known: %2)").arg(id, m_registry.familyIds().join(QStringLiteral(", ")))
              << Qt::endl;
        return nullptr;
    }
    return map.get();
}

int MapCommands::families(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("families"), tr("Lists the device families and the map files they come from."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 0, 0))
        return *stop;
    for (const auto &map : m_registry.families()) {
        m_out << map->family << '\t' << map->name << '\t' << map->models.join(QStringLiteral(", ")) << '\t'
              << tr("%n registers", nullptr, int(map->entries().size())) << '\t' << map->sourceFile << Qt::endl;
    }
    for (const QString &error : m_registry.errors())
        m_err << tr("refused map file: %1").arg(error) << Qt::endl;
    return m_registry.errors().isEmpty() ? 0 : 1;
}

QString MapCommands::csvHeader()
{
    return QStringLiteral("address,bit,id,label,type,words,access,storage,unit,group,notes,precision,default");
}

QStringList MapCommands::csvRows(const RegisterMap &map)
{
    QStringList rows;
    for (const RegisterEntry &e : map.entries()) {
        const QString address = formatAddress(e.address);
        rows << QStringList{address, QString(), e.id, csvField(e.label), valueTypeName(e.type),
                            QString::number(e.wordCount()), accessName(e.access), storageName(e.storage),
                            csvField(e.unit), csvField(e.group), csvField(entryNotes(e)),
                            e.type == ValueType::Float ? e.precision.name() : QString(), defaultText(e)}
                        .join(QLatin1Char(','));
        for (const BitDefinition &b : e.bits) {
            rows << QStringList{address, QString::number(b.bit), e.id + QLatin1Char('.') + b.id, csvField(b.label),
                                b.width > 1 ? QStringLiteral("uint16") : QStringLiteral("bool"), QStringLiteral("1"),
                                accessName(e.access), storageName(e.storage), QString(), csvField(e.group),
                                csvField(bitNotes(b)), QString(), QString()}
                            .join(QLatin1Char(','));
        }
    }
    return rows;
}

int MapCommands::map(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("map"), tr("Prints the register map of a device family."));
    parser.addPositionalArgument(QStringLiteral("family"), tr("Family id, see 'jumoctl families'."));
    parser.addOption({QStringLiteral("csv"), tr("CSV: one row per register and one per bit of a bit field.")});
    parser.addOption({QStringLiteral("json"), tr("JSON: the family's facts and every register.")});
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 1, 1))
        return *stop;
    const bool csv = parser.isSet(QStringLiteral("csv"));
    const bool json = parser.isSet(QStringLiteral("json"));
    if (csv == json) {
        m_err << tr("jumoctl map: give exactly one of --csv and --json") << Qt::endl;
        return 2;
    }
    const RegisterMap *map = requireFamily(parser.positionalArguments().constFirst());
    if (!map)
        return 1;
    if (csv) {
        m_out << csvHeader() << '\n';
        for (const QString &row : csvRows(*map))
            m_out << row << '\n';
        m_out.flush();
        return 0;
    }
    QJsonArray entries;
    for (const RegisterEntry &e : map->entries())
        entries.append(entryJson(e));
    QJsonObject exceptions;
    for (auto it = map->exceptions.cbegin(); it != map->exceptions.cend(); ++it)
        exceptions.insert(QString::number(it.key()), it.value());
    const ProtocolInfo &p = map->protocol;
    QJsonObject protocol{{"maxReadWords", p.maxReadWords},
                         {"maxWriteWords", p.maxWriteWords},
                         {"floatWordOrder", wordOrderName(p.floatWordOrder)},
                         {"int32WordOrder", wordOrderName(p.int32WordOrder)},
                         {"baudRates", QJsonArray::fromVariantList(QVariantList(p.baudRates.cbegin(), p.baudRates.cend()))},
                         {"dataFormats", QJsonArray::fromStringList(p.dataFormats)},
                         {"addressMin", p.addressMin},
                         {"addressMax", p.addressMax},
                         {"alwaysAnswersAddress", p.alwaysAnswersAddress ? QJsonValue(*p.alwaysAnswersAddress) : QJsonValue()},
                         {"broadcast", p.broadcast},
                         {"processingTimeMaxMs", p.processingTimeMaxMs},
                         {"turnaroundMs", p.turnaroundMs},
                         {"busErrorTimeoutMs", p.busErrorTimeoutMs ? QJsonValue(*p.busErrorTimeoutMs) : QJsonValue()}};
    QJsonObject configuredUnits;
    for (auto it = map->configuredUnits.cbegin(); it != map->configuredUnits.cend(); ++it)
        configuredUnits.insert(it.key(), it.value());
    QJsonObject root{{"family", map->family}, {"name", map->name}, {"shortName", map->shortName},
                     {"models", QJsonArray::fromStringList(map->models)}, {"configuredUnits", configuredUnits},
                     {"manual", map->manual}, {"protocol", protocol}, {"exceptions", exceptions},
                     {"entries", entries}};
    if (map->errorValues)
        root.insert("errorValues", QJsonObject{{"underrange", map->errorValues->underrange},
                                               {"overrange", map->errorValues->overrange},
                                               {"invalid", map->errorValues->invalid}});
    m_out << QJsonDocument(root).toJson(QJsonDocument::Indented);
    m_out.flush();
    return 0;
}

int MapCommands::plan(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("plan"),
                         tr("Shows the read requests that poll the given entries (all readable entries if none)."));
    parser.addPositionalArgument(QStringLiteral("family"), tr("Family id."));
    parser.addPositionalArgument(QStringLiteral("id"), tr("Entry ids to read."), QStringLiteral("[id...]"));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 1))
        return *stop;
    QStringList ids = parser.positionalArguments();
    const RegisterMap *map = requireFamily(ids.takeFirst());
    if (!map)
        return 1;
    const ReadPlan plan = ReadPlanner::plan(*map, ids);
    for (const QString &error : plan.errors)
        m_err << error << Qt::endl;
    for (const ReadBlock &block : plan.blocks) {
        QStringList names;
        for (const RegisterEntry *e : block.entries)
            names << e->id;
        m_out << tr("read %1..%2 (%n words): ", nullptr, block.count)
                         .arg(formatAddress(block.start), formatAddress(block.end()))
              << names.join(QStringLiteral(", ")) << '\n';
    }
    m_out << tr("%n requests, ", nullptr, int(plan.blocks.size())) << tr("%n words", nullptr, plan.totalWords())
          << Qt::endl;
    return plan.errors.isEmpty() ? 0 : 1;
}

int MapCommands::decode(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("decode"),
                         tr("Decodes raw register words (hex, as read from the device) as an entry."));
    parser.addPositionalArgument(QStringLiteral("family"), tr("Family id."));
    parser.addPositionalArgument(QStringLiteral("id"), tr("Entry id."));
    parser.addPositionalArgument(QStringLiteral("word"), tr("Register words in hex, e.g. 70A3 4145."),
                                 QStringLiteral("word..."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 3))
        return *stop;
    QStringList args = parser.positionalArguments();
    const RegisterMap *map = requireFamily(args.takeFirst());
    if (!map)
        return 1;
    const QString id = args.takeFirst();
    const RegisterEntry *entry = map->entry(id);
    if (!entry) {
        m_err << tr("'%1' is not an entry of %2").arg(id, map->family) << Qt::endl;
        return 1;
    }
    QList<quint16> words;
    static const QRegularExpression hexWord(
            QRegularExpression::anchoredPattern(QStringLiteral("(0[xX])?[0-9A-Fa-f]{1,4}")));
    for (const QString &text : std::as_const(args)) {
        if (!hexWord.match(text).hasMatch()) {
            m_err << tr("'%1' is not a 16-bit hex word").arg(text) << Qt::endl;
            return 2;
        }
        const bool prefixed = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive);
        words << quint16((prefixed ? text.mid(2) : text).toUInt(nullptr, 16));
    }
    if (words.size() != entry->wordCount()) {
        m_err << tr("'%1' takes %2 words, %3 given").arg(id).arg(entry->wordCount()).arg(words.size()) << Qt::endl;
        return 2;
    }
    const DecodedValue v = ValueCodec::decode(*entry, *map, words);
    m_out << entry->id << " (" << formatAddress(entry->address) << ") = " << v.display;
    if (v.isOk() && !entry->unit.isEmpty())
        m_out << ' ' << entry->unit;
    m_out << " [" << valueStatusName(v.status) << ']';
    if (!v.isOk())
        m_out << ": " << ValueCodec::statusDescription(v.status, *map);
    m_out << Qt::endl;
    return v.status == ValueStatus::DecodeError ? 1 : 0;
}

} // namespace jumo
