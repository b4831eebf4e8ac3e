#include "protocol/maploader.h"

#include "protocol/jsonfieldreader.h"
#include "protocol/overlapcheck.h"
#include "protocol/regularfile.h"
#include "protocol/valuecodec.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QSet>

#include <cmath>
#include <limits>

Q_LOGGING_CATEGORY(lcMap, "jumo.map", QtWarningMsg)

namespace jumo {

namespace {

// The values a type can hold: what min, max and a default must lie within.
std::pair<double, double> typeRange(ValueType type)
{
    switch (type) {
    case ValueType::Int16: return {-32768, 32767};
    case ValueType::UInt16: return {0, 65535};
    case ValueType::Int32: return {-2147483648.0, 2147483647.0};
    case ValueType::UInt32: return {0, 4294967295.0};
    case ValueType::Enum:
    case ValueType::Bitfield: return {0, 65535};
    case ValueType::Bool: return {0, 1};
    case ValueType::Float:
    case ValueType::Text: break;
    }
    return {-double(std::numeric_limits<float>::max()), double(std::numeric_limits<float>::max())};
}

// Walks one JSON document and collects every problem instead of stopping at the first,
// so a user fixing a file sees all that is wrong in one go.
class MapParser : private JsonFieldReader
{
    Q_DECLARE_TR_FUNCTIONS(jumo::MapLoader)

public:
    explicit MapParser(QString source) : JsonFieldReader(std::move(source)) { }

    MapLoadResult parse(const QByteArray &json)
    {
        QJsonParseError parseError;
        const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
        if (parseError.error != QJsonParseError::NoError) {
            fail(QString(), tr("malformed JSON at byte %1: %2").arg(parseError.offset).arg(parseError.errorString()));
            return finish(std::nullopt);
        }
        if (const qsizetype at = controlCharacterAt(json); at >= 0) {
            fail(QString(), tr("malformed JSON at byte %1: a control character").arg(at));
            return finish(std::nullopt);
        }
        QString key;
        if (const qsizetype at = duplicateKeyAt(json, &key); at >= 0) {
            // Qt keeps one of the two values silently.
            fail(QString(), tr("malformed JSON at byte %1: '%2' given twice in one object").arg(at).arg(key));
            return finish(std::nullopt);
        }
        if (!doc.isObject()) {
            fail(QString(), tr("the top level must be a JSON object"));
            return finish(std::nullopt);
        }
        return finish(parseMap(doc.object()));
    }

private:
    MapLoadResult finish(std::optional<RegisterMap> map)
    {
        MapLoadResult result;
        result.errors = errors();
        if (errors().isEmpty())
            result.map = std::move(map);
        for (const QString &e : errors())
            qCDebug(lcMap).noquote() << e;
        return result;
    }

    std::optional<RegisterMap> parseMap(const QJsonObject &root)
    {
        checkKeys(root, {"format", "family", "name", "shortName", "models", "manual", "description", "protocol",
                         "identify", "scanPriority", "exceptions", "errorValues", "configuredUnits", "simulation",
                         "overview", "faceplate", "identity", "entries"},
                  QString());
        RegisterMap map;
        map.sourceFile = source();
        requireInt(root, "format", 1, 1, QString());
        map.family = requireString(root, "family", QString());
        if (!map.family.isEmpty() && !isId(map.family))
            fail(QString(), tr("family id '%1' must be lower case letters, digits and '_'").arg(map.family));
        map.name = requireString(root, "name", QString());
        checkShownText(map.name, QStringLiteral("name"), QString());
        map.shortName = optionalString(root, "shortName", QString());
        checkShownText(map.shortName, QStringLiteral("shortName"), QString());
        if (root.contains("shortName") && (map.shortName.trimmed().isEmpty() || map.shortName.size() > 24))
            fail(QString(), tr("'shortName' must be 1 to 24 characters, not '%1'").arg(map.shortName.left(40)));
        if (map.shortName.isEmpty())
            map.shortName = map.name;
        map.manual = optionalString(root, "manual", QString());
        map.description = optionalString(root, "description", QString());
        map.models = stringList(root, "models", QString());
        map.scanPriority = optionalInt(root, "scanPriority", 0, 1000, QString()).value_or(100);

        parseProtocol(root.value("protocol"), map.protocol);
        parseIdentify(root.value("identify"), map.identify);
        parseExceptions(root.value("exceptions"), map.exceptions);
        parseErrorValues(root, map.errorValues);
        parseConfiguredUnits(root.value("configuredUnits"), map.configuredUnits);

        const QJsonValue entries = root.value("entries");
        if (!entries.isArray() || entries.toArray().isEmpty()) {
            fail(QString(), tr("'entries' must be a non-empty array"));
            return std::nullopt;
        }
        QList<RegisterEntry> parsed;
        int index = 0;
        for (const QJsonValue &value : entries.toArray()) {
            if (std::optional<RegisterEntry> e = parseEntry(value, index++))
                parsed << *e;
        }
        for (const RegisterEntry &e : std::as_const(parsed)) {
            if (!e.configuredUnit.isEmpty() && !map.configuredUnits.contains(e.configuredUnit))
                fail(tr("entry '%1' (%2)").arg(e.id, formatAddress(e.address)),
                     tr("'configuredUnit' names '%1', which 'configuredUnits' does not define").arg(e.configuredUnit));
        }
        checkEntries(parsed);
        map.setEntries(std::move(parsed));
        checkStateSources(map);
        if (root.contains("simulation"))
            parseSimulation(root.value("simulation"), map);
        for (const char *key : {"overview", "identity"}) {
            QStringList &ids = QLatin1String(key) == QLatin1String("overview") ? map.overview : map.identity;
            for (const QString &id : stringList(root, QLatin1String(key), QString())) {
                if (const RegisterEntry *e = map.entry(id); e && e->isReadable())
                    ids << id;
                else
                    fail(QLatin1String(key), tr("'%1' is not a readable entry").arg(id));
            }
        }
        if (root.contains("faceplate"))
            parseFaceplate(root.value("faceplate"), map);
        else
            map.faceplate.values = defaultFaceplateValues(map);
        for (FaceplateValue &v : map.faceplate.values) {
            if (const RegisterEntry *e = map.entry(v.entry); e && v.label.isEmpty())
                v.label = e->label;
        }
        map.assignPollClasses();
        return map;
    }

