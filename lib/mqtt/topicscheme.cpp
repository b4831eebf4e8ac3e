#include "mqtt/topicscheme.h"

#include "bus/lineaddress.h"

#include "bus/valuetext.h"
#include "protocol/valueformat.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>

namespace jumo {

namespace {

QByteArray compact(const QJsonObject &object)
{
    return QJsonDocument(object).toJson(QJsonDocument::Compact);
}

std::optional<QJsonObject> objectOf(const QByteArray &payload)
{
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(payload, &error);
    if (error.error != QJsonParseError::NoError || !document.isObject())
        return std::nullopt;
    return document.object();
}

QJsonValue timeOrNull(const QDateTime &time)
{
    return time.isValid() ? QJsonValue(TopicScheme::timeText(time)) : QJsonValue();
}

} // namespace

bool TopicScheme::isTopicLevel(const QString &name)
{
    if (name.isEmpty() || name.size() > 128)
        return false;
    for (QChar c : name) {
        if (c == QLatin1Char('/') || c == QLatin1Char('+') || c == QLatin1Char('#') || c.isNull())
            return false;
    }
    return true;
}

bool TopicScheme::isValidPrefix(const QString &prefix)
{
    // Topics starting with '$' are the broker's own ($SYS): a station does not publish
    // there. A control character (a line end) would hide in logs and ACL files.
    if (prefix.startsWith(QLatin1Char('$'))
        || std::any_of(prefix.begin(), prefix.end(), [](QChar c) { return c.category() == QChar::Other_Control; }))
        return false;
    const QStringList levels = prefix.split(QLatin1Char('/'));
    return std::all_of(levels.begin(), levels.end(), [](const QString &level) { return isTopicLevel(level); });
}

QString TopicScheme::status(const QString &station) const
{
    return QStringLiteral("%1/%2/status").arg(m_prefix, station);
}

QString TopicScheme::heartbeat(const QString &station) const
{
    return QStringLiteral("%1/%2/heartbeat").arg(m_prefix, station);
}

QString TopicScheme::order(const QString &station) const
{
    return QStringLiteral("%1/%2/order").arg(m_prefix, station);
}

QString TopicScheme::line(const QString &station, const QString &line) const
{
    return QStringLiteral("%1/%2/lines/%3").arg(m_prefix, station, line);
}

QString TopicScheme::deviceInfo(const QString &station, const QString &line, const QString &device) const
{
    return QStringLiteral("%1/%2/devices/%3/%4/info").arg(m_prefix, station, line, device);
}

QString TopicScheme::deviceCondition(const QString &station, const QString &line, const QString &device) const
{
    return QStringLiteral("%1/%2/devices/%3/%4/condition").arg(m_prefix, station, line, device);
}

QString TopicScheme::value(const QString &station, const QString &line, const QString &device,
                           const QString &entry) const
{
    return QStringLiteral("%1/%2/devices/%3/%4/values/%5").arg(m_prefix, station, line, device, entry);
}

QString TopicScheme::viewer(const QString &station, const QString &viewerId) const
{
    return QStringLiteral("%1/%2/viewers/%3").arg(m_prefix, station, viewerId);
}

QString TopicScheme::probe(const QString &station, const QString &probeId) const
{
    return QStringLiteral("%1/%2/probe/%3").arg(m_prefix, station, probeId);
}

QString TopicScheme::stationFilter(const QString &station) const
{
    return QStringLiteral("%1/%2/#").arg(m_prefix, station.isEmpty() ? QStringLiteral("+") : station);
}

std::optional<TopicScheme::Topic> TopicScheme::parse(const QString &topic) const
{
    if (!topic.startsWith(m_prefix + QLatin1Char('/')))
        return std::nullopt;
    const QStringList levels = topic.mid(m_prefix.size() + 1).split(QLatin1Char('/'));
    if (levels.size() < 2 || levels[0].isEmpty())
        return std::nullopt;
    Topic t;
    t.station = levels[0];
    const QString &what = levels[1];
    if (levels.size() == 2 && what == QLatin1String("status")) {
        t.kind = Kind::Status;
        return t;
    }
    if (levels.size() == 2 && what == QLatin1String("heartbeat")) {
        t.kind = Kind::Heartbeat;
        return t;
    }
    if (levels.size() == 2 && what == QLatin1String("order")) {
        t.kind = Kind::Order;
        return t;
    }
    if (levels.size() == 3 && what == QLatin1String("lines") && !levels[2].isEmpty()) {
        t.kind = Kind::Line;
        t.line = levels[2];
        return t;
    }
    if (levels.size() == 3 && what == QLatin1String("viewers") && !levels[2].isEmpty()) {
        t.kind = Kind::Viewer;
        t.viewer = levels[2];
        return t;
    }
    if (levels.size() == 3 && what == QLatin1String("probe") && !levels[2].isEmpty()) {
        t.kind = Kind::Probe;
        t.viewer = levels[2];
        return t;
    }
    if (what != QLatin1String("devices") || levels.size() < 5 || levels[2].isEmpty() || levels[3].isEmpty())
        return std::nullopt;
    t.line = levels[2];
    t.device = levels[3];
    if (levels.size() == 5 && levels[4] == QLatin1String("info")) {
        t.kind = Kind::DeviceInfo;
        return t;
    }
    if (levels.size() == 5 && levels[4] == QLatin1String("condition")) {
        t.kind = Kind::DeviceCondition;
        return t;
    }
    if (levels.size() == 6 && levels[4] == QLatin1String("values") && !levels[5].isEmpty()) {
        t.kind = Kind::Value;
        t.entry = levels[5];
        return t;
    }
    return std::nullopt;
}

QString TopicScheme::timeText(const QDateTime &time)
{
    return time.toUTC().toString(Qt::ISODateWithMs);
}

QDateTime TopicScheme::parseTime(const QString &text)
{
    return QDateTime::fromString(text, Qt::ISODateWithMs);
}

QString TopicScheme::lineKind(const QString &address)
{
    const std::optional<LineAddress> parsed = LineAddress::parse(address, nullptr);
    return parsed ? parsed->kindName() : QStringLiteral("rtu");
}

QString TopicScheme::lineStateName(LineState state)
{
    switch (state) {
    case LineState::Connected: return QStringLiteral("connected");
    case LineState::Lost: return QStringLiteral("lost");
    case LineState::Disconnected: break;
    }
    return QStringLiteral("disconnected");
}

std::optional<LineState> TopicScheme::lineStateFromName(const QString &name)
{
    for (LineState s : {LineState::Connected, LineState::Lost, LineState::Disconnected}) {
        if (lineStateName(s) == name)
            return s;
    }
    return std::nullopt;
}

QString TopicScheme::conditionName(DeviceCondition::State state)
{
    using S = DeviceCondition::State;
    switch (state) {
    case S::Online: return QStringLiteral("online");
    case S::Offline: return QStringLiteral("offline");
    case S::LineLost: return QStringLiteral("line_lost");
    case S::Identifying: return QStringLiteral("identifying");
    case S::WrongDevice: return QStringLiteral("wrong_device");
    case S::Disconnected: break;
    }
    return QStringLiteral("disconnected");
}

std::optional<DeviceCondition::State> TopicScheme::conditionFromName(const QString &name)
{
    using S = DeviceCondition::State;
    for (S s : {S::Online, S::Offline, S::LineLost, S::Disconnected, S::Identifying, S::WrongDevice}) {
        if (conditionName(s) == name)
            return s;
    }
    return std::nullopt;
}

ReadError TopicScheme::readErrorFromStatus(const QString &status, int *exceptionCode)
{
    if (exceptionCode)
        *exceptionCode = 0;
    if (status.startsWith(QLatin1String("exception:"))) {
        if (exceptionCode)
            *exceptionCode = status.mid(10).toInt();
        return ReadError::Exception;
    }
    static const QHash<QString, ReadError> errors = {
            {QStringLiteral("timeout"), ReadError::Timeout},
            {QStringLiteral("offline"), ReadError::DeviceOffline},
            {QStringLiteral("line_lost"), ReadError::LineLost},
            {QStringLiteral("disconnected"), ReadError::LineClosed},
            {QStringLiteral("unavailable"), ReadError::NotAvailable},
            {QStringLiteral("unconfirmed"), ReadError::Unconfirmed},
            {QStringLiteral("wrong_device"), ReadError::WrongDevice},
            {QStringLiteral("not_read"), ReadError::NotRead},
    };
    // Current and stale values ("ok", "overrange", "stale", ...) have no read error.
    return errors.value(status, ReadError::None);
}

QByteArray TopicScheme::statusOnline(const QString &software, const QDateTime &started, const QStringList &lines,
                                     qint64 restored, qint64 cleared)
{
    QJsonObject o{{"state", "online"},
                  {"software", software},
                  {"started", timeOrNull(started)},
                  {"lines", QJsonArray::fromStringList(lines)}};
    if (restored > 0 || cleared > 0)
        o.insert(QStringLiteral("foreign"), QJsonObject{{"restored", restored}, {"cleared", cleared}});
    return compact(o);
}

QByteArray TopicScheme::statusOffline(const QString &reason)
{
    return compact({{"state", "offline"}, {"reason", reason}});
}

QByteArray TopicScheme::heartbeatPayload(const QDateTime &time)
{
    return compact({{"time", timeText(time)}});
}

QByteArray TopicScheme::linePayload(const QString &address, LineState state, const QDateTime &since,
                                    const QString &error)
{
    return compact({{"address", address},
                    {"kind", lineKind(address)},
                    {"state", lineStateName(state)},
                    {"since", timeOrNull(since)},
                    {"error", error}});
}

QByteArray TopicScheme::deviceInfoPayload(const QString &line, const RegisterMap &map, int address)
{
    return compact({{"line", line}, {"family", map.family}, {"address", address}, {"model", map.name}});
}

QByteArray TopicScheme::conditionPayload(const DeviceCondition &condition, const QDateTime &cycle)
{
    QJsonObject o{{"state", conditionName(condition.state)},
                  {"since", timeOrNull(condition.since)},
                  {"detail", condition.detail}};
    if (cycle.isValid())
        o.insert(QStringLiteral("cycle"), timeText(cycle));
    return compact(o);
}

QByteArray TopicScheme::orderPayload(const QStringList &devices)
{
    return compact({{"devices", QJsonArray::fromStringList(devices)}});
}

QByteArray TopicScheme::valuePayload(const EntryState &state, const RegisterEntry &entry, const QDateTime &readTime)
{
    // A stale value is still shown (its validity says what it is worth); an unknown one not.
    const bool shown = state.validity != Validity::Unknown && state.hasValue();
    const bool number = shown && state.value.isOk();
    QJsonObject o{{"value", number ? QJsonValue::fromVariant(state.value.value) : QJsonValue()},
                  {"text", shown ? ValueFormat::withUnit(state.value, entry, QLocale::c()) : ValueText::noValue()},
                  {"unit", entry.unit},
                  {"status", state.statusName()},
                  {"validity", validityName(state.validity)},
                  {"read", timeOrNull(readTime)}};
    QJsonArray words;
    for (quint16 w : state.words)
        words.append(int(w));
    o.insert(QStringLiteral("words"), words);
    if (state.validity == Validity::Unknown && state.error == ReadError::Exception)
        o.insert(QStringLiteral("exception"), state.exceptionCode);
    if (entry.type == ValueType::Bitfield) {
        QJsonObject bits;
        for (const BitDefinition &bit : entry.bits) {
            if (!bit.reserved)
                bits.insert(bit.id, number ? QJsonValue((state.value.raw & bit.mask()) != 0) : QJsonValue());
        }
        o.insert(QStringLiteral("bits"), bits);
    }
    return compact(o);
}

QByteArray TopicScheme::viewerPayload(const QString &host)
{
    return compact({{"state", "watching"}, {"host", host}});
}

QByteArray TopicScheme::viewerGonePayload()
{
    return compact({{"state", "gone"}});
}

std::optional<StationStatusMessage> TopicScheme::parseStatus(const QByteArray &payload)
{
    const auto o = objectOf(payload);
    if (!o)
        return std::nullopt;
    const QString state = o->value(QLatin1String("state")).toString();
    if (state != QLatin1String("online") && state != QLatin1String("offline"))
        return std::nullopt;
    StationStatusMessage m;
    m.online = state == QLatin1String("online");
    m.reason = o->value(QLatin1String("reason")).toString();
    m.software = o->value(QLatin1String("software")).toString();
    m.started = parseTime(o->value(QLatin1String("started")).toString());
    for (const QJsonValue &line : o->value(QLatin1String("lines")).toArray())
        m.lines << line.toString();
    const QJsonObject foreign = o->value(QLatin1String("foreign")).toObject();
    m.restored = std::max<qint64>(0, foreign.value(QLatin1String("restored")).toInteger());
    m.cleared = std::max<qint64>(0, foreign.value(QLatin1String("cleared")).toInteger());
    return m;
}

std::optional<QDateTime> TopicScheme::parseHeartbeat(const QByteArray &payload)
{
    const auto o = objectOf(payload);
    if (!o)
        return std::nullopt;
    const QDateTime time = parseTime(o->value(QLatin1String("time")).toString());
    if (!time.isValid())
        return std::nullopt;
    return time;
}

std::optional<LineMessage> TopicScheme::parseLine(const QByteArray &payload)
{
    const auto o = objectOf(payload);
    if (!o)
        return std::nullopt;
    const auto state = lineStateFromName(o->value(QLatin1String("state")).toString());
    if (!state)
        return std::nullopt;
    LineMessage m;
    m.address = o->value(QLatin1String("address")).toString();
    m.kind = o->value(QLatin1String("kind")).toString();
    m.state = *state;
    m.since = parseTime(o->value(QLatin1String("since")).toString());
    m.error = o->value(QLatin1String("error")).toString();
    return m;
}

std::optional<DeviceInfoMessage> TopicScheme::parseDeviceInfo(const QByteArray &payload)
{
    const auto o = objectOf(payload);
    if (!o)
        return std::nullopt;
    DeviceInfoMessage m;
    m.line = o->value(QLatin1String("line")).toString();
    m.family = o->value(QLatin1String("family")).toString();
    m.address = o->value(QLatin1String("address")).toInt(-1);
    m.model = o->value(QLatin1String("model")).toString();
    if (m.family.isEmpty() || m.address < 0 || m.address > 255)
        return std::nullopt;
    return m;
}

std::optional<ConditionMessage> TopicScheme::parseCondition(const QByteArray &payload)
{
    const auto o = objectOf(payload);
    if (!o)
        return std::nullopt;
    const auto state = conditionFromName(o->value(QLatin1String("state")).toString());
    if (!state)
        return std::nullopt;
    ConditionMessage m;
    m.condition.state = *state;
    m.condition.since = parseTime(o->value(QLatin1String("since")).toString());
    m.condition.detail = o->value(QLatin1String("detail")).toString();
    m.cycle = parseTime(o->value(QLatin1String("cycle")).toString());
    return m;
}

std::optional<QStringList> TopicScheme::parseOrder(const QByteArray &payload, int maxDevices)
{
    const auto o = objectOf(payload);
    if (!o)
        return std::nullopt;
    const QJsonArray devices = o->value(QLatin1String("devices")).toArray();
    if (devices.size() > maxDevices)
        return std::nullopt;
    QStringList names;
    for (const QJsonValue &device : devices) {
        const QString name = device.toString();
        const qsizetype slash = name.indexOf(QLatin1Char('/'));
        if (slash < 0 || !isTopicLevel(name.left(slash)) || !isTopicLevel(name.mid(slash + 1)))
            return std::nullopt;
        names << name;
    }
    return names;
}

std::optional<ValueMessage> TopicScheme::parseValue(const QByteArray &payload)
{
    const auto o = objectOf(payload);
    if (!o)
        return std::nullopt;
    ValueMessage m;
    const QString validity = o->value(QLatin1String("validity")).toString();
    if (validity == QLatin1String("current"))
        m.validity = Validity::Current;
    else if (validity == QLatin1String("stale"))
        m.validity = Validity::Stale;
    else if (validity == QLatin1String("unknown"))
        m.validity = Validity::Unknown;
    else
        return std::nullopt;
    m.value = o->value(QLatin1String("value"));
    m.text = o->value(QLatin1String("text")).toString();
    m.unit = o->value(QLatin1String("unit")).toString();
    m.status = o->value(QLatin1String("status")).toString();
    // Validity and status say the same thing twice: a message where they disagree was not
    // made by a station (a current value "timeout" is no good value).
    static const QStringList currentStatus = {QStringLiteral("ok"), QStringLiteral("underrange"),
                                              QStringLiteral("overrange"), QStringLiteral("invalid")};
    switch (m.validity) {
    case Validity::Current:
        if (!currentStatus.contains(m.status))
            return std::nullopt;
        break;
    case Validity::Stale:
        if (m.status != QLatin1String("stale"))
            return std::nullopt;
        break;
    case Validity::Unknown:
        // "ok", "stale" and words of no status map to no read error.
        if (readErrorFromStatus(m.status, nullptr) == ReadError::None)
            return std::nullopt;
        break;
    }
    m.error = m.validity == Validity::Unknown ? readErrorFromStatus(m.status, &m.exception) : ReadError::None;
    if (o->contains(QLatin1String("exception")))
        m.exception = o->value(QLatin1String("exception")).toInt();
    for (const QJsonValue &w : o->value(QLatin1String("words")).toArray()) {
        const int word = w.toInt(-1);
        if (word < 0 || word > 0xFFFF)
            return std::nullopt;
        m.words << quint16(word);
    }
    m.read = parseTime(o->value(QLatin1String("read")).toString());
    const QJsonObject bits = o->value(QLatin1String("bits")).toObject();
    for (auto it = bits.begin(); it != bits.end(); ++it)
        m.bits.insert(it.key(), it.value().isBool() ? std::optional<bool>(it.value().toBool()) : std::nullopt);
    return m;
}

} // namespace jumo
