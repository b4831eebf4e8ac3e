#include "bus/stationconfig.h"

#include "bus/lineaddress.h"

#include "protocol/familyregistry.h"
#include "protocol/filesaver.h"
#include "protocol/jsonfieldreader.h"
#include "protocol/regularfile.h"

#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSet>
#include <QSysInfo>

namespace jumo {

namespace {

constexpr int maxStationNameLength = 64;
constexpr int maxDeviceAddress = 247;   // the highest unicast address Modbus allows

const QRegularExpression &namePattern()
{
    static const QRegularExpression pattern(QRegularExpression::anchoredPattern(QStringLiteral("[A-Za-z0-9_.-]+")));
    return pattern;
}

bool isStationName(const QString &text)
{
    return text.size() <= maxStationNameLength && namePattern().match(text).hasMatch();
}

const QRegularExpression &devicePattern()
{
    static const QRegularExpression pattern(
            QRegularExpression::anchoredPattern(QStringLiteral("([a-z][a-z0-9_]*)@([0-9]{1,3})")));
    return pattern;
}

// The line's address text: a serial port, tcp://HOST[:PORT] or rtu+tcp://HOST:PORT.
bool checkLineAddress(const QString &text, QString *error)
{
    if (text.trimmed().isEmpty()) {
        if (error)
            *error = StationConfig::tr("the line address (serial port or URL) is empty");
        return false;
    }
    return LineAddress::parse(text, error).has_value();
}

QString lineWhere(qsizetype index, const QString &name)
{
    return name.isEmpty() ? QStringLiteral("lines[%1]").arg(index)
                          : QStringLiteral("lines[%1] (%2)").arg(index).arg(name);
}

QString nameProblem(const QString &shown)
{
    return StationConfig::tr("'name' must be 1..%1 of the letters A-Z, a-z, digits, '_', '.' and '-', not '%2'")
            .arg(StationConfig::maxLineNameLength)
            .arg(shown.left(40));
}

QString baudProblem(const QString &key, const QString &shown)
{
    return StationConfig::tr("'%1' must be 4800, 9600, 19200 or 38400, not %2").arg(key, shown);
}

QString formatProblem(const QString &key, const QString &shown)
{
    return StationConfig::tr("'%1' must be 8N1, 8E1, 8O1 or 8N2, not %2").arg(key, shown);
}

QString timeoutProblem(const QString &key, const QString &shown)
{
    return StationConfig::tr("'%1' must be 0 (derived from the baud rate and the families) or 10..60000 ms, not %2")
            .arg(key, shown);
}

// One problem per device listed on one line twice at one address.
QStringList duplicateAddresses(const QList<DeviceSpec> &devices)
{
    QStringList problems;
    QSet<int> seen;
    for (qsizetype i = 0; i < devices.size(); ++i) {
        if (seen.contains(devices[i].address))
            continue;
        QStringList sharing{devices[i].name()};
        for (qsizetype j = i + 1; j < devices.size(); ++j) {
            if (devices[j].address == devices[i].address)
                sharing << devices[j].name();
        }
        if (sharing.size() > 1)
            problems << StationConfig::tr("address %1 is used twice on the line (%2)")
                                .arg(devices[i].address)
                                .arg(sharing.join(QStringLiteral(", ")));
        seen.insert(devices[i].address);
    }
    return problems;
}

// Names the unnamed lines by position and finds names that are bad or used twice.
QStringList nameLines(QList<LineConfig> &lines)
{
    QStringList problems;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (lines[i].name.isEmpty())
            lines[i].name = StationConfig::defaultLineName(i);
    }
    QSet<QString> reported;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString &name = lines[i].name;
        if (!StationConfig::isLineName(name)) {
            problems << QStringLiteral("%1: %2").arg(lineWhere(i, QString()), nameProblem(name));
            continue;
        }
        for (qsizetype j = i + 1; j < lines.size(); ++j) {
            if (lines[j].name == name && !reported.contains(name)) {
                problems << QStringLiteral("%1: %2").arg(lineWhere(j, name),
                                                         StationConfig::tr("the line name '%1' is used by lines[%2] too")
                                                                 .arg(name)
                                                                 .arg(i));
                reported.insert(name);
            }
        }
    }
    return problems;
}