    static constexpr int maxFaceplateValues = 16;

    // The overview's values the HMI reads, as many as a faceplate shows.
    static QList<FaceplateValue> defaultFaceplateValues(const RegisterMap &map)
    {
        QList<FaceplateValue> values;
        for (const QString &id : map.overview) {
            const RegisterEntry *e = map.entry(id);
            if (!e || !e->alias.isEmpty() || e->reserved || values.size() == maxFaceplateValues)
                continue;
            FaceplateValue value;
            value.entry = id;
            values << value;
        }
        return values;
    }

    // A readable bool entry or a readable single bit ("entry.bit"). Not of an alias or a
    // reserve: the HMI reads and shows neither, so the state would stay unknown forever.
    void checkStateReference(const RegisterMap &map, const QString &reference, const QString &where)
    {
        if (!checkReference(map, reference, where))
            return;
        const RegisterEntry *e = map.entry(reference.section(QLatin1Char('.'), 0, 0));
        const QString bit = reference.section(QLatin1Char('.'), 1);
        const bool single = bit.isEmpty() ? e->type == ValueType::Bool : e->bitById(bit)->width == 1;
        if (!e->isReadable() || !single || !e->alias.isEmpty() || e->reserved)
            fail(where, tr("'%1' must be a readable bool entry or a single bit of a readable bit field").arg(reference));
    }

    // A number, or an enum whose every text starts with one ("100 A"): what a bar, its
    // scale and a program's segments and time are made of.
    static bool isNumeric(const RegisterEntry &e)
    {
        if (e.type == ValueType::Enum) {
            bool numbers = !e.enumValues.isEmpty();
            for (const QString &text : e.enumValues)
                numbers = numbers && leadingNumber(text).has_value();
            return numbers;
        }
        return e.type != ValueType::Text && e.type != ValueType::Bitfield && e.type != ValueType::Bool;
    }

    QList<FaceplateState> faceplateStates(const RegisterMap &map, const QJsonObject &o, const char *key,
                                          const QString &where)
    {
        QList<FaceplateState> states;
        const QJsonValue value = o.value(QLatin1String(key));
        if (value.isUndefined())
            return states;
        if (!value.isArray()) {
            fail(where, tr("'%1' must be an array").arg(QLatin1String(key)));
            return states;
        }
        int index = 0;
        for (const QJsonValue &v : value.toArray()) {
            const QString stateWhere = QStringLiteral("%1.%2[%3]").arg(where, QLatin1String(key)).arg(index++);
            const QJsonObject s = v.toObject();
            checkKeys(s, {"when", "text", "progress"}, stateWhere);
            FaceplateState state;
            state.when = requireString(s, "when", stateWhere);
            state.text = requireString(s, "text", stateWhere);
            checkShownText(state.text, QStringLiteral("text"), stateWhere);
            state.progress = optionalBool(s, "progress", true, stateWhere);
            if (!state.when.isEmpty())
                checkStateReference(map, state.when, stateWhere);
            states << state;
        }
        return states;
    }

    // What an entry of the faceplate is for: shown as it is, drawn as a bar, the scale of a
    // bar, or counted (a program's segments and time left).
    enum class FaceplateUse { Shown, Bar, Scale, Count };

    // A readable entry the HMI reads (no alias, no reserve); a number where it is drawn,
    // scaled or counted.
    void checkFaceplateEntry(const RegisterMap &map, const QString &id, const QString &where, FaceplateUse use)
    {
        const RegisterEntry *e = map.entry(id);
        if (!e || !e->isReadable() || !e->alias.isEmpty()) {
            fail(where, tr("'%1' is not a readable entry").arg(id));
            return;
        }
        if (e->reserved) {
            fail(where, tr("'%1' is a reserve, which the HMI does not read").arg(id));
            return;
        }
        if (use == FaceplateUse::Shown || isNumeric(*e))
            return;
        if (use == FaceplateUse::Scale)
            fail(where, tr("the scale '%1' must be a number, or an enum whose every text starts with one").arg(id));
        else if (use == FaceplateUse::Bar)
            fail(where, tr("'%1' has a bar, so it must be a number, or an enum whose every text starts with one").arg(id));
        else
            fail(where, tr("'%1' must be a number").arg(id));
    }

