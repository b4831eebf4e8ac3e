// The lines of the stations a RemoteStation mirrors, each as a MirroredLine: a DeviceSource
// like a station's own Bus, so the overview, the device pages, the LEDs, the trend and the
// journal show a remote line with the same classes, and nothing among them can write.
// While a station is not live (offline, silent, or the broker out of reach) its lines
// read "Lost" with the reason, and its devices "Line lost"; the values keep what the
// RemoteStation made of them (stale, not unknown).
#pragma once

#include "bus/mirroredline.h"

#include <QHash>
#include <QObject>

#include <memory>
#include <vector>

namespace jumo {

class RemoteStation;

class RemoteLines : public QObject
{
    Q_OBJECT

public:
    explicit RemoteLines(RemoteStation *station, QObject *parent = nullptr);
    ~RemoteLines() override;

    QList<MirroredLine *> lines() const;
    // The line's label: "line" for one station, "station/line" once there are several.
    MirroredLine *line(const QString &station, const QString &line) const;
    QString stationOf(const MirroredLine *line) const;

signals:
    void lineAdded(jumo::MirroredLine *line);
    void deviceAdded(jumo::MirroredLine *line, jumo::DeviceId id);
    // Emitted before the device leaves its line.
    void deviceRemoving(jumo::MirroredLine *line, jumo::DeviceId id);
    // A device whose family this program has no map of (it cannot be shown).
    void unknownFamily(const QString &station, const QString &line, const QString &device);

private:
    struct Mirrored
    {
        MirroredLine *line = nullptr;
        DeviceId id = -1;
    };

    MirroredLine *ensureLine(const QString &station, const QString &line);
    void onDeviceAdded(DeviceId remote);
    void onDeviceRemoved(DeviceId remote);
    void onEntriesUpdated(DeviceId remote, const QStringList &ids);
    void onConditionChanged(DeviceId remote);
    void onStationChanged(const QString &station);
    void updateLine(const QString &station, const QString &line);
    // Why the station's publications do not count now; empty while it is live.
    QString silenceReason(const QString &station) const;

    RemoteStation *m_station;
    std::vector<std::unique_ptr<MirroredLine>> m_lines;
    QHash<QString, MirroredLine *> m_lineByKey;   // "station/line"
    QHash<const MirroredLine *, QString> m_stationOf;
    QHash<DeviceId, Mirrored> m_mirrored;         // the RemoteStation's id -> ours
};

} // namespace jumo