// A serial port or a serial device server has one master: two lines of one station on
// it would talk over each other. (Two lines through one Modbus TCP gateway are two
// connections the gateway orders, and allowed.) Host names are looked up (once each)
// only when two device-server lines on one port are not told apart by their addresses.
QStringList sharedAddresses(const QList<LineConfig> &lines)
{
    QHash<QString, QStringList> looked;
    const auto resolve = [&looked](const QString &name) {
        if (!looked.contains(name))
            looked.insert(name, LineAddress::lookUp(name));
        return looked.value(name);
    };
    QList<std::optional<LineAddress>> addresses;
    for (const LineConfig &line : lines)
        addresses << LineAddress::parse(line.settings.portName, nullptr);
    QStringList problems;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        for (qsizetype j = 0; j < i && addresses[i]; ++j) {
            if (!addresses[j] || !LineAddress::shareMaster(*addresses[j], *addresses[i], resolve))
                continue;
            problems << QStringLiteral("%1: %2").arg(
                    lineWhere(i, lines[i].name),
                    StationConfig::tr("'port' %1 is the port of lines[%2] (%3) too: a line has one master, so give "
                                      "the devices of both to one line")
                            .arg(lines[i].settings.portName)
                            .arg(j)
                            .arg(lines[j].name));
            break;
        }
    }
    return problems;
}

class StationParser : private JsonFieldReader
{
public:
    StationParser(QString source, const FamilyRegistry &registry)
        : JsonFieldReader(std::move(source)), m_registry(registry)
    {
    }

    std::optional<StationConfig> parse(const QByteArray &json)
    {
        QJsonParseError parseError;
        const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
        if (parseError.error != QJsonParseError::NoError) {
            fail(QString(), StationConfig::tr("malformed JSON at byte %1: %2")
                                    .arg(parseError.offset)
                                    .arg(parseError.errorString()));
            return std::nullopt;
        }
        if (const qsizetype at = controlCharacterAt(json); at >= 0) {
            fail(QString(), StationConfig::tr("malformed JSON at byte %1: a control character").arg(at));
            return std::nullopt;
        }
        QString key;
        if (const qsizetype at = duplicateKeyAt(json, &key); at >= 0) {
            // Qt keeps one of the two values silently: which line or port is meant is not clear.
            fail(QString(), StationConfig::tr("malformed JSON at byte %1: '%2' given twice in one object").arg(at).arg(key));
            return std::nullopt;
        }
        const QJsonObject root = doc.object();
        if (!doc.isObject() || root.value(QStringLiteral("format")) != QJsonValue(QStringLiteral("jumo-station"))) {
            fail(QString(), StationConfig::tr("not a station file (no \"format\": \"jumo-station\")"));
            return std::nullopt;
        }
        if (root.value(QStringLiteral("version")) != QJsonValue(StationConfig::formatVersion)) {
            fail(QString(), StationConfig::tr("station file version %1 is not supported (expected %2)")
                                    .arg(shown(root.value(QStringLiteral("version"))))
                                    .arg(StationConfig::formatVersion));
            return std::nullopt;
        }
        checkKeys(root, {"format", "version", "name", "lines"}, QString());
        StationConfig station;
        if (root.contains(QStringLiteral("name"))) {
            station.name = optionalString(root, "name", QString());
            if (!isStationName(station.name))
                fail(QString(), StationConfig::tr("'name' must be 1..%1 of the letters A-Z, a-z, digits, '_', '.' and '-', "
                                                  "not '%2'")
                                        .arg(maxStationNameLength)
                                        .arg(station.name.left(80)));
        }
        const QJsonValue lines = root.value(QStringLiteral("lines"));
        if (!lines.isArray()) {
            fail(QString(), StationConfig::tr("'lines' must be an array of lines"));
            return std::nullopt;
        }
        qsizetype index = 0;
        for (const QJsonValue &line : lines.toArray())
            station.lines << parseLine(line, index++);
        for (const QString &problem : nameLines(station.lines) + sharedAddresses(station.lines))
            fail(QString(), problem);
        if (!errors().isEmpty())
            return std::nullopt;
        return station;
    }