    void parseFaceplate(const QJsonValue &value, RegisterMap &map)
    {
        const QString where = QStringLiteral("faceplate");
        if (!value.isObject()) {
            fail(QString(), tr("'faceplate' must be an object"));
            return;
        }
        const QJsonObject o = value.toObject();
        checkKeys(o, {"kind", "primary", "primaryLabel", "values", "modes", "modeOtherwise", "modeNote", "program"}, where);
        FaceplateSpec spec;
        const QString kind = requireString(o, "kind", where);
        if (kind == QLatin1String("process_controller"))
            spec.kind = FaceplateSpec::Kind::ProcessController;
        else if (kind != QLatin1String("power_unit") && !kind.isEmpty())
            fail(where, tr("unknown kind '%1' (expected power_unit or process_controller)").arg(kind));
        spec.primary = optionalString(o, "primary", where);
        spec.primaryLabel = optionalString(o, "primaryLabel", where);
        if (const RegisterEntry *e = map.entry(spec.primary); e && spec.primaryLabel.isEmpty())
            spec.primaryLabel = e->label;
        if (!spec.primary.isEmpty())
            checkFaceplateEntry(map, spec.primary, where + QStringLiteral(".primary"), FaceplateUse::Shown);
        const QJsonValue values = o.value("values");
        if (!values.isArray() || values.toArray().isEmpty()) {
            fail(where, tr("'values' must be a non-empty array"));
        } else if (values.toArray().size() > maxFaceplateValues) {
            // A faceplate is read at a glance; a taller one pushes its alarms out of sight
            // and makes every faceplate of its row as tall.
            fail(where, tr("'values' has %1 rows; a faceplate shows at most %2").arg(values.toArray().size()).arg(maxFaceplateValues));
        } else {
            int index = 0;
            for (const QJsonValue &v : values.toArray()) {
                const QString valueWhere = QStringLiteral("%1.values[%2]").arg(where).arg(index++);
                const QJsonObject vo = v.toObject();
                checkKeys(vo, {"entry", "label", "scale", "min", "max", "from"}, valueWhere);
                FaceplateValue fv;
                fv.entry = requireString(vo, "entry", valueWhere);
                fv.label = optionalString(vo, "label", valueWhere);
                checkShownText(fv.label, QStringLiteral("label"), valueWhere);
                const QString scale = optionalString(vo, "scale", valueWhere);
                if (scale == QLatin1String("range")) {
                    fv.scale = FaceplateValue::Scale::Range;
                    fv.barMin = optionalNumber(vo, "min", valueWhere).value_or(0);
                    fv.barMax = optionalNumber(vo, "max", valueWhere).value_or(100);
                    if (!(fv.barMax > fv.barMin))
                        fail(valueWhere, tr("'max' must be above 'min'"));
                } else if (scale == QLatin1String("nominal") || scale == QLatin1String("limit")) {
                    fv.scale = scale == QLatin1String("nominal") ? FaceplateValue::Scale::Nominal
                                                                  : FaceplateValue::Scale::Limit;
                    fv.scaleFrom = stringList(vo, "from", valueWhere);
                    if (fv.scaleFrom.isEmpty() || fv.scaleFrom.size() > 2)
                        fail(valueWhere, tr("'from' names one entry, or two whose product is the scale"));
                    for (const QString &id : std::as_const(fv.scaleFrom))
                        checkFaceplateEntry(map, id, valueWhere, FaceplateUse::Scale);
                } else if (!scale.isEmpty()) {
                    fail(valueWhere, tr("unknown scale '%1' (expected range, nominal or limit)").arg(scale));
                }
                if (!fv.entry.isEmpty())
                    checkFaceplateEntry(map, fv.entry, valueWhere,
                                        fv.scale == FaceplateValue::Scale::None ? FaceplateUse::Shown : FaceplateUse::Bar);
                if (fv.scale != FaceplateValue::Scale::Range && (vo.contains("min") || vo.contains("max")))
                    fail(valueWhere, tr("'min' and 'max' are only for the scale 'range'"));
                if (fv.scale == FaceplateValue::Scale::None || fv.scale == FaceplateValue::Scale::Range) {
                    if (vo.contains("from"))
                        fail(valueWhere, tr("'from' is only for the scales 'nominal' and 'limit'"));
                }
                spec.values << fv;
            }
        }
        spec.modes = faceplateStates(map, o, "modes", where);
        spec.modeOtherwise = optionalString(o, "modeOtherwise", where);
        spec.modeNote = optionalString(o, "modeNote", where);
        if (o.contains("program") && !o.value("program").isObject()) {
            fail(where, tr("'program' must be an object"));
        } else if (o.contains("program")) {
            const QString programWhere = where + QStringLiteral(".program");
            const QJsonObject p = o.value("program").toObject();
            checkKeys(p, {"segment", "segments", "timeLeft", "states", "otherwise"}, programWhere);
            spec.programSegment = requireString(p, "segment", programWhere);
            spec.programSegments = requireString(p, "segments", programWhere);
            spec.programTimeLeft = requireString(p, "timeLeft", programWhere);
            for (const QString &id : {spec.programSegment, spec.programSegments, spec.programTimeLeft}) {
                if (!id.isEmpty())
                    checkFaceplateEntry(map, id, programWhere, FaceplateUse::Count);
            }
            spec.programStates = faceplateStates(map, p, "states", programWhere);
            spec.programOtherwise = optionalString(p, "otherwise", programWhere);
        }
        map.faceplate = spec;
    }

