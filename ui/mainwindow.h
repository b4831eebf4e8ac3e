// The HMI's main window: it composes the connection bar, the device list, the overview,
// the traffic page and one page per device, over any number of lines (StationLine), and
// keeps the settings. Everything that knows about devices lives in the pages and models
// it creates.
#pragma once

#include "bus/bus.h"
#include "bus/stationconfig.h"
#include "commissioning/commissioningreport.h"

#include <QDateTime>
#include <QHash>
#include <QJsonObject>
#include <QMap>
#include <QMainWindow>
#include <QSettings>

#include <memory>

class QLabel;
class QListWidget;
class QMenu;
class QStackedWidget;

namespace jumo {

class AlarmBitsModel;
class ConnectionBar;
class DataLogger;
class LiveValuesModel;
class LineHeader;
class NavigationList;
class StationLine;
class DemoLine;
class DevicePage;
class EventLog;
class EventLogView;
class DeviceTile;
class ElidedLabel;
class FamilyRegistry;
class OverviewPage;
class TrafficView;

class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    struct Options
    {
        bool demo = false;
        bool readOnly = false;  // --read-only or the system configuration's readOnly
        // Each device is checked to be of its family when it answers (off: --no-identify).
        bool identify = true;
        QString settingsFile;   // empty: the user's settings
        QString logFolder;      // empty: EventLog::defaultFolder(), its demo/ for the demo
        QString theme;          // a Theme name for this run; empty: the one last chosen in the View menu
        // Lines given on the command line (--line, --station): used instead of the kept
        // ones, and not kept.
        QList<LineConfig> lines;
    };

    MainWindow(const FamilyRegistry &registry, const Options &options, QWidget *parent = nullptr);
    ~MainWindow() override;

    // The first line's bus (a window has one line at least).
    Bus *bus();
    bool isReadOnly() const { return m_readOnly; }
    ConnectionBar *connectionBar() const { return m_connectionBar; }
    // The first device of that family and address, on whichever line.
    DevicePage *devicePage(const QString &family, quint8 address) const;
    DeviceTile *deviceTile(const QString &family, quint8 address) const;
    // The device on the named line.
    DevicePage *devicePage(const QString &line, const QString &family, quint8 address) const;
    DeviceTile *deviceTile(const QString &line, const QString &family, quint8 address) const;

    QList<StationLine *> lines() const { return m_lines; }
    StationLine *line(const QString &name) const;
    LineHeader *lineHeader(const QString &name) const;
    // The line the connection bar, Connect, Add and Scan act on: the line of the device
    // page shown, or the one chosen.
    StationLine *currentLine() const { return m_currentLine; }
    void setCurrentLine(StationLine *line);
    // A new line, disconnected; nullptr (with the reason) when the name is not fit or taken.
    StationLine *addLine(const QString &name, const BusSettings &settings, QString *error = nullptr);
    // Closes the line and removes it with its devices (the last line stays).
    bool removeLine(StationLine *line);
    // "2 lines connected, 1 lost": the status bar's summary of the lines.
    QString linesSummary() const;
    // Opens a line with its own settings; false with the reason in its lastError().
    bool connectLine(StationLine *line);
    // Connects every disconnected line; the lines that could not be, with the reason.
    QStringList connectAllLines();
    void disconnectAllLines();
    DemoLine *demoLine() const { return m_demo.get(); }
    EventLog *alarmJournal() const { return m_journalLog; }
    EventLog *auditLog() const { return m_auditLog; }
    EventLogView *journalView() const { return m_journalView; }
    EventLogView *auditView() const { return m_auditView; }

    // The data logger of a device, made when first asked for; a failure shows in the
    // status bar and the journal.
    DataLogger *dataLogger(DeviceId id);