    QStringList problems() const { return errors(); }

private:
    LineConfig parseLine(const QJsonValue &value, qsizetype index)
    {
        LineConfig line;
        if (!value.isObject()) {
            fail(lineWhere(index, QString()), StationConfig::tr("a line must be an object, not %1").arg(shown(value)));
            return line;
        }
        const QJsonObject o = value.toObject();
        const QJsonValue nameValue = o.value(QStringLiteral("name"));
        // Named in messages only when the name itself is fine.
        const QString where = lineWhere(index, nameValue.isString() && StationConfig::isLineName(nameValue.toString())
                                                       ? nameValue.toString()
                                                       : QString());
        checkKeys(o,
                  {"name", "port", "baud", "format", "timeout_ms", "min_response_ms", "retries", "read_only",
                   "devices"},
                  where);
        line.name = optionalString(o, "name", where);
        // An empty name would be given a default one: say it instead.
        if (line.name.isEmpty() && nameValue.isString())
            fail(where, nameProblem(QString()));
        BusSettings &s = line.settings;
        s.portName = requireString(o, "port", where);
        QString problem;
        if (!s.portName.isEmpty() && !checkLineAddress(s.portName, &problem))
            fail(where, QStringLiteral("'port': %1").arg(problem));
        const QJsonValue baud = o.value(QStringLiteral("baud"));
        const QJsonValue format = o.value(QStringLiteral("format"));
        const std::optional<LineFormat> baudOnly =
                LineFormat::parse(baud.isUndefined() ? 9600 : baud.toInt(-1), QStringLiteral("8N1"));
        if (!baudOnly || (!baud.isUndefined() && !baud.isDouble()))
            fail(where, baudProblem(QStringLiteral("baud"), shown(baud)));
        const std::optional<LineFormat> formatOnly = LineFormat::parse(9600, format.toString(QStringLiteral("8N1")));
        if (!formatOnly || (!format.isUndefined() && !format.isString()))
            fail(where, formatProblem(QStringLiteral("format"), shown(format)));
        if (baudOnly && formatOnly)
            s.format = *LineFormat::parse(baudOnly->baudRate, formatOnly->formatName());
        const std::optional<int> timeout = optionalInt(o, "timeout_ms", 0, 60000, where);
        if (timeout && *timeout > 0 && *timeout < 10)
            fail(where, timeoutProblem(QStringLiteral("timeout_ms"), QString::number(*timeout)));
        s.timeoutMs = timeout.value_or(0);
        s.minimumResponseTimeMs = optionalInt(o, "min_response_ms", 0, 500, where).value_or(0);
        s.retries = optionalInt(o, "retries", 0, 10, where).value_or(2);
        s.readOnly = optionalBool(o, "read_only", false, where);
        const QJsonValue devices = o.value(QStringLiteral("devices"));
        if (!devices.isUndefined() && !devices.isArray()) {
            fail(where, StationConfig::tr("'devices' must be an array of \"FAMILY@ADDRESS\" texts, e.g. \"ipc300@1\""));
            return line;
        }
        for (const QString &text : stringList(o, "devices", where)) {
            QString deviceProblem;
            if (const std::optional<DeviceSpec> device = DeviceSpec::parse(text, m_registry, &deviceProblem))
                line.devices << *device;
            else
                fail(where, QStringLiteral("'devices': %1").arg(deviceProblem));
        }
        for (const QString &duplicate : duplicateAddresses(line.devices))
            fail(where, QStringLiteral("'devices': %1").arg(duplicate));
        return line;
    }

    const FamilyRegistry &m_registry;
};

} // namespace

QString DeviceSpec::name() const
{
    return QStringLiteral("%1@%2").arg(family).arg(address);
}

std::optional<DeviceSpec> DeviceSpec::parse(const QString &text, const FamilyRegistry &registry, QString *error)
{
    auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const QRegularExpressionMatch match = devicePattern().match(text);
    if (!match.hasMatch())
        return fail(StationConfig::tr("'%1' is not a device: use FAMILY@ADDRESS, e.g. ipc300@1").arg(text.left(80)));
    DeviceSpec device;
    device.family = match.captured(1);
    const std::shared_ptr<const RegisterMap> map = registry.family(device.family);
    if (!map)
        return fail(StationConfig::tr("'%1': unknown family '%2' (families: %3)")
                            .arg(text, device.family, registry.familyIds().join(QStringLiteral(", "))));
    const int address = match.captured(2).toInt();
    if (address < 1 || address > maxDeviceAddress)
        return fail(StationConfig::tr("'%1': the address must be 1..%2, not %3").arg(text).arg(maxDeviceAddress).arg(address));
    if (address < map->protocol.addressMin || address > map->protocol.addressMax)
        return fail(StationConfig::tr("'%1': a %2 cannot have address %3, its addresses are %4..%5")
                            .arg(text, device.family)
                            .arg(address)
                            .arg(map->protocol.addressMin)
                            .arg(map->protocol.addressMax));
    device.address = quint8(address);
    return device;
}

QString StationConfig::defaultName()
{
    QString name = QSysInfo::machineHostName().left(maxStationNameLength);
    static const QRegularExpression notAllowed(QStringLiteral("[^A-Za-z0-9_.-]"));
    name.replace(notAllowed, QStringLiteral("-"));
    return name.isEmpty() ? QStringLiteral("station") : name;
}