    void parseProtocol(const QJsonValue &value, ProtocolInfo &p)
    {
        const QString where = QStringLiteral("protocol");
        if (!value.isObject()) {
            fail(QString(), tr("'protocol' must be an object"));
            return;
        }
        const QJsonObject o = value.toObject();
        checkKeys(o, {"readFunctions", "writeFunctions", "maxReadWords", "maxWriteWords", "floatWordOrder",
                      "int32WordOrder", "baudRates", "dataFormats", "addressMin", "addressMax",
                      "alwaysAnswersAddress", "broadcast", "processingTimeMaxMs", "turnaroundMs",
                      "minResponseTimeMaxMs", "busErrorTimeoutMs", "notes"},
                  where);
        p.readFunctions = intList(o, "readFunctions", {3, 4}, where);
        p.writeFunctions = intList(o, "writeFunctions", {6, 16}, where);
        p.maxReadWords = requireInt(o, "maxReadWords", 1, 127, where);
        p.maxWriteWords = requireInt(o, "maxWriteWords", 1, 127, where);
        for (const char *key : {"floatWordOrder", "int32WordOrder"}) {
            const QString name = optionalString(o, QLatin1String(key), where);
            const std::optional<WordOrder> order = wordOrderFromName(name);
            if (!order)
                fail(where, tr("'%1' must be ABCD, CDAB, BADC or DCBA, not '%2'").arg(key, name));
            else if (QLatin1String(key) == QLatin1String("floatWordOrder"))
                p.floatWordOrder = *order;
            else
                p.int32WordOrder = *order;
        }
        // The standard rates of a serial line; anything else is a typo.
        p.baudRates = intList(o, "baudRates", {1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200}, where);
        for (const QString &f : stringList(o, "dataFormats", where)) {
            static const QStringList known{"8N1", "8E1", "8O1", "8N2"};
            if (!known.contains(f))
                fail(where, tr("unknown data format '%1'").arg(f));
            p.dataFormats << f;
        }
        if (p.dataFormats.isEmpty())
            fail(where, tr("'dataFormats' must list at least one format"));
        p.addressMin = requireInt(o, "addressMin", 1, 255, where);
        p.addressMax = requireInt(o, "addressMax", 1, 255, where);
        if (p.addressMin > p.addressMax)
            fail(where, tr("address range %1..%2 is empty").arg(p.addressMin).arg(p.addressMax));
        p.alwaysAnswersAddress = optionalInt(o, "alwaysAnswersAddress", 1, 255, where);
        if (p.alwaysAnswersAddress && *p.alwaysAnswersAddress > 247 && *p.alwaysAnswersAddress != 255)
            fail(where, tr("'alwaysAnswersAddress' must be 1..247 or 255, not %1").arg(*p.alwaysAnswersAddress));
        p.broadcast = optionalBool(o, "broadcast", false, where);
        // Bounds the manuals make plausible: a device that needs longer is broken, and a
        // typo here would make every timeout on the line minutes long.
        p.processingTimeMaxMs = optionalNumber(o, "processingTimeMaxMs", where, 0, 1000).value_or(-1);
        if (!o.contains("processingTimeMaxMs"))
            fail(where, tr("'processingTimeMaxMs' is missing"));
        p.turnaroundMs = optionalNumber(o, "turnaroundMs", where, 0, 100).value_or(0);
        p.minResponseTimeMaxMs = optionalNumber(o, "minResponseTimeMaxMs", where, 0, 1000).value_or(0);
        p.busErrorTimeoutMs = optionalInt(o, "busErrorTimeoutMs", 100, 3600000, where);
        p.notes = optionalString(o, "notes", where);
    }

    void parseIdentify(const QJsonValue &value, QList<IdentifyProbe> &probes)
    {
        if (!value.isArray() || value.toArray().isEmpty()) {
            fail(QString(), tr("'identify' must be a non-empty array of probes"));
            return;
        }
        int index = 0;
        for (const QJsonValue &v : value.toArray()) {
            const QString where = QStringLiteral("identify[%1]").arg(index++);
            if (!v.isObject()) {
                fail(where, tr("a probe must be an object"));
                continue;
            }
            const QJsonObject o = v.toObject();
            checkKeys(o, {"address", "words", "textContains", "maskNonZero", "answers", "exception"}, where);
            IdentifyProbe probe;
            probe.address = parseHex16(o.value("address"), "address", where).value_or(0);
            probe.words = optionalInt(o, "words", 1, 125, where).value_or(1);
            int tests = 0;
            if (o.contains("textContains")) {
                probe.test = ProbeTest::TextContains;
                probe.text = requireString(o, "textContains", where);
                ++tests;
            }
            if (o.contains("maskNonZero")) {
                probe.test = ProbeTest::MaskNonZero;
                probe.mask = parseHex16(o.value("maskNonZero"), "maskNonZero", where).value_or(0);
                ++tests;
            }
            if (o.contains("answers")) {
                probe.test = ProbeTest::Answers;
                if (o.value("answers") != QJsonValue(true))
                    fail(where, tr("'answers' can only be true"));
                ++tests;
            }
            if (o.contains("exception")) {
                probe.test = ProbeTest::Exception;
                probe.exceptionCode = requireInt(o, "exception", 1, 255, where);
                ++tests;
            }
            if (tests != 1)
                fail(where, tr("a probe needs exactly one of textContains, maskNonZero, answers, exception"));
            probes << probe;
        }
    }

    void parseExceptions(const QJsonValue &value, QMap<int, QString> &exceptions)
    {
        if (!value.isObject() || value.toObject().isEmpty()) {
            fail(QString(), tr("'exceptions' must be an object mapping codes to meanings"));
            return;
        }
        const QJsonObject o = value.toObject();
        for (auto it = o.begin(); it != o.end(); ++it) {
            const std::optional<int> code = decimalKey(it.key(), 1, 255);
            if (!code || !it.value().isString())
                fail(QStringLiteral("exceptions"), tr("'%1' is not an exception code with a text").arg(it.key()));
            else
                exceptions.insert(*code, it.value().toString());
        }
    }

    void parseErrorValues(const QJsonObject &root, std::optional<ErrorValueTexts> &out)
    {
        const QJsonValue value = root.value("errorValues");
        if (value.isNull())
            return;
        if (!value.isObject()) {
            fail(QString(), tr("'errorValues' must be an object or null"));
            return;
        }
        const QJsonObject o = value.toObject();
        const QString where = QStringLiteral("errorValues");
        checkKeys(o, {"underrange", "overrange", "invalid"}, where);
        out = ErrorValueTexts{requireString(o, "underrange", where), requireString(o, "overrange", where),
                              requireString(o, "invalid", where)};
    }

    void parseConfiguredUnits(const QJsonValue &value, QMap<QString, QString> &out)
    {
        const QString where = QStringLiteral("configuredUnits");
        if (value.isUndefined())
            return;
        if (!value.isObject()) {
            fail(QString(), tr("'configuredUnits' must be an object mapping ids to what decides the unit"));
            return;
        }
        const QJsonObject o = value.toObject();
        for (auto it = o.begin(); it != o.end(); ++it) {
            if (!isId(it.key()))
                fail(where, tr("'%1' is no id (lower case letters, digits and '_')").arg(it.key().left(40)));
            else if (!it.value().isString() || it.value().toString().trimmed().isEmpty())
                fail(where, tr("'%1' needs a text that says what decides the unit").arg(it.key()));
            else
                out.insert(it.key(), it.value().toString());
        }
    }