    // The current line, with the address, baud and format of the connection bar.
    bool connectLine();
    void disconnectLine();
    // Adds a device to the current line, the list and the overview; its page is made when shown.
    bool addDevice(std::shared_ptr<const RegisterMap> map, quint8 address);
    bool addDevice(StationLine *line, std::shared_ptr<const RegisterMap> map, quint8 address);
    void showDevice(DevicePage *page);
    void showDevice(const QString &family, quint8 address);
    void showOverview();
    void openScanDialog();
    void openFindDialog();
    // The commissioning report of a device, with the writes since this window opened.
    bool writeReport(const QString &family, quint8 address, const QString &path, const ReportTitle &title,
                     QString *error);
    // The title block offered for a device's next report: what was given last time (the
    // tag per device, the rest for every device).
    ReportTitle reportTitle(const QString &family, quint8 address);
    void rememberReportTitle(const QString &family, quint8 address, const ReportTitle &title);

signals:
    void demoReady();

protected:
    void closeEvent(QCloseEvent *event) override;
    // A text field being typed in keeps its word-deleting keys (Ctrl+Delete would
    // otherwise remove the device whose value is being typed).
    bool event(QEvent *event) override;

private:
    // Models live as long as the device; its page is made the first time it is shown,
    // so thirty devices in a control room cost thirty tiles, not thirty pages.
    struct DeviceEntry
    {
        DeviceId id;
        StationLine *line;
        LiveValuesModel *values;
        AlarmBitsModel *alarms;
        DeviceTile *tile;
        DevicePage *page;
        DataLogger *logger;   // made when logging is first asked for
    };
    DevicePage *ensurePage(int index) const;
    // The position of a device in m_devices (and in the navigation after its first
    // rows), -1 when it is gone. Tiles and callbacks keep ids, never positions.
    int indexOf(DeviceId id) const;
    int indexOf(const StationLine *line, const QString &family, quint8 address) const;
    // The device at this address on the line, of whatever family; -1 when none.
    int indexAt(const StationLine *line, quint8 address) const;
    void onNavigation(int row);
    // The line rows and device rows of the list again, after lines or devices changed.
    void rebuildNavigation();
    // Headers on the overview and in the list, and line names in the logs, while there
    // are several lines.
    void updateLineGrouping();
    // The connection bar shows the current line: its address, format and state.
    void showLineInBar();
    void takeSettingsFromBar();
    void addLineInteractively();
    void connectAllInteractively();
    void editCurrentLine();
    void removeCurrentLineInteractively();
    // "ipc300@1", or "line2/ipc300@1" where lines must be told apart.
    QString deviceName(const DeviceEntry &d) const;
    // The device a report of family@address is about: on the current line first.
    int reportDevice(const QString &family, quint8 address) const;
    // The device's list entry: its state icon and a tooltip with the full name and state.
    void updateNavigationItem(DeviceId id);

    void buildMenus();
    // Keyboard: pages by number (Ctrl+0 overview, Ctrl+1..9 devices), next and previous.
    void buildPageShortcuts(QMenu *view);
    void showNavigationRow(int row);
    void requestConnect();
    void addDeviceInteractively();
    // The device whose page is shown, or -1.
    int currentDeviceIndex() const;
    // Applies a theme (and keeps it for the next start): palette, tiles, banners.
    void setTheme(int kind);
    void startDemo();
    void removeCurrentDevice();
    void removeCurrentDeviceInteractively();
    void onLineStateChanged(StationLine *line);
    void updateStatus();
    void restoreSettings();
    void saveSettings();
    // A log that failed to keep a record, in the status bar until the window closes
    // (the newest message of each source).
    void showLogFailure(const QString &source, const QString &message);
    void journalLogEvent(const QString &device, const QString &id, const QString &label, const QString &state);
    QSettings &settings();

    const FamilyRegistry &m_registry;
    Options m_options;
    bool m_readOnly = false;
    QList<StationLine *> m_lines;
    StationLine *m_currentLine = nullptr;
    QHash<StationLine *, LineHeader *> m_headers;
    bool m_fillingBar = false;
    int m_listMinimumWidth = 0;   // of the page list with one line
    std::unique_ptr<DemoLine> m_demo;
    std::unique_ptr<QSettings> m_settings;
    ConnectionBar *m_connectionBar;
    QAction *m_connectAction = nullptr;
    QAction *m_disconnectAction = nullptr;
    NavigationList *m_navigation;
    QStackedWidget *m_pages;
    OverviewPage *m_overview;
    TrafficView *m_traffic;
    EventLog *m_journalLog;
    EventLog *m_auditLog;
    EventLogView *m_journalView;
    EventLogView *m_auditView;
    ElidedLabel *m_lineStatus;
    QLabel *m_loadStatus;
    ElidedLabel *m_errorStatus;
    ElidedLabel *m_logFailure;
    int m_unloggedRecords = 0;
    QMap<QString, QString> m_logFailures;
    QList<QJsonObject> m_sessionWrites;   // audit records appended by this window
    QDateTime m_sessionStart = QDateTime::currentDateTime();
    mutable QList<DeviceEntry> m_devices;
    QHash<StationLine *, int> m_requestsAtLastStatus;
    QString m_lastError;       // the newest error, not yet shown
    QString m_shownError;      // the error the status bar shows now
    qint64 m_lastErrorShownMs = -1;
};

} // namespace jumo
