// The lines of the stations a RemoteStation mirrors, each as a MirroredLine: a DeviceSource
// like a station's own Bus, so the overview, the device pages, the LEDs, the trend and the
// journal show a remote line with the same classes, and nothing among them can write.
// While a station is not live (offline, silent, or the broker out of reach) its lines
// read "Lost" with the reason and the time this viewer lost contact, and its devices
// "Line lost"; while the viewer waits for a station it has not yet seen live, they read
// "Disconnected" (no loss to record). Lines and devices leave when the station clears
// their topics; the order is the station's.
#pragma once

#include "bus/mirroredline.h"

#include <QHash>
#include <QObject>
#include <QSet>

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
    MirroredLine *line(const QString &station, const QString &line) const;
    QString stationOf(const MirroredLine *line) const;

    // Every line in the order to show: stations by name, each station's lines as it lists
    // them; and every device, as its station lists them (others after, by address).
    QList<MirroredLine *> orderedLines() const;
    QList<DeviceId> orderedDevices(const MirroredLine *line) const;

signals:
    void lineAdded(jumo::MirroredLine *line);
    // Emitted before the line goes (deleted later: signals may be on their way).
    void lineRemoving(jumo::MirroredLine *line);
    void deviceAdded(jumo::MirroredLine *line, jumo::DeviceId id);
    // Emitted before the device leaves its line.
    void deviceRemoving(jumo::MirroredLine *line, jumo::DeviceId id);
    // The order of lines or devices to show changed.
    void orderChanged();

private:
    struct Mirrored
    {
        MirroredLine *line = nullptr;
        DeviceId id = -1;
    };
    // Why a station's publications do not count now.
    struct Silence
    {
        enum class Kind { Live, Waiting, Lost } kind = Kind::Live;
        QString reason;
        QDateTime since;
    };

    MirroredLine *ensureLine(const QString &station, const QString &line);
    void removeLineIfGone(const QString &station, const QString &line);
    void onDeviceAdded(DeviceId remote);
    void onDeviceRemoved(DeviceId remote);
    void onEntriesUpdated(DeviceId remote, const QStringList &ids);
    void onConditionChanged(DeviceId remote);
    void onStationChanged(const QString &station);
    void updateLine(const QString &station, const QString &line);
    Silence silenceOf(const QString &station) const;

    RemoteStation *m_station;
    std::vector<std::unique_ptr<MirroredLine>> m_lines;
    QHash<QString, MirroredLine *> m_lineByKey;   // "station/line"
    QHash<const MirroredLine *, QString> m_stationOf;
    QHash<DeviceId, Mirrored> m_mirrored;         // the RemoteStation's id -> ours
    QHash<DeviceId, DeviceId> m_remoteOf;         // ours -> the RemoteStation's
};

} // namespace jumo