    // Floats only: "decimals" (0..6) or "significantDigits" (1..7, a float's own), not
    // both; without either, the unit's default.
    void parsePrecision(const QJsonObject &o, RegisterEntry &e, const QString &where)
    {
        const bool hasDecimals = o.contains("decimals");
        const bool hasSignificant = o.contains("significantDigits");
        if ((hasDecimals || hasSignificant) && e.type != ValueType::Float) {
            fail(where, tr("'decimals' and 'significantDigits' are only for floats"));
            return;
        }
        if (hasDecimals && hasSignificant) {
            fail(where, tr("give 'decimals' or 'significantDigits', not both"));
            return;
        }
        e.precision = DisplayPrecision::defaultForUnit(e.unit);
        if (const std::optional<int> n = optionalInt(o, "decimals", 0, 6, where)) {
            e.precision = DisplayPrecision::decimals(*n);
            e.precisionFromMap = true;
        } else if (const std::optional<int> n = optionalInt(o, "significantDigits", 1, 7, where)) {
            e.precision = DisplayPrecision::significant(*n);
            e.precisionFromMap = true;
        }
    }

    // A text shown in lists, tables and on terminals: a control character in it (a line
    // end, an escape sequence) would break the row or drive the screen.
    void checkShownText(const QString &text, const QString &key, const QString &where)
    {
        for (const QChar c : text) {
            if (c.category() == QChar::Other_Control) {
                fail(where, tr("'%1' contains a control character (U+%2)")
                                    .arg(key)
                                    .arg(int(c.unicode()), 4, 16, QLatin1Char('0')));
                return;
            }
        }
    }

    std::optional<RegisterEntry> parseEntry(const QJsonValue &value, int index)
    {
        if (!value.isObject()) {
            fail(tr("entry #%1").arg(index), tr("an entry must be an object"));
            return std::nullopt;
        }
        const QJsonObject o = value.toObject();
        RegisterEntry e;
        const QString rawId = o.value("id").toString().left(40);
        const QString where = rawId.isEmpty()
                ? tr("entry #%1 (%2)").arg(index).arg(o.value("address").toString())
                : tr("entry '%1' (%2)").arg(rawId, o.value("address").toString());
        const qsizetype errorsBefore = errors().size();

        checkKeys(o, {"address", "id", "label", "type", "bytes", "words", "access", "storage", "unit", "configuredUnit",
                      "decimals", "significantDigits", "group", "min", "max", "values", "bits", "activation", "action", "control", "restoreValue", "precondition",
                      "reserved", "alias", "notes", "erratum", "default", "poll"},
                  where);
        e.address = parseHex16(o.value("address"), "address", where).value_or(0);
        e.id = requireString(o, "id", where);
        if (!e.id.isEmpty() && !isId(e.id))
            fail(where, tr("id must be lower case letters, digits and '_'"));
        e.label = requireString(o, "label", where);
        e.group = requireString(o, "group", where);
        checkShownText(e.label, QStringLiteral("label"), where);
        checkShownText(e.group, QStringLiteral("group"), where);

        const QString typeName = optionalString(o, "type", where);
        if (const std::optional<ValueType> t = valueTypeFromName(typeName))
            e.type = *t;
        else
            fail(where, tr("unknown type '%1' (expected float, int16, uint16, int32, uint32, bool, enum, bitfield or text)")
                            .arg(typeName));

        const QString accessText = optionalString(o, "access", where);
        if (const std::optional<Access> a = accessFromName(accessText))
            e.access = *a;
        else
            fail(where, tr("unknown access '%1' (expected R, W or RW)").arg(accessText));

        const QString storageText = optionalString(o, "storage", where);
        if (storageText == QLatin1String("RAM"))
            e.storage = Storage::Ram;
        else if (storageText == QLatin1String("EEPROM"))
            e.storage = Storage::Eeprom;
        else if (!storageText.isEmpty())
            fail(where, tr("unknown storage '%1' (expected RAM or EEPROM)").arg(storageText));
        if (e.storage != Storage::None && e.access == Access::Read)
            fail(where, tr("a read-only entry cannot have a storage"));

        e.reserved = optionalBool(o, "reserved", false, where);
        if (e.type == ValueType::Text) {
            // Within one reply frame: 125 words.
            if (!o.contains("bytes"))
                fail(where, tr("a text needs 'bytes' (at least 2, including the NUL)"));
            e.textBytes = optionalInt(o, "bytes", 2, 250, where).value_or(2);
        } else if (o.contains("bytes")) {
            fail(where, tr("'bytes' is only for texts"));
        }
        if (o.contains("words")) {
            e.reservedWords = optionalInt(o, "words", 1, 125, where).value_or(1);
            if (!e.reserved)
                fail(where, tr("'words' is only for reserved blocks"));
        }

        e.unit = optionalString(o, "unit", where);
        checkShownText(e.unit, QStringLiteral("unit"), where);
        e.configuredUnit = optionalString(o, "configuredUnit", where);
        if (!e.configuredUnit.isEmpty() && !e.unit.isEmpty())
            fail(where, tr("give 'unit' or 'configuredUnit', not both"));
        if ((!e.unit.isEmpty() || !e.configuredUnit.isEmpty())
            && (e.type == ValueType::Bool || e.type == ValueType::Enum || e.type == ValueType::Bitfield
                || e.type == ValueType::Text))
            fail(where, tr("a unit is only for numbers"));
        parsePrecision(o, e, where);
        e.minimum = optionalNumber(o, "min", where);
        e.maximum = optionalNumber(o, "max", where);
        if (e.minimum && e.maximum && *e.minimum > *e.maximum)
            fail(where, tr("'min' is greater than 'max'"));
        // A bound the type cannot hold checks nothing, or refuses every value.
        for (const auto &[key, bound] : {std::pair{"min", e.minimum}, std::pair{"max", e.maximum}}) {
            const auto [low, high] = typeRange(e.type);
            if (bound && e.type == ValueType::Text)
                fail(where, tr("'%1' is only for numbers").arg(QLatin1String(key)));
            else if (bound && (*bound < low || *bound > high))
                fail(where, tr("'%1' %2 is outside what a %3 holds (%4..%5)")
                                    .arg(QLatin1String(key))
                                    .arg(*bound)
                                    .arg(valueTypeName(e.type))
                                    .arg(low)
                                    .arg(high));
        }
        e.control = optionalString(o, "control", where);
        static const QStringList controls{"setpoint", "analog_output", "digital_output", "external_input", "alpha",
                                          "setpoint_select", "parameter_set_select", "binary_outputs", "switches", "command",
                                          "override", "program", "parameter"};
        if (!e.control.isEmpty() && !controls.contains(e.control))
            fail(where, tr("unknown control '%1'").arg(e.control));
        if (!e.control.isEmpty() && !e.isWritable())
            fail(where, tr("a control needs a writable entry"));
        e.restoreValue = optionalNumber(o, "restoreValue", where);
        e.precondition = optionalString(o, "precondition", where);
        e.alias = optionalString(o, "alias", where);
        if (!e.alias.isEmpty() && e.alias == e.id)
            fail(where, tr("an entry cannot be an alias of itself"));
        e.notes = optionalString(o, "notes", where);
        e.erratum = optionalString(o, "erratum", where);
        if (o.contains("activation"))
            e.activationMask = parseHex16(o.value("activation"), "activation", where);
        e.action = optionalBool(o, "action", false, where);
        if (e.action && !e.isWritable())
            fail(where, tr("an action needs a writable entry"));
        // A command word goes out whole, once: a number of 16 bits, never a measured value.
        if (e.action && (e.type == ValueType::Float || e.type == ValueType::Text))
            fail(where, tr("'action' is for command words (bit fields, enums, integers), not for a %1")
                                .arg(valueTypeName(e.type)));
        if (o.contains("poll")) {
            const QString poll = optionalString(o, "poll", where);
            e.pollOverride = pollClassFromName(poll);
            if (!e.pollOverride)
                fail(where, tr("unknown poll class '%1' (expected alarm, live or setting)").arg(poll.left(40)));
            else if (!e.isReadable() || !e.alias.isEmpty())
                fail(where, tr("'poll' is only for entries that are read (not write-only, not an alias)"));
        }

        parseEnumValues(o, e, where);
        parseBits(o, e, where);
        parseDefault(o, e, where);

        if (errors().size() != errorsBefore)
            return std::nullopt;
        return e;
    }

