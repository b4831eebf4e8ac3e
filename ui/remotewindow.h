// The control-room viewer of stations that publish to an MQTT broker (jumo-hmi --remote):
// the same overview, faceplates, device pages, LEDs and trend as a station's own window,
// fed by the broker, in the stations' order. It holds no Bus and no port, so nothing in it
// can write; its only publications are its presence and its write probe. Alarms it sees go
// to its own journal. Faceplates, pages and rows are keyed by device id and go when their
// device leaves its station.
#pragma once

#include "bus/mirroredline.h"
#include "mqtt/mqttsettings.h"

#include <QHash>
#include <QMainWindow>

#include <memory>

class QLabel;
class QListWidget;
class QListWidgetItem;
class QStackedWidget;
class QTimer;

namespace jumo {

class AlarmBitsModel;
class AlarmJournal;
class DevicePage;
class DeviceTile;
class EventLog;
class EventLogView;
class FamilyRegistry;
class LineHeader;
class LiveValuesModel;
class OverviewPage;
class RemoteLines;
class RemoteStation;

class RemoteWindow : public QMainWindow
{
    Q_OBJECT

public:
    struct Options
    {
        MqttSettings broker;
        QString station;        // empty: every station under the prefix
        QString prefix = QStringLiteral("jumo");
        QString logFolder;      // empty: EventLog::defaultFolder()
    };

    RemoteWindow(const FamilyRegistry &registry, const Options &options, QWidget *parent = nullptr);
    ~RemoteWindow() override;

    // Connects to the broker (and keeps reconnecting by itself); false with the reason
    // when the settings cannot be used at all.
    bool start(QString *error);

    RemoteStation *station() const { return m_station.get(); }
    OverviewPage *overview() const { return m_overview; }
    DeviceTile *deviceTile(const QString &line, const QString &family, quint8 address) const;
    // The device's page, made when first asked for.
    DevicePage *devicePage(const QString &line, const QString &family, quint8 address);
    LineHeader *lineHeader(const QString &line) const;
    void showDevice(DevicePage *page);
    EventLogView *journalView() const { return m_journalView; }
    // Every faceplate of the overview, in the order shown.
    QList<DeviceTile *> tilesInOrder() const;

private:
    struct Device
    {
        MirroredLine *line = nullptr;
        LiveValuesModel *values = nullptr;
        AlarmBitsModel *alarms = nullptr;
        DeviceTile *tile = nullptr;
        DevicePage *page = nullptr;
        QListWidgetItem *item = nullptr;
    };
    struct Line
    {
        LineHeader *header = nullptr;
        QListWidgetItem *item = nullptr;
        AlarmJournal *journal = nullptr;
    };

    void onLineAdded(MirroredLine *line);
    void onLineRemoving(MirroredLine *line);
    void onDeviceAdded(MirroredLine *line, DeviceId id);
    void onDeviceRemoving(MirroredLine *line, DeviceId id);
    // The overview and the page list in the stations' order (coalesced: many devices come
    // at once).
    void reorder();
    void fitNavigationWidth();
    void showForgeryWarning();
    void updateLine(MirroredLine *line);
    void updateDevice(DeviceId id);
    void updateStatus();
    DevicePage *ensurePage(DeviceId id);
    DeviceId find(const QString &line, const QString &family, quint8 address) const;
    // "cabinet-a", or "hall-3/cabinet-a" once more than one station is shown.
    QString lineLabel(MirroredLine *line) const;
    // The line's state in words: "Connected", "Line lost: ...", "Disconnected".
    QString lineStateText(MirroredLine *line) const;

    const FamilyRegistry &m_registry;
    Options m_options;
    std::unique_ptr<RemoteStation> m_station;
    std::unique_ptr<RemoteLines> m_lines;
    QListWidget *m_navigation;
    QStackedWidget *m_pages;
    OverviewPage *m_overview;
    EventLog *m_journalLog;
    EventLogView *m_journalView;
    QLabel *m_brokerStatus;
    QLabel *m_stationStatus;
    QLabel *m_forgeryBanner;
    QLabel *m_forgeryStatus;
    QTimer *m_reorder;
    QHash<MirroredLine *, Line> m_lineEntries;
    QHash<DeviceId, Device> m_devices;
    QString m_brokerError;
};

} // namespace jumo