QString StationConfig::defaultLineName(qsizetype index)
{
    return QStringLiteral("line%1").arg(index + 1);
}

bool StationConfig::isLineName(const QString &text)
{
    return text.size() <= maxLineNameLength && namePattern().match(text).hasMatch();
}

std::optional<StationConfig> StationConfig::load(const QString &path, const FamilyRegistry &registry, QString *error)
{
    QString reason;
    const std::optional<QByteArray> json = RegularFile::read(path, maxFileBytes, &reason);
    if (!json) {
        if (error)
            *error = reason;
        return std::nullopt;
    }
    StationParser parser(path, registry);
    std::optional<StationConfig> station = parser.parse(*json);
    if (!station && error)
        *error = parser.problems().join(QLatin1Char('\n'));
    return station;
}

std::optional<StationConfig> StationConfig::fromJson(const QByteArray &json, const FamilyRegistry &registry,
                                                     QString *error)
{
    StationParser parser{QString(), registry};
    std::optional<StationConfig> station = parser.parse(json);
    if (!station && error)
        *error = parser.problems().join(QLatin1Char('\n'));
    return station;
}

QByteArray StationConfig::toJson() const
{
    // Written by hand: QJsonObject sorts its keys, and a person reads a station file in
    // this order (the port before the devices, the name first).
    const auto value = [](const QJsonValue &v) {
        return QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact).mid(1).chopped(1);
    };
    QByteArray json = "{\n    \"format\": \"jumo-station\",\n    \"version\": " + QByteArray::number(formatVersion)
            + ",\n    \"name\": " + value(name) + ",\n    \"lines\": [";
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const LineConfig &line = lines[i];
        const BusSettings &s = line.settings;
        QJsonArray devices;
        for (const DeviceSpec &device : line.devices)
            devices << device.name();
        const QList<QPair<QByteArray, QJsonValue>> fields{{"name", line.name},
                                                          {"port", s.portName},
                                                          {"baud", s.format.baudRate},
                                                          {"format", s.format.formatName()},
                                                          {"timeout_ms", s.timeoutMs},
                                                          {"min_response_ms", s.minimumResponseTimeMs},
                                                          {"retries", s.retries},
                                                          {"read_only", s.readOnly},
                                                          {"devices", devices}};
        json += i == 0 ? "\n        {" : ",\n        {";
        for (qsizetype f = 0; f < fields.size(); ++f)
            json += (f == 0 ? "\n            \"" : ",\n            \"") + fields[f].first + "\": " + value(fields[f].second);
        json += "\n        }";
    }
    json += lines.isEmpty() ? "]\n}\n" : "\n    ]\n}\n";
    return json;
}

bool StationConfig::save(const QString &path, QString *error) const
{
    return FileSaver::save(path, toJson(), error);
}

std::optional<LineConfig> StationConfig::parseLineSpec(const QString &spec, QString *error)
{
    BusSettings defaults;
    defaults.format = *LineFormat::parse(9600, QStringLiteral("8N1"));
    return parseLineSpec(spec, defaults, error);
}