    void parseEnumValues(const QJsonObject &o, RegisterEntry &e, const QString &where)
    {
        const QJsonValue values = o.value("values");
        if (e.type != ValueType::Enum) {
            if (!values.isUndefined())
                fail(where, tr("'values' is only for enums"));
            return;
        }
        if (!values.isObject() || values.toObject().isEmpty()) {
            fail(where, tr("an enum needs 'values'"));
            return;
        }
        const QJsonObject v = values.toObject();
        for (auto it = v.begin(); it != v.end(); ++it) {
            // Written as the number itself: "01" and "1" would be one value twice.
            const std::optional<int> key = decimalKey(it.key(), 0, 0xFFFF);
            if (!key || !it.value().isString())
                fail(where, tr("enum value '%1' must be a number 0..65535 with a text").arg(it.key()));
            else
                e.enumValues.insert(*key, it.value().toString());
        }
        // A label is what a user types to write its value: typed, it must give that value,
        // not another's number ("0": "1") nor another label in other case ("On", "on").
        RegisterEntry asTyped;
        asTyped.id = e.id;
        asTyped.type = ValueType::Enum;
        asTyped.access = Access::ReadWrite;
        asTyped.enumValues = e.enumValues;
        for (auto it = e.enumValues.cbegin(); it != e.enumValues.cend(); ++it) {
            checkShownText(it.value(), QStringLiteral("values"), where);
            const EncodeResult typed = ValueCodec::encode(asTyped, RegisterMap(), it.value());
            if (typed.ok() && typed.words.value(0) != it.key())
                fail(where, tr("'values': the label '%1' of %2 would be written as %3 (a label must not be another "
                               "value's number, nor another label in other case)")
                                    .arg(it.value())
                                    .arg(it.key())
                                    .arg(typed.words.value(0)));
        }
    }

