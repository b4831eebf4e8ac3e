// The topics and JSON payloads a station publishes and viewers read (README, "MQTT"):
// built and parsed in this one place, so the publisher and the mirror cannot disagree.
#pragma once

#include "bus/bus.h"
#include "bus/entrystate.h"
#include "bus/lineconnection.h"
#include "protocol/registermap.h"

#include <QByteArray>
#include <QDateTime>
#include <QHash>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <optional>

namespace jumo {

struct StationStatusMessage
{
    bool online = false;
    QString reason;      // offline: "connection lost" (the will) or "stopped"
    QString software;
    QDateTime started;
    QStringList lines;
    // Messages of other clients under the station that it undid: its own published again,
    // or junk cleared (README, "Rogue clients").
    qint64 restored = 0;
    qint64 cleared = 0;
};

struct LineMessage
{
    QString address;
    QString kind;        // "rtu", "tcp", "rtu+tcp"
    LineState state = LineState::Disconnected;
    QDateTime since;
    QString error;
};

struct DeviceInfoMessage
{
    QString line;
    QString family;
    int address = 0;
    QString model;
};

struct ConditionMessage
{
    DeviceCondition condition;
    QDateTime cycle;     // when the device's last poll cycle ended (invalid: not said)
};

struct ValueMessage
{
    QJsonValue value;    // null when there is none to show
    QString text;
    QString unit;
    QString status;      // EntryState::statusName()
    Validity validity = Validity::Unknown;
    ReadError error = ReadError::NotRead;
    QList<quint16> words;
    int exception = 0;
    QDateTime read;      // the last good read, invalid if never
    QHash<QString, std::optional<bool>> bits;
};

class TopicScheme
{
public:
    enum class Kind { Status, Heartbeat, Order, Line, DeviceInfo, DeviceCondition, Value, Viewer, Probe };

    // What a topic names, for a viewer's dispatch.
    struct Topic
    {
        Kind kind = Kind::Status;
        QString station;
        QString line;
        QString device;   // "family@address"
        QString entry;
        QString viewer;   // a viewer's or a probe's id
    };

    explicit TopicScheme(const QString &prefix = QStringLiteral("jumo")) : m_prefix(prefix) { }
    QString prefix() const { return m_prefix; }

    // A name that is one topic level: not empty, no '/', '+', '#' and no NUL.
    static bool isTopicLevel(const QString &name);
    // A prefix of one or more levels ("jumo", "plant/jumo"), without control characters
    // and not in the broker's own '$' topics.
    static bool isValidPrefix(const QString &prefix);

    QString status(const QString &station) const;
    QString heartbeat(const QString &station) const;
    // The station's devices in its order, "LINE/FAMILY@ADDRESS" (retained).
    QString order(const QString &station) const;
    QString line(const QString &station, const QString &line) const;
    QString deviceInfo(const QString &station, const QString &line, const QString &device) const;
    QString deviceCondition(const QString &station, const QString &line, const QString &device) const;
    QString value(const QString &station, const QString &line, const QString &device, const QString &entry) const;
    QString viewer(const QString &station, const QString &viewerId) const;
    // Where a viewer checks whether its user may publish into a station's tree: never
    // retained, ignored by stations and viewers.
    QString probe(const QString &station, const QString &probeId) const;
    // Everything of one station, or of every station when station is empty.
    QString stationFilter(const QString &station) const;
    std::optional<Topic> parse(const QString &topic) const;

    // ISO 8601 UTC with milliseconds: "2026-12-02T10:20:00.123Z".
    static QString timeText(const QDateTime &time);
    static QDateTime parseTime(const QString &text);

    static QString lineKind(const QString &address);
    static QString lineStateName(LineState state);
    static std::optional<LineState> lineStateFromName(const QString &name);
    static QString conditionName(DeviceCondition::State state);
    static std::optional<DeviceCondition::State> conditionFromName(const QString &name);
    // The inverse of EntryState::statusName() for what is not current.
    static ReadError readErrorFromStatus(const QString &status, int *exceptionCode);

    static QByteArray statusOnline(const QString &software, const QDateTime &started, const QStringList &lines,
                                   qint64 restored = 0, qint64 cleared = 0);
    static QByteArray statusOffline(const QString &reason);
    static QByteArray heartbeatPayload(const QDateTime &time);
    static QByteArray linePayload(const QString &address, LineState state, const QDateTime &since, const QString &error);
    static QByteArray deviceInfoPayload(const QString &line, const RegisterMap &map, int address);
    // cycle: when the device's last poll cycle ended (invalid: left out).
    static QByteArray conditionPayload(const DeviceCondition &condition, const QDateTime &cycle = {});
    static QByteArray orderPayload(const QStringList &devices);
    // readTime: the wall-clock time of the value's last good read (invalid: never).
    static QByteArray valuePayload(const EntryState &state, const RegisterEntry &entry, const QDateTime &readTime);
    static QByteArray viewerPayload(const QString &host);
    static QByteArray viewerGonePayload();

    static std::optional<StationStatusMessage> parseStatus(const QByteArray &payload);
    static std::optional<QDateTime> parseHeartbeat(const QByteArray &payload);
    static std::optional<LineMessage> parseLine(const QByteArray &payload);
    static std::optional<DeviceInfoMessage> parseDeviceInfo(const QByteArray &payload);
    static std::optional<ConditionMessage> parseCondition(const QByteArray &payload);
    // A value whose validity and status disagree ("current" with "timeout", "unknown" with
    // "ok") is refused: it is no value a station publishes.
    static std::optional<ValueMessage> parseValue(const QByteArray &payload);
    // At most maxDevices names, each "LINE/FAMILY@ADDRESS" with topic levels for both.
    static std::optional<QStringList> parseOrder(const QByteArray &payload, int maxDevices);

private:
    QString m_prefix;
};

} // namespace jumo