std::optional<LineConfig> StationConfig::parseLineSpec(const QString &spec, const BusSettings &defaults,
                                                       QString *error)
{
    QStringList problems;
    const QStringList parts = spec.split(QLatin1Char(','));
    LineConfig line;
    line.settings = defaults;
    line.settings.portName = parts.constFirst();
    QString problem;
    if (!checkLineAddress(line.settings.portName, &problem))
        problems << problem;
    int baud = defaults.format.baudRate;
    QString format = defaults.format.formatName();
    QSet<QString> given;
    const auto number = [&](const QString &key, const QString &text, int minimum, int maximum) {
        bool ok = false;
        const int n = text.toInt(&ok);
        if (!ok || n < minimum || n > maximum) {
            problems << tr("'%1' must be a whole number %2..%3, not '%4'").arg(key).arg(minimum).arg(maximum).arg(text);
            return minimum;
        }
        return n;
    };
    for (const QString &part : parts.mid(1)) {
        const QString key = part.section(QLatin1Char('='), 0, 0);
        const QString value = part.section(QLatin1Char('='), 1);
        const bool hasValue = part.contains(QLatin1Char('='));
        if (given.contains(key)) {
            problems << tr("'%1' is given twice").arg(key);
            continue;
        }
        given.insert(key);
        if (key == QLatin1String("read-only")) {
            if (hasValue)
                problems << tr("'read-only' takes no value");
            line.settings.readOnly = true;
            continue;
        }
        if (key == QLatin1String("name") && hasValue) {
            line.name = value;
            if (!isLineName(value))
                problems << nameProblem(value);
        } else if (key == QLatin1String("baud") && hasValue) {
            bool ok = false;
            baud = value.toInt(&ok);
            if (!ok || !LineFormat::parse(baud, QStringLiteral("8N1"))) {
                problems << baudProblem(key, value);
                baud = defaults.format.baudRate;
            }
        } else if (key == QLatin1String("format") && hasValue) {
            format = value;
            if (!LineFormat::parse(9600, value)) {
                problems << formatProblem(key, value);
                format = defaults.format.formatName();
            }
        } else if (key == QLatin1String("timeout") && hasValue) {
            line.settings.timeoutMs = number(key, value, 0, 60000);
            if (line.settings.timeoutMs > 0 && line.settings.timeoutMs < 10)
                problems << timeoutProblem(key, value);
        } else if (key == QLatin1String("min-response") && hasValue) {
            line.settings.minimumResponseTimeMs = number(key, value, 0, 500);
        } else if (key == QLatin1String("retries") && hasValue) {
            line.settings.retries = number(key, value, 0, 10);
        } else {
            problems << tr("unknown option '%1' (ADDRESS[,name=NAME][,baud=N][,format=8N1][,timeout=MS]"
                           "[,min-response=MS][,retries=N][,read-only])")
                                .arg(part.left(40));
        }
    }
    line.settings.format = LineFormat::parse(baud, format).value_or(defaults.format);
    if (!problems.isEmpty()) {
        if (error)
            *error = tr("--line '%1': %2").arg(spec, problems.join(QStringLiteral("; ")));
        return std::nullopt;
    }
    return line;
}

std::optional<StationConfig> StationConfig::fromLines(QList<LineConfig> lines, QString *error)
{
    QStringList problems = nameLines(lines) + sharedAddresses(lines);
    for (qsizetype i = 0; i < lines.size(); ++i) {
        for (const QString &duplicate : duplicateAddresses(lines[i].devices))
            problems << QStringLiteral("%1: %2").arg(lineWhere(i, lines[i].name), duplicate);
    }
    if (!problems.isEmpty()) {
        if (error)
            *error = problems.join(QLatin1Char('\n'));
        return std::nullopt;
    }
    StationConfig station;
    station.lines = std::move(lines);
    return station;
}

qsizetype StationConfig::lineIndex(const QString &lineName) const
{
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (lines[i].name == lineName)
            return i;
    }
    return -1;
}

QString StationConfig::deviceName(qsizetype line, const DeviceSpec &device) const
{
    return lines.size() > 1 ? qualifiedName(lines.value(line).name, device) : device.name();
}

QString StationConfig::qualifiedName(const QString &lineName, const DeviceSpec &device)
{
    return QStringLiteral("%1/%2").arg(lineName, device.name());
}

qsizetype StationConfig::lineOfDevice(const QString &text, QString *device, QString *error) const
{
    QStringList names;
    for (const LineConfig &line : lines)
        names << line.name;
    const qsizetype slash = text.indexOf(QLatin1Char('/'));
    if (device)
        *device = text.mid(slash + 1);
    QString problem;
    qsizetype found = -1;
    if (slash >= 0) {
        const QString lineName = text.left(slash);
        found = lineIndex(lineName);
        if (found < 0)
            problem = tr("'%1': there is no line '%2' (lines: %3)")
                              .arg(text, lineName.left(40), names.join(QStringLiteral(", ")));
    } else if (lines.size() == 1) {
        found = 0;
    } else if (lines.isEmpty()) {
        problem = tr("'%1': no line is given").arg(text);
    } else {
        problem = tr("'%1': which line? The station has the lines %2: name it as LINE/%1, e.g. %3/%1")
                          .arg(text, names.join(QStringLiteral(", ")), names.constFirst());
    }
    if (found < 0 && error)
        *error = problem;
    return found;
}

std::optional<StationDevice> StationConfig::resolveDevice(const QString &text, const FamilyRegistry &registry,
                                                          QString *error) const
{
    StationDevice found;
    QString rest;
    found.line = lineOfDevice(text, &rest, error);
    if (found.line < 0)
        return std::nullopt;
    const std::optional<DeviceSpec> device = DeviceSpec::parse(rest, registry, error);
    if (!device)
        return std::nullopt;
    found.device = *device;
    return found;
}

QList<StationDevice> StationConfig::devices() const
{
    QList<StationDevice> all;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        for (const DeviceSpec &device : lines[i].devices)
            all << StationDevice{i, device};
    }
    return all;
}

} // namespace jumo