    // "default": what the manual gives as the factory setting or the value after power
    // on; a value the entry can hold, of its own JSON type (a number, an enum's value,
    // true or false), within its range.
    void parseDefault(const QJsonObject &o, RegisterEntry &e, const QString &where)
    {
        const QJsonValue v = o.value("default");
        if (v.isUndefined())
            return;
        if (!e.isWritable() || e.reserved) {
            fail(where, tr("'default' is only for writable entries"));
            return;
        }
        const auto shown = [&v] {
            return v.isString() ? QStringLiteral("'%1'").arg(v.toString().left(40)) : JsonFieldReader::shown(v).left(40);
        };
        switch (e.type) {
        case ValueType::Text:
        case ValueType::Bitfield:
            fail(where, tr("'default' is only for numbers, enums and booleans"));
            return;
        case ValueType::Bool:
            if (!v.isBool()) {
                fail(where, tr("'default' of a boolean must be true or false, not %1").arg(shown()));
                return;
            }
            e.defaultValue = v.toBool() ? 1 : 0;
            return;
        default:
            break;
        }
        const double d = v.toDouble();
        if (!v.isDouble() || !std::isfinite(d)) {
            fail(where, tr("'default' must be a number, not %1").arg(shown()));
            return;
        }
        if (e.type == ValueType::Enum) {
            if (d != std::floor(d) || d < 0 || d > 0xFFFF || !e.enumValues.contains(int(d)))
                fail(where, tr("'default' %1 is none of the enum's values").arg(shown()));
            else
                e.defaultValue = d;
            return;
        }
        auto [low, high] = typeRange(e.type);
        if (e.type != ValueType::Float && d != std::floor(d)) {
            fail(where, tr("'default' of a %1 must be a whole number, not %2").arg(valueTypeName(e.type), shown()));
            return;
        }
        if (e.minimum)
            low = std::max(low, *e.minimum);
        if (e.maximum)
            high = std::min(high, *e.maximum);
        if (d < low || d > high) {
            fail(where, tr("'default' %1 is outside the entry's range %2..%3").arg(shown()).arg(low).arg(high));
            return;
        }
        e.defaultValue = d;
    }

    void parseBits(const QJsonObject &o, RegisterEntry &e, const QString &where)
    {
        const QJsonValue bits = o.value("bits");
        if (e.type != ValueType::Bitfield) {
            if (!bits.isUndefined())
                fail(where, tr("'bits' is only for bit fields"));
            return;
        }
        if (!bits.isArray() || bits.toArray().isEmpty()) {
            fail(where, tr("a bit field needs 'bits'"));
            return;
        }
        quint16 used = 0;
        QSet<QString> ids;
        for (const QJsonValue &value : bits.toArray()) {
            if (!value.isObject()) {
                fail(where, tr("a bit must be an object"));
                continue;
            }
            const QJsonObject b = value.toObject();
            const QString bitWhere = tr("%1, bit %2").arg(where, b.value("bit").toVariant().toString().left(20));
            const qsizetype errorsBefore = errors().size();
            BitDefinition def;
            def.bit = optionalInt(b, "bit", 0, 15, bitWhere).value_or(-1);
            def.width = optionalInt(b, "width", 1, 16, bitWhere).value_or(1);
            def.id = optionalString(b, "id", bitWhere);
            def.label = optionalString(b, "label", bitWhere);
            def.reserved = optionalBool(b, "reserved", false, bitWhere);
            def.notes = optionalString(b, "notes", bitWhere);
            def.erratum = optionalString(b, "erratum", bitWhere);
            def.stateFrom = optionalString(b, "stateFrom", bitWhere);
            checkKeys(b, {"bit", "width", "id", "label", "kind", "reserved", "stateFrom", "notes", "erratum"}, bitWhere);
            if (def.bit < 0) {
                if (errors().size() == errorsBefore)
                    fail(bitWhere, tr("bit number must be 0..15"));
                continue;
            }
            if (errors().size() != errorsBefore)
                continue;
            if (def.bit + def.width > 16) {
                fail(bitWhere, tr("bit field of width %1 does not fit in 16 bits").arg(def.width));
                continue;
            }
            if (def.id.isEmpty() || !isId(def.id))
                fail(bitWhere, tr("a bit needs an id of lower case letters, digits and '_'"));
            else if (ids.contains(def.id))
                fail(bitWhere, tr("duplicate bit id '%1'").arg(def.id));
            ids.insert(def.id);
            if (def.label.isEmpty())
                fail(bitWhere, tr("a bit needs a label"));
            checkShownText(def.label, QStringLiteral("label"), bitWhere);
            const QString kindText = optionalString(b, "kind", bitWhere);
            if (const std::optional<BitKind> k = bitKindFromName(kindText))
                def.kind = *k;
            else
                fail(bitWhere, tr("unknown kind '%1' (expected alarm, warning, status or command)").arg(kindText));
            if (used & def.mask())
                fail(bitWhere, tr("bit defined twice"));
            used |= def.mask();
            e.bits << def;
        }
    }

    // Checks that a reference names an entry ("id") or a bit of a bit field ("id.bit").
    bool checkReference(const RegisterMap &map, const QString &reference, const QString &where)
    {
        const QString id = reference.section(QLatin1Char('.'), 0, 0);
        const QString bit = reference.section(QLatin1Char('.'), 1);
        const RegisterEntry *e = map.entry(id);
        if (!e) {
            fail(where, tr("refers to unknown entry '%1'").arg(id));
            return false;
        }
        if (!bit.isEmpty() && !e->bitById(bit)) {
            fail(where, tr("refers to unknown bit '%1' of '%2'").arg(bit, id));
            return false;
        }
        return true;
    }

    // A bit's state source must be a readable single bit of another entry.
    void checkStateSources(const RegisterMap &map)
    {
        for (const RegisterEntry &e : map.entries()) {
            for (const BitDefinition &b : e.bits) {
                if (b.stateFrom.isEmpty())
                    continue;
                const QString where = tr("entry '%1', bit %2").arg(e.id).arg(b.bit);
                if (e.isReadable()) {
                    fail(where, tr("'stateFrom' is only for write-only words (a readable word reports its own bits)"));
                    continue;
                }
                // Without a bit it names a whole word, whose state a single bit cannot take.
                if (b.width != 1) {
                    fail(where, tr("'stateFrom' is only for single bits, not for a field of %1").arg(b.width));
                    continue;
                }
                if (!b.stateFrom.contains(QLatin1Char('.'))) {
                    fail(where, tr("'stateFrom' must name a single bit as ENTRY.BIT, not '%1'").arg(b.stateFrom));
                    continue;
                }
                if (!checkReference(map, b.stateFrom, where))
                    continue;
                const RegisterEntry *source = map.entry(b.stateFrom.section(QLatin1Char('.'), 0, 0));
                const BitDefinition *sourceBit = source->bitById(b.stateFrom.section(QLatin1Char('.'), 1));
                if (!source->isReadable() || sourceBit->width != 1)
                    fail(where, tr("'stateFrom' must name a single bit of a readable bit field"));
            }
        }
    }

