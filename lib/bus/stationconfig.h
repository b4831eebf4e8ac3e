// A station: any number of lines, each with its own settings and devices, as a station
// file (JSON, documented in README "Station files" and resources/stations/) or "--line" specs.
#pragma once

#include "bus/bussettings.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace jumo {

class FamilyRegistry;

struct DeviceSpec
{
    QString family;
    quint8 address = 0;

    // "ipc300@1"
    QString name() const;
    // "FAMILY@ADDRESS" of a known family, the address 1..247 and within the family's range.
    static std::optional<DeviceSpec> parse(const QString &text, const FamilyRegistry &registry, QString *error);
    bool operator==(const DeviceSpec &other) const = default;
};

struct LineConfig
{
    QString name;
    BusSettings settings;
    QList<DeviceSpec> devices;
};

// A device of a station: which line (index into StationConfig::lines), which device.
struct StationDevice
{
    qsizetype line = -1;
    DeviceSpec device;
};

struct StationConfig
{
    Q_DECLARE_TR_FUNCTIONS(jumo::StationConfig)

public:
    static constexpr int formatVersion = 1;
    static constexpr qint64 maxFileBytes = 1024 * 1024;
    static constexpr int maxLineNameLength = 32;

    QString name = defaultName();   // the station's name (MQTT topics, reports)
    QList<LineConfig> lines;

    // The file, validated: every problem is named with the file, the line and the key
    // ("hall.json: lines[1] (cabinet-b): 'baud' must be ..."), one per text line in error.
    static std::optional<StationConfig> load(const QString &path, const FamilyRegistry &registry, QString *error);
    static std::optional<StationConfig> fromJson(const QByteArray &json, const FamilyRegistry &registry, QString *error);
    QByteArray toJson() const;
    // Through FileSaver: the whole file replaced atomically, or the old one left as it was.
    bool save(const QString &path, QString *error) const;

    // "--line" text: ADDRESS[,name=NAME][,baud=N][,format=8N1][,timeout=MS][,min-response=MS]
    // [,retries=N][,read-only]. What the spec leaves out comes from defaults (the command
    // line's --baud, --format, ...). The name stays empty when not given: fromLines names it.
    static std::optional<LineConfig> parseLineSpec(const QString &spec, QString *error);
    static std::optional<LineConfig> parseLineSpec(const QString &spec, const BusSettings &defaults, QString *error);
    // A station of these lines: unnamed lines become "line1", "line2", ... by position;
    // names must be valid and unique, and no address may be on one line twice.
    static std::optional<StationConfig> fromLines(QList<LineConfig> lines, QString *error);

    // 1..32 of [A-Za-z0-9_.-]: safe in MQTT topics and file names.
    static bool isLineName(const QString &text);
    static QString defaultLineName(qsizetype index);
    // The host name, made a valid station name.
    static QString defaultName();

    // The index of the named line, or -1.
    qsizetype lineIndex(const QString &lineName) const;
    // "LINE/FAMILY@ADDRESS" where lines must be told apart (more than one), else "FAMILY@ADDRESS".
    QString deviceName(qsizetype line, const DeviceSpec &device) const;
    // Always "LINE/FAMILY@ADDRESS" (topics, records that name their line).
    static QString qualifiedName(const QString &lineName, const DeviceSpec &device);
    // "LINE/FAMILY@ADDRESS", or "FAMILY@ADDRESS" when the station has exactly one line. The
    // device need not be listed in the line. nullopt with the reason for an unknown or an
    // ambiguous line, an unknown family, a bad address.
    std::optional<StationDevice> resolveDevice(const QString &text, const FamilyRegistry &registry,
                                               QString *error) const;
    // The line a device text names: "LINE/REST", or "REST" on a station of one line; the
    // rest goes to device (unchecked). -1 with the reason for an unknown or ambiguous line.
    qsizetype lineOfDevice(const QString &text, QString *device, QString *error) const;
    // Every listed device, line by line.
    QList<StationDevice> devices() const;
};

} // namespace jumo