    void parseSimulation(const QJsonValue &value, RegisterMap &map)
    {
        const QString where = QStringLiteral("simulation");
        const QJsonObject o = value.toObject();
        checkKeys(o, {"model", "bindings", "initial", "limits", "commands", "status", "links"}, where);
        SimulationSpec spec;
        spec.model = o.value("model").toString();
        if (spec.model != QLatin1String("power_controller") && spec.model != QLatin1String("process_controller"))
            fail(where, tr("unknown model '%1' (expected power_controller or process_controller)").arg(spec.model));
        const QJsonObject bindings = o.value("bindings").toObject();
        for (auto it = bindings.begin(); it != bindings.end(); ++it) {
            QStringList ids;
            if (it.value().isArray()) {
                for (const QJsonValue &v : it.value().toArray())
                    ids << v.toString();
            } else {
                ids << it.value().toString();
            }
            for (const QString &id : std::as_const(ids))
                checkReference(map, id, where + QStringLiteral(".bindings.") + it.key());
            spec.bindings.insert(it.key(), ids);
        }
        const QJsonObject initial = o.value("initial").toObject();
        for (auto it = initial.begin(); it != initial.end(); ++it) {
            checkReference(map, it.key(), where + QStringLiteral(".initial"));
            spec.initial.insert(it.key(), it.value().toVariant());
        }
        int index = 0;
        for (const QJsonValue &v : o.value("limits").toArray()) {
            const QString limitWhere = QStringLiteral("%1.limits[%2]").arg(where).arg(index++);
            const QJsonObject l = v.toObject();
            checkKeys(l, {"value", "above", "below", "set"}, limitWhere);
            SimulationLimit limit;
            limit.value = l.value("value").toString();
            checkReference(map, limit.value, limitWhere);
            limit.above = l.contains("above");
            const QJsonValue threshold = l.value(limit.above ? "above" : "below");
            if (threshold.isString()) {
                limit.thresholdId = threshold.toString();
                checkReference(map, limit.thresholdId, limitWhere);
            } else if (threshold.isDouble()) {
                limit.threshold = threshold.toDouble();
            } else {
                fail(limitWhere, tr("a limit needs 'above' or 'below' (an entry id or a number)"));
            }
            for (const QJsonValue &s : l.value("set").toArray()) {
                limit.set << s.toString();
                checkReference(map, s.toString(), limitWhere);
            }
            spec.limits << limit;
        }
        static const QStringList actions{"manual_on", "manual_off", "tuning_start", "tuning_abort", "controller_off"};
        const QJsonObject commands = o.value("commands").toObject();
        for (auto it = commands.begin(); it != commands.end(); ++it) {
            checkReference(map, it.key(), where + QStringLiteral(".commands"));
            if (!actions.contains(it.value().toString()))
                fail(where + QStringLiteral(".commands"), tr("unknown action '%1'").arg(it.value().toString()));
            spec.commands.insert(it.key(), it.value().toString());
        }
        int linkIndex = 0;
        for (const QJsonValue &v : o.value("links").toArray()) {
            const QString linkWhere = QStringLiteral("%1.links[%2]").arg(where).arg(linkIndex++);
            const QJsonArray pair = v.toArray();
            if (pair.size() != 2 || !pair[0].isString() || !pair[1].isString()) {
                fail(linkWhere, tr("a link is a pair of references"));
                continue;
            }
            if (checkReference(map, pair[0].toString(), linkWhere) && checkReference(map, pair[1].toString(), linkWhere))
                spec.links << qMakePair(pair[0].toString(), pair[1].toString());
        }
        const QJsonObject status = o.value("status").toObject();
        for (auto it = status.begin(); it != status.end(); ++it) {
            checkReference(map, it.value().toString(), where + QStringLiteral(".status"));
            spec.status.insert(it.key(), it.value().toString());
        }
        map.simulation = spec;
    }

    // Checks that need all entries: unique ids, aliases, overlapping word ranges.
    void checkEntries(const QList<RegisterEntry> &entries)
    {
        QHash<QString, const RegisterEntry *> byId;
        for (const RegisterEntry &e : entries) {
            if (byId.contains(e.id))
                fail(tr("entry '%1' (%2)").arg(e.id, formatAddress(e.address)),
                     tr("duplicate id (also at %1)").arg(formatAddress(byId.value(e.id)->address)));
            byId.insert(e.id, &e);
        }
        for (const RegisterEntry &e : entries) {
            if (!e.alias.isEmpty() && e.alias != e.id && !byId.contains(e.alias))
                fail(tr("entry '%1'").arg(e.id), tr("alias of unknown entry '%1'").arg(e.alias));
            if (int(e.address) + e.wordCount() > 0x10000)
                fail(tr("entry '%1'").arg(e.id), tr("runs past address 0xFFFF"));
        }
        for (const auto &[where, problem] : OverlapCheck::check(entries))
            fail(where, problem);
    }
};

} // namespace

MapLoadResult MapLoader::loadFile(const QString &path)
{
    QString error;
    const std::optional<QByteArray> json = RegularFile::read(path, maxFileBytes, &error);
    if (!json) {
        MapLoadResult result;
        result.errors << error;
        return result;
    }
    return loadData(*json, path.startsWith(QLatin1Char(':')) ? path : QFileInfo(path).absoluteFilePath());
}

MapLoadResult MapLoader::loadData(const QByteArray &json, const QString &sourceName)
{
    return MapParser(sourceName).parse(json);
}

} // namespace jumo
