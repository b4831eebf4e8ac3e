#include "mainwindow.h"

#include "adddevicedialog.h"
#include "commissioning/commissioningreport.h"
#include "reportwriter.h"
#include "reportdetailsdialog.h"
#include "models/alarmbitsmodel.h"
#include "models/devicetitle.h"
#include "connectionbar.h"
#include "logs/datalogger.h"
#include "dataloggingdialog.h"
#include "sim/demoline.h"
#include "devicepage.h"
#include "devicestateicon.h"
#include "devicetile.h"
#include "elidedlabel.h"
#include "linedialog.h"
#include "lineheader.h"
#include "navigationlist.h"
#include "stationline.h"
#include "stationsettings.h"
#include "logs/alarmjournal.h"
#include "logs/eventlog.h"
#include "eventlogview.h"
#include "logs/writeaudit.h"
#include "protocol/familyregistry.h"
#include "models/livevaluesmodel.h"
#include "overviewpage.h"
#include "parametersdialog.h"
#include "scandialog.h"
#include "finddialog.h"
#include "theme.h"
#include "trafficview.h"
#include "jumoversion.h"

#include <QApplication>
#include <QFileDialog>
#include <QRegularExpression>
#include <QCloseEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QKeyEvent>
#include <QLineEdit>
#include <QListWidget>
#include <QActionGroup>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPointer>
#include <QPushButton>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTextEdit>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

#include <utility>

namespace jumo {

namespace {

constexpr int overviewRow = 0;
constexpr int trafficRow = 1;
constexpr int journalRow = 2;
constexpr int auditRow = 3;

// The demo's simulated devices keep logs of their own: none of their alarms and writes
// among the plant's.
QString logFolder(const MainWindow::Options &options)
{
    if (!options.logFolder.isEmpty())
        return options.logFolder;
    return EventLog::defaultFolder() + (options.demo ? QStringLiteral("/demo") : QString());
}

} // namespace

MainWindow::MainWindow(const FamilyRegistry &registry, const Options &options, QWidget *parent)
    : QMainWindow(parent), m_registry(registry), m_options(options), m_connectionBar(new ConnectionBar(this)),
      m_navigation(new NavigationList({tr("Overview"), tr("Traffic and statistics"), tr("Alarm journal"),
                                       tr("Write audit log")},
                                      this)),
      m_pages(new QStackedWidget(this)), m_overview(new OverviewPage(this)), m_traffic(new TrafficView(this)),
      m_journalLog(new EventLog(logFolder(options) + QStringLiteral("/alarm-journal.jsonl"), this)),
      m_auditLog(new EventLog(logFolder(options) + QStringLiteral("/write-audit.jsonl"), this)),
      m_journalView(new EventLogView(m_journalLog, AlarmJournal::columns(),
                                     {tr("Time"), tr("Device"), tr("Register"), tr("Bit"), tr("Id"), tr("Signal"),
                                      tr("Kind"), tr("State")},
                                     this)),
      m_auditView(new EventLogView(m_auditLog, WriteAudit::columns(),
                                   {tr("Time"), tr("Device"), tr("Entry"), tr("Old value"), tr("New value"),
                                    tr("Result"), tr("Message")},
                                   this)),
      m_lineStatus(new ElidedLabel(this)), m_loadStatus(new QLabel(this)),
      m_errorStatus(new ElidedLabel(this)), m_logFailure(new ElidedLabel(this))
{
    setObjectName(QStringLiteral("mainWindow"));
    // The theme first: the widgets below take their colours from it.
    if (const auto kind = Theme::fromName(options.theme.isEmpty()
                                                  ? settings().value(QStringLiteral("theme")).toString()
                                                  : options.theme))
        Theme::apply(*kind);
    else
        Theme::apply(Theme::Kind::System);
    // options.readOnly includes the system-wide configuration's, which jumo-hmi reads.
    m_readOnly = options.readOnly;
    setWindowTitle(m_readOnly ? tr("JUMO HMI [read-only]") : tr("JUMO HMI"));

    auto *toolbar = addToolBar(tr("Connection"));
    toolbar->setObjectName(QStringLiteral("connectionToolBar"));
    toolbar->setMovable(false);
    toolbar->addWidget(m_connectionBar);
    connect(m_connectionBar, &ConnectionBar::connectRequested, this, &MainWindow::requestConnect);
    connect(m_connectionBar, &ConnectionBar::disconnectRequested, this, &MainWindow::disconnectLine);
    connect(m_connectionBar, &ConnectionBar::lineChosen, this, [this](int index) {
        if (index >= 0 && index < m_lines.size())
            setCurrentLine(m_lines[index]);
    });
    connect(m_connectionBar, &ConnectionBar::settingsEdited, this, &MainWindow::takeSettingsFromBar);

    m_navigation->setObjectName(QStringLiteral("navigation"));
    // Short names with a state icon; what does not fit ends in "…" and is in the tooltip.
    m_navigation->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_navigation->setTextElideMode(Qt::ElideRight);
    m_navigation->setIconSize(QSize(16, 16));
    m_pages->addWidget(m_overview);
    m_pages->addWidget(m_traffic);
    m_pages->addWidget(m_journalView);
    m_pages->addWidget(m_auditView);
    m_journalView->setObjectName(QStringLiteral("alarmJournal"));
    m_auditView->setObjectName(QStringLiteral("auditLog"));
    connect(m_navigation, &QListWidget::currentRowChanged, this, &MainWindow::onNavigation);
    auto *addButton = new QPushButton(tr("Add..."), this);
    auto *scanButton = new QPushButton(tr("Scan..."), this);
    auto *removeButton = new QPushButton(tr("Remove"), this);
    addButton->setObjectName(QStringLiteral("addDeviceButton"));
    scanButton->setObjectName(QStringLiteral("scanButton"));
    removeButton->setObjectName(QStringLiteral("removeDeviceButton"));
    connect(addButton, &QPushButton::clicked, this, &MainWindow::addDeviceInteractively);
    connect(scanButton, &QPushButton::clicked, this, &MainWindow::openScanDialog);
    connect(removeButton, &QPushButton::clicked, this, &MainWindow::removeCurrentDevice);
    auto *side = new QWidget(this);
    auto *sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    sideLayout->addWidget(m_navigation);
    // Two buttons a row keep the list narrow and the pages wide.
    auto *sideButtons = new QGridLayout;
    sideButtons->addWidget(addButton, 0, 0);
    sideButtons->addWidget(scanButton, 0, 1);
    sideButtons->addWidget(removeButton, 1, 0);
    sideLayout->addLayout(sideButtons);
    auto *split = new QSplitter(this);
    split->setObjectName(QStringLiteral("mainSplitter"));
    split->addWidget(side);
    split->addWidget(m_pages);
    split->setStretchFactor(1, 4);
    split->setCollapsible(0, false);
    split->setCollapsible(1, false);
    // The list as wide as its page names, a short device name ("dTRON 300 @ 247") and
    // its buttons; the pages get the rest.
    const int listWidth = std::max({m_navigation->sizeHintForColumn(0),
                                    m_navigation->fontMetrics().horizontalAdvance(QStringLiteral("dTRON 300 @ 247")) + 16 + 12})
            + 2 * m_navigation->frameWidth() + 8;
    side->setMinimumWidth(std::max(listWidth, sideButtons->minimumSize().width()));
    m_listMinimumWidth = side->minimumWidth();
    split->setSizes({side->minimumWidth(), 1280 - side->minimumWidth()});
    setCentralWidget(split);

    m_lineStatus->setObjectName(QStringLiteral("lineStatus"));
    m_loadStatus->setObjectName(QStringLiteral("loadStatus"));
    m_errorStatus->setObjectName(QStringLiteral("errorStatus"));
    // The lines' state as wide as it needs (an elided label takes no room of itself and
    // had none: the line's state was never seen); the newest error gets the rest.
    m_lineStatus->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
    statusBar()->addWidget(m_lineStatus);
    statusBar()->addWidget(m_loadStatus);
    statusBar()->addWidget(m_errorStatus, 1);
    if (m_readOnly) {
        auto *mode = new QLabel(tr("READ-ONLY"), this);
        mode->setObjectName(QStringLiteral("readOnlyIndicator"));
        mode->setStyleSheet(Theme::bannerStyle(Theme::Role::InfoBanner, Theme::Role::InfoBannerText)
                            + QStringLiteral("; padding: 0 6px; font-weight: bold"));
        statusBar()->addPermanentWidget(mode);
    }
    // A record the logs could not keep is no passing error: it stays until the end.
    m_logFailure->setObjectName(QStringLiteral("logFailureStatus"));
    m_logFailure->setStyleSheet(Theme::bannerStyle(Theme::Role::ErrorBanner, Theme::Role::ErrorBannerText)
                                + QStringLiteral("; padding: 0 6px"));
    m_logFailure->hide();
    statusBar()->addPermanentWidget(m_logFailure);
    const EventLog::Rotation rotation = EventLog::Rotation::fromSettings(settings());
    for (EventLog *log : {m_journalLog, m_auditLog}) {
        log->setRotation(rotation);
        connect(log, &EventLog::writeFailed, this, [this, log](const QString &message) {
            ++m_unloggedRecords;
            showLogFailure(QStringLiteral("logs"),
                           tr("Not logged (%n record(s) so far): %1", nullptr, m_unloggedRecords).arg(message));
            // The journal has the start of a failure of the audit log and its end, not
            // every record lost in between.
            if (log == m_auditLog && log->unwrittenRecords() == 1)
                journalLogEvent(QString(), QStringLiteral("write_audit_log"), QStringLiteral("Write audit log"),
                                QStringLiteral("not written: %1").arg(message));
        });
    }
    connect(m_auditLog, &EventLog::writeRecovered, this, [this](int lost) {
        journalLogEvent(QString(), QStringLiteral("write_audit_log"), QStringLiteral("Write audit log"),
                        QStringLiteral("written again; %1 record(s) lost").arg(lost));
    });
    // The report lists the writes of the session: kept here, the log may be large.
    connect(m_auditLog, &EventLog::appended, this, [this](const QJsonObject &record) { m_sessionWrites << record; });
    auto *statusTimer = new QTimer(this);
    connect(statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
    statusTimer->start(1000);

    buildMenus();
    m_navigation->setCurrentRow(overviewRow);
    resize(1280, 800);
    if (options.demo) {
        startDemo();
    } else if (!options.lines.isEmpty()) {
        restoreGeometry(settings().value(QStringLiteral("window/geometry")).toByteArray());
        for (const LineConfig &config : options.lines) {
            if (StationLine *line = addLine(config.name, config.settings)) {
                for (const DeviceSpec &device : config.devices)
                    addDevice(line, m_registry.family(device.family), device.address);
            }
        }
    } else {
        restoreSettings();
    }
    // A window has a line to connect at least: the first one, named as such.
    if (m_lines.isEmpty())
        addLine(QStringLiteral("line1"), BusSettings{});
    showLineInBar();
    updateStatus();
}

MainWindow::~MainWindow()
{
    // The clients go first, then the simulator, then socat.
    for (StationLine *line : std::as_const(m_lines))
        line->close();
}

Bus *MainWindow::bus()
{
    return m_lines.isEmpty() ? nullptr : m_lines.first()->bus();
}

QSettings &MainWindow::settings()
{
    if (!m_settings) {
        m_settings = m_options.settingsFile.isEmpty()
                ? std::make_unique<QSettings>(QStringLiteral("jumo"), QStringLiteral("jumo-hmi"))
                : std::make_unique<QSettings>(m_options.settingsFile, QSettings::IniFormat);
    }
    return *m_settings;
}

void MainWindow::buildMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu *line = menuBar()->addMenu(tr("&Line"));
    line->setObjectName(QStringLiteral("lineMenu"));
    m_connectAction = line->addAction(tr("&Connect"), QKeySequence(Qt::Key_F5), this, &MainWindow::requestConnect);
    m_disconnectAction = line->addAction(tr("&Disconnect"), QKeySequence(Qt::SHIFT | Qt::Key_F5), this,
                                         &MainWindow::disconnectLine);
    m_disconnectAction->setEnabled(false);
    line->addAction(tr("Connect &all lines"), this, &MainWindow::connectAllInteractively)
            ->setObjectName(QStringLiteral("connectAllLines"));
    line->addAction(tr("Disc&onnect all lines"), this, &MainWindow::disconnectAllLines)
            ->setObjectName(QStringLiteral("disconnectAllLines"));
    line->addSeparator();
    line->addAction(tr("&New line..."), this, &MainWindow::addLineInteractively)->setObjectName(QStringLiteral("addLine"));
    line->addAction(tr("&Edit the line..."), this, &MainWindow::editCurrentLine)->setObjectName(QStringLiteral("editLine"));
    line->addAction(tr("&Remove the line..."), this, &MainWindow::removeCurrentLineInteractively)
            ->setObjectName(QStringLiteral("removeLine"));

    QMenu *devices = menuBar()->addMenu(tr("&Devices"));
    devices->addAction(tr("&Add a device..."), QKeySequence::New, this, &MainWindow::addDeviceInteractively);
    devices->addAction(tr("&Scan the line..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S), this,
                       &MainWindow::openScanDialog);
    devices->addAction(tr("&Find on an unknown line..."), this, &MainWindow::openFindDialog)
            ->setObjectName(QStringLiteral("findDevices"));
    devices->addAction(tr("&Remove the shown device..."), QKeySequence(Qt::CTRL | Qt::Key_Delete), this,
                       &MainWindow::removeCurrentDeviceInteractively);
    devices->addSeparator();
    devices->addAction(tr("&Parameters: back up, compare, restore..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P),
                       this, [this] {
        const int index = currentDeviceIndex();
        if (index < 0) {
            QMessageBox::information(this, tr("Parameters"), tr("Open the page of a device first."));
            return;
        }
        ParametersDialog dialog(m_devices[index].line->bus(), m_devices[index].id, this);
        dialog.exec();
    });
    devices->addAction(tr("&Data logging of the shown device..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L),
                       this, [this] {
        const int index = currentDeviceIndex();
        if (index < 0) {
            QMessageBox::information(this, tr("Data logging"), tr("Open the page of a device first."));
            return;
        }
        const DeviceId id = m_devices[index].id;
        DataLoggingDialog dialog(m_devices[index].line->bus(), id, dataLogger(id), this);
        dialog.exec();
    });
    devices->addAction(tr("&Commissioning report of the shown device..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R),
                       this, [this] {
        const int index = currentDeviceIndex();
        if (index < 0) {
            QMessageBox::information(this, tr("Report"), tr("Open the page of a device first."));
            return;
        }
        const DeviceId id = m_devices[index].id;
        const Bus *bus = m_devices[index].line->bus();
        const QString family = bus->deviceMap(id)->family;
        const quint8 address = bus->deviceAddress(id);
        // Reports of devices on other lines than the current one are not offered here.
        setCurrentLine(m_devices[index].line);
        ReportDetailsDialog details(DeviceTitle::brief(*bus->deviceMap(id), address),
                                    reportTitle(family, address), this);
        details.setObjectName(QStringLiteral("reportDetailsDialog"));
        if (details.exec() != QDialog::Accepted)
            return;
        const ReportTitle title = details.title();
        rememberReportTitle(family, address, title);
        // A name that says what it is: the tag (or the device) and the day.
        QString name = title.tag.isEmpty() ? QStringLiteral("%1-%2").arg(family).arg(address) : title.tag;
        name.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9._-]+")), QStringLiteral("_"));
        const QString suggested = tr("commissioning-report-%1-%2.pdf").arg(name, QDate::currentDate().toString(Qt::ISODate));
        const QString path = QFileDialog::getSaveFileName(this, tr("Commissioning report"), suggested,
                                                          tr("PDF (*.pdf);;HTML (*.html)"));
        QString error;
        if (!path.isEmpty() && !writeReport(family, address, path, title, &error))
            QMessageBox::warning(this, tr("Report"), error);
    });

    buildPageShortcuts(menuBar()->addMenu(tr("&View")));
    QMenu *language = menuBar()->addMenu(tr("La&nguage"));
    for (const auto &[code, name] : {std::pair{"", QT_TR_NOOP("System language")}, std::pair{"en", "English"},
                                     std::pair{"de", "Deutsch"}}) {
        QAction *action = language->addAction(code[0] ? QString::fromUtf8(name) : tr(name));
        action->setCheckable(true);
        action->setChecked(settings().value(QStringLiteral("language")).toString() == QLatin1String(code));
        connect(action, &QAction::triggered, this, [this, code = QString::fromLatin1(code)] {
            settings().setValue(QStringLiteral("language"), code);
            QMessageBox::information(this, tr("Language"), tr("The language changes when the HMI is started again."));
        });
    }
    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About"), this, [this] {
        QMessageBox::about(this, tr("About JUMO HMI"),
                           tr("JUMO HMI %1\nCommissioning and monitoring of JUMO power and process controllers "
                              "over Modbus RTU.")
                                   .arg(QStringLiteral(JUMO_VERSION)));
    });
}

void MainWindow::buildPageShortcuts(QMenu *view)
{
    view->addAction(tr("&Overview"), QKeySequence(Qt::CTRL | Qt::Key_0), this,
                    [this] { showNavigationRow(overviewRow); });
    view->addAction(tr("&Traffic and statistics"), QKeySequence(Qt::CTRL | Qt::Key_T), this,
                    [this] { showNavigationRow(trafficRow); });
    view->addAction(tr("Alarm &journal"), QKeySequence(Qt::CTRL | Qt::Key_J), this,
                    [this] { showNavigationRow(journalRow); });
    view->addAction(tr("&Write audit log"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A), this,
                    [this] { showNavigationRow(auditRow); });
    view->addSeparator();
    // The first nine devices in the list, by their place in it.
    QMenu *devicePages = view->addMenu(tr("&Device pages"));
    for (int n = 1; n <= 9; ++n) {
        QAction *action = devicePages->addAction(tr("Device %1 in the list").arg(n),
                                                 QKeySequence(Qt::CTRL | Qt::Key(Qt::Key_0 + n)), this,
                                                 [this, n] { showNavigationRow(m_navigation->deviceRow(n)); });
        action->setObjectName(QStringLiteral("showDevice%1").arg(n));
    }
    view->addAction(tr("&Next page"), QKeySequence(Qt::CTRL | Qt::Key_PageDown), this, [this] {
        showNavigationRow((m_navigation->currentRow() + 1) % m_navigation->count());
    });
    view->addAction(tr("&Previous page"), QKeySequence(Qt::CTRL | Qt::Key_PageUp), this, [this] {
        showNavigationRow((m_navigation->currentRow() + m_navigation->count() - 1) % m_navigation->count());
    });
    // The tabs of a device page, wherever the focus is in the window.
    view->addAction(tr("Ne&xt tab of the device page"), QKeySequence(Qt::CTRL | Qt::Key_Tab), this, [this] {
        if (auto *page = qobject_cast<DevicePage *>(m_pages->currentWidget()))
            page->tabs()->setCurrentIndex((page->tabs()->currentIndex() + 1) % page->tabs()->count());
    });
    QAction *previousTab = view->addAction(tr("Previous t&ab of the device page"), this, [this] {
        if (auto *page = qobject_cast<DevicePage *>(m_pages->currentWidget()))
            page->tabs()->setCurrentIndex((page->tabs()->currentIndex() + page->tabs()->count() - 1)
                                          % page->tabs()->count());
    });
    // X11 reports Shift+Tab as Backtab; the menu shows the first.
    previousTab->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Tab),
                               QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Backtab)});
    view->addAction(tr("Go to the page &list"), QKeySequence(Qt::Key_F6), this, [this] { m_navigation->setFocus(); });
    view->addSeparator();
    QMenu *themes = view->addMenu(tr("T&heme"));
    auto *group = new QActionGroup(themes);
    for (Theme::Kind kind : Theme::kinds()) {
        QAction *action = themes->addAction(Theme::title(kind));
        action->setObjectName(QStringLiteral("theme_") + Theme::name(kind));
        action->setCheckable(true);
        action->setChecked(kind == Theme::current());
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, kind] { setTheme(int(kind)); });
    }
    // The overview turns compact by itself when it would need scrolling; this keeps it so.
    QAction *compact = view->addAction(tr("&Compact overview"));
    compact->setObjectName(QStringLiteral("compactOverview"));
    compact->setCheckable(true);
    compact->setChecked(settings().value(QStringLiteral("compactOverview"), false).toBool());
    m_overview->setAlwaysCompact(compact->isChecked());
    connect(compact, &QAction::toggled, this, [this](bool on) {
        m_overview->setAlwaysCompact(on);
        settings().setValue(QStringLiteral("compactOverview"), on);
    });
}

void MainWindow::setTheme(int kind)
{
    Theme::apply(Theme::Kind(kind));
    settings().setValue(QStringLiteral("theme"), Theme::name(Theme::Kind(kind)));
    if (auto *action = findChild<QAction *>(QStringLiteral("theme_") + Theme::name(Theme::Kind(kind))))
        action->setChecked(true);
    if (auto *mode = findChild<QLabel *>(QStringLiteral("readOnlyIndicator")))
        mode->setStyleSheet(Theme::bannerStyle(Theme::Role::InfoBanner, Theme::Role::InfoBannerText)
                            + QStringLiteral("; padding: 0 6px; font-weight: bold"));
    m_logFailure->setStyleSheet(Theme::bannerStyle(Theme::Role::ErrorBanner, Theme::Role::ErrorBannerText)
                                + QStringLiteral("; padding: 0 6px"));
    for (const DeviceEntry &d : std::as_const(m_devices)) {
        d.tile->restyle();
        if (d.page)
            d.page->restyle(d.line->bus()->condition(d.id));
    }
    for (LineHeader *header : std::as_const(m_headers))
        header->refresh();
    // Texts coloured by meaning (write states, hints) and the state icons of the list.
    Theme::restyleWidgets();
    for (const DeviceEntry &d : std::as_const(m_devices)) {
        if (QListWidgetItem *item = m_navigation->item(m_navigation->rowOf(d.id)))
            item->setData(Qt::UserRole, 0);   // drawn again in the theme's colours
        updateNavigationItem(d.id);
    }
    for (StationLine *line : std::as_const(m_lines))
        m_navigation->updateLine(line);
}

void MainWindow::showNavigationRow(int row)
{
    if (row < 0 || row >= m_navigation->count())
        return;
    m_navigation->setCurrentRow(row);
    // The keyboard goes on in the page now shown, at its first field (the overview: its
    // first tile).
    QWidget *page = m_pages->currentWidget();
    if (!page)
        return;
    for (QWidget *w = page->nextInFocusChain(); w && w != page; w = w->nextInFocusChain()) {
        if (page->isAncestorOf(w) && w->isVisible() && w->isEnabled() && (w->focusPolicy() & Qt::TabFocus)) {
            w->setFocus(Qt::ShortcutFocusReason);
            return;
        }
    }
    page->setFocus(Qt::ShortcutFocusReason);
}

void MainWindow::requestConnect()
{
    StationLine *line = m_currentLine;
    if (!line || line->state() != LineState::Disconnected)
        return;
    if (!connectLine())
        QMessageBox::warning(this, tr("Connect"), line->lastError());
}

void MainWindow::addDeviceInteractively()
{
    AddDeviceDialog dialog(m_registry, this);
    QStringList names;
    for (const StationLine *line : std::as_const(m_lines))
        names << line->name();
    dialog.setLines(names, int(m_lines.indexOf(m_currentLine)));
    if (dialog.exec() != QDialog::Accepted || !dialog.family())
        return;
    StationLine *line = m_lines.value(dialog.line(), m_currentLine);
    // One device per address on a line: a second one would read the first one's registers.
    if (const int taken = indexAt(line, dialog.address()); taken >= 0) {
        const Bus *bus = line->bus();
        QMessageBox::information(this, tr("Add device"),
                                 tr("Address %1 on line %2 is taken by %3: a line has one device per address.")
                                         .arg(dialog.address())
                                         .arg(line->name(),
                                              DeviceTitle::brief(*bus->deviceMap(m_devices[taken].id),
                                                                 bus->deviceAddress(m_devices[taken].id))));
        return;
    }
    if (!addDevice(line, dialog.family(), dialog.address()))
        return;
    const int index = indexOf(line, dialog.family()->family, dialog.address());
    showDevice(ensurePage(index));
}

int MainWindow::currentDeviceIndex() const
{
    return indexOf(m_navigation->deviceAt(m_navigation->currentRow()));
}

void MainWindow::startDemo()
{
    m_demo = std::make_unique<DemoLine>(m_registry);
    StationLine *line = addLine(QStringLiteral("line1"), BusSettings{});
    connect(m_demo.get(), &DemoLine::failed, this, [this](const QString &reason) {
        m_lineStatus->setFullText(tr("Demo line failed: %1").arg(reason));
    });
    connect(m_demo.get(), &DemoLine::ready, this, [this, line](const QString &port) {
        const LineFormat f = m_demo->format();
        BusSettings s = line->settings();
        s.portName = port;
        s.format = f;
        line->setSettings(s);
        showLineInBar();
        if (!connectLine(line)) {
            m_lineStatus->setFullText(line->lastError());
            return;
        }
        for (const auto &[family, address] : m_demo->devices())
            addDevice(line, m_registry.family(family), address);
        emit demoReady();
    });
    m_lineStatus->setFullText(tr("Starting the simulated demo line..."));
    m_demo->start();
}

StationLine *MainWindow::line(const QString &name) const
{
    for (StationLine *line : m_lines) {
        if (line->name() == name)
            return line;
    }
    return nullptr;
}

LineHeader *MainWindow::lineHeader(const QString &name) const
{
    return m_headers.value(line(name));
}

StationLine *MainWindow::addLine(const QString &name, const BusSettings &settings, QString *error)
{
    QStringList taken;
    for (const StationLine *line : std::as_const(m_lines))
        taken << line->name();
    if (const QString problem = LineDialog::nameProblem(name, taken); !problem.isEmpty()) {
        if (error)
            *error = problem;
        return nullptr;
    }
    auto *line = new StationLine(name, settings, this);
    Bus *bus = line->bus();
    bus->setReadOnly(m_readOnly);
    if (m_options.identify)
        bus->setIdentityCheck(m_registry.families());
    line->attachLogs(m_journalLog, m_auditLog);
    connect(line, &StationLine::stateChanged, this, [this, line] { onLineStateChanged(line); });
    connect(line, &StationLine::changed, this, [this, line] {
        m_navigation->updateLine(line);
        for (const DeviceEntry &d : std::as_const(m_devices)) {
            if (d.line == line && d.page)
                d.page->setDeviceTitle(DeviceTitle::full(*line->bus()->deviceMap(d.id), line->bus()->deviceAddress(d.id),
                                                         line->name()));
        }
        if (line == m_currentLine && !m_fillingBar)
            showLineInBar();
        updateLineGrouping();
    });
    connect(bus, &Bus::lineError, this, [this, line](const QString &message) {
        m_lastError = m_lines.size() > 1 ? QStringLiteral("%1: %2").arg(line->name(), message) : message;
    });
    connect(bus, &Bus::traffic, this, [this, line](const TrafficRecord &record) {
        if (record.error.isEmpty())
            return;
        m_lastError = tr("address %1: %2").arg(record.slave).arg(record.error);
        if (m_lines.size() > 1)
            m_lastError = QStringLiteral("%1: %2").arg(line->name(), m_lastError);
    });
    connect(bus, &Bus::conditionChanged, this, [this](DeviceId id, const DeviceCondition &condition) {
        if (const int index = indexOf(id); index >= 0) {
            m_devices[index].tile->setCondition(condition);
            if (m_devices[index].page)
                m_devices[index].page->setCondition(condition);
        }
        updateNavigationItem(id);
    });
    m_lines << line;
    auto *header = new LineHeader(line);
    connect(header, &LineHeader::activated, this, &MainWindow::setCurrentLine);
    m_headers.insert(line, header);
    m_overview->addGroup(header);
    m_traffic->addLine(line);
    if (!m_currentLine)
        m_currentLine = line;
    updateLineGrouping();
    rebuildNavigation();
    showLineInBar();
    return line;
}

bool MainWindow::removeLine(StationLine *line)
{
    if (!m_lines.contains(line) || m_lines.size() < 2)
        return false;
    line->close();
    for (qsizetype i = m_devices.size() - 1; i >= 0; --i) {
        if (m_devices[i].line != line)
            continue;
        const DeviceEntry d = m_devices.takeAt(i);
        line->bus()->removeDevice(d.id);
        m_overview->removeTile(d.tile);
        if (d.page) {
            m_pages->removeWidget(d.page);
            d.page->deleteLater();
        }
        d.values->deleteLater();
        d.alarms->deleteLater();
        if (d.logger)
            d.logger->deleteLater();
    }
    m_traffic->removeLine(line);
    m_overview->removeGroup(m_headers.take(line));
    m_lines.removeAll(line);
    m_requestsAtLastStatus.remove(line);
    if (m_currentLine == line)
        m_currentLine = m_lines.first();
    line->disconnect(this);
    line->deleteLater();
    updateLineGrouping();
    rebuildNavigation();
    showLineInBar();
    updateStatus();
    return true;
}

void MainWindow::setCurrentLine(StationLine *line)
{
    if (!line || !m_lines.contains(line) || line == m_currentLine)
        return;
    m_currentLine = line;
    showLineInBar();
}

void MainWindow::showLineInBar()
{
    if (!m_currentLine)
        return;
    QStringList names;
    for (const StationLine *line : std::as_const(m_lines))
        names << line->name();
    m_fillingBar = true;
    m_connectionBar->setLines(names, int(m_lines.indexOf(m_currentLine)));
    const BusSettings &s = m_currentLine->settings();
    m_connectionBar->setSettings(s.portName, s.format.baudRate, s.format.formatName());
    m_fillingBar = false;
    // The bar names a listed adapter by its stable by-id name: that is what is kept.
    if (m_currentLine->state() == LineState::Disconnected)
        takeSettingsFromBar();
    onLineStateChanged(m_currentLine);
}

void MainWindow::takeSettingsFromBar()
{
    if (m_fillingBar || !m_currentLine || m_currentLine->state() != LineState::Disconnected)
        return;
    BusSettings s = m_currentLine->settings();
    s.portName = m_connectionBar->port();
    if (const auto format = LineFormat::parse(m_connectionBar->baud(), m_connectionBar->format()))
        s.format = *format;
    if (s.portName == m_currentLine->settings().portName && s.format.baudRate == m_currentLine->settings().format.baudRate
        && s.format.formatName() == m_currentLine->settings().format.formatName())
        return;
    m_fillingBar = true;
    m_currentLine->setSettings(s);
    m_fillingBar = false;
}

bool MainWindow::connectLine()
{
    if (!m_currentLine)
        return false;
    takeSettingsFromBar();
    const std::optional<LineFormat> format = LineFormat::parse(m_connectionBar->baud(), m_connectionBar->format());
    if (!format || m_connectionBar->port().isEmpty()) {
        QMessageBox::warning(this, tr("Connect"), tr("Choose or type the line's address first: a serial port, tcp://HOST[:PORT] or rtu+tcp://HOST:PORT."));
        return false;
    }
    return connectLine(m_currentLine);
}

bool MainWindow::connectLine(StationLine *line)
{
    if (!line || line->settings().portName.isEmpty())
        return false;
    return line->open();
}

void MainWindow::disconnectLine()
{
    if (m_currentLine)
        m_currentLine->close();
}

QStringList MainWindow::connectAllLines()
{
    QStringList failed;
    for (StationLine *line : std::as_const(m_lines)) {
        if (line->state() == LineState::Disconnected && !connectLine(line))
            failed << QStringLiteral("%1: %2").arg(line->name(),
                                                   line->lastError().isEmpty() ? tr("no address") : line->lastError());
    }
    return failed;
}

void MainWindow::connectAllInteractively()
{
    const QStringList failed = connectAllLines();
    if (!failed.isEmpty())
        QMessageBox::warning(this, tr("Connect"), tr("Not connected:\n%1").arg(failed.join(QLatin1Char('\n'))));
}

void MainWindow::disconnectAllLines()
{
    for (StationLine *line : std::as_const(m_lines))
        line->close();
}

void MainWindow::addLineInteractively()
{
    QStringList taken;
    for (const StationLine *line : std::as_const(m_lines))
        taken << line->name();
    QString name;
    for (int n = 1; name.isEmpty() || taken.contains(name); ++n)
        name = QStringLiteral("line%1").arg(n);
    BusSettings settings;
    if (m_currentLine)
        settings.format = m_currentLine->settings().format;
    LineDialog dialog(name, settings, taken, this);
    dialog.setWindowTitle(tr("New line"));
    if (dialog.exec() != QDialog::Accepted)
        return;
    if (StationLine *line = addLine(dialog.name(), dialog.settings()))
        setCurrentLine(line);
}

void MainWindow::editCurrentLine()
{
    StationLine *line = m_currentLine;
    if (!line)
        return;
    if (line->state() != LineState::Disconnected) {
        QMessageBox::information(this, tr("Edit line"), tr("Disconnect line %1 first.").arg(line->name()));
        return;
    }
    QStringList taken;
    for (const StationLine *other : std::as_const(m_lines)) {
        if (other != line)
            taken << other->name();
    }
    LineDialog dialog(line->name(), line->settings(), taken, this);
    dialog.setWindowTitle(tr("Edit line %1").arg(line->name()));
    if (dialog.exec() != QDialog::Accepted)
        return;
    line->setSettings(dialog.settings());
    line->setName(dialog.name());
    showLineInBar();
    rebuildNavigation();
}

void MainWindow::removeCurrentLineInteractively()
{
    StationLine *line = m_currentLine;
    if (!line)
        return;
    if (m_lines.size() < 2) {
        QMessageBox::information(this, tr("Remove line"),
                                 tr("%1 is the only line; change its address with Edit instead.").arg(line->name()));
        return;
    }
    QStringList devices;
    for (const DeviceEntry &d : std::as_const(m_devices)) {
        if (d.line == line)
            devices << DeviceTitle::brief(*line->bus()->deviceMap(d.id), line->bus()->deviceAddress(d.id));
    }
    QString question = tr("Remove line %1 from the station?").arg(line->name());
    if (!devices.isEmpty())
        question += QLatin1Char('\n')
                + tr("Devices removed with it: %1 (%2).").arg(devices.size()).arg(devices.join(QStringLiteral(", ")));
    if (QMessageBox::question(this, tr("Remove line"), question) == QMessageBox::Yes)
        removeLine(line);
}

void MainWindow::updateLineGrouping()
{
    const bool several = m_lines.size() > 1;
    m_overview->setHeadersShown(several);
    for (StationLine *line : std::as_const(m_lines))
        line->setNamedInLogs(several);
}

void MainWindow::rebuildNavigation()
{
    QList<NavigationList::Group> groups;
    for (StationLine *line : std::as_const(m_lines)) {
        NavigationList::Group g{line, {}};
        for (const DeviceEntry &d : std::as_const(m_devices)) {
            if (d.line == line) {
                const auto map = line->bus()->deviceMap(d.id);
                g.devices << NavigationList::Device{d.id, DeviceTitle::brief(*map, line->bus()->deviceAddress(d.id))};
            }
        }
        groups << g;
    }
    m_navigation->setGroups(groups, m_lines.size() > 1);
    // A line's row says its name and state ("cabinet-a (connected)"): the list is as wide
    // as the widest, within reason; longer ones end in "..." with the whole in the tooltip.
    int width = m_listMinimumWidth;
    if (m_lines.size() > 1) {
        QFont bold = m_navigation->font();
        bold.setBold(true);
        const QFontMetrics metrics(bold);
        for (int row = m_navigation->pageCount(); row < m_navigation->count(); ++row) {
            if (m_navigation->isLineRow(row))
                width = std::max(width, metrics.horizontalAdvance(m_navigation->item(row)->text() + QStringLiteral("dis")) + 16 + 12
                                                + 2 * m_navigation->frameWidth() + 8);
        }
        width = std::min(width, m_listMinimumWidth * 3 / 2);
    }
    if (QWidget *side = m_navigation->parentWidget(); side && side->minimumWidth() != width) {
        side->setMinimumWidth(width);
        if (auto *split = findChild<QSplitter *>(QStringLiteral("mainSplitter")); split && split->sizes().value(0) < width)
            split->setSizes({width, split->width() - width});
    }
    for (const DeviceEntry &d : std::as_const(m_devices))
        updateNavigationItem(d.id);
}

QString MainWindow::linesSummary() const
{
    int connected = 0;
    int lost = 0;
    int disconnected = 0;
    for (const StationLine *line : m_lines) {
        switch (line->state()) {
        case LineState::Connected:
            ++connected;
            break;
        case LineState::Lost:
            ++lost;
            break;
        case LineState::Disconnected:
            ++disconnected;
            break;
        }
    }
    QStringList parts;
    if (connected)
        parts << tr("%1 connected").arg(connected);
    if (lost)
        parts << tr("%1 lost").arg(lost);
    if (disconnected)
        parts << tr("%1 disconnected").arg(disconnected);
    return tr("Lines: %1").arg(parts.join(QStringLiteral(", ")));
}

void MainWindow::onLineStateChanged(StationLine *line)
{
    m_navigation->updateLine(line);
    if (line == m_currentLine) {
        const QString address = line->settings().portName;
        switch (line->state()) {
        case LineState::Connected:
            m_connectionBar->setConnected(true, tr("Connected to %1").arg(address));
            break;
        case LineState::Lost:
            m_connectionBar->setConnected(true, tr("Line lost, waiting for the port to come back..."));
            break;
        case LineState::Disconnected:
            m_connectionBar->setConnected(false, tr("Disconnected"));
            break;
        }
        if (m_connectAction) {
            m_connectAction->setEnabled(line->state() == LineState::Disconnected);
            m_disconnectAction->setEnabled(line->state() != LineState::Disconnected);
        }
    }
    updateStatus();
}

void MainWindow::updateStatus()
{
    int requests = 0;
    int errors = 0;
    for (StationLine *line : std::as_const(m_lines)) {
        int lineRequests = 0;
        for (DeviceId id : line->bus()->devices()) {
            const DeviceStatistics *s = line->bus()->statistics(id);
            lineRequests += s->requests;
            errors += s->timeouts + s->crcErrors + s->mismatches;
            for (int n : s->exceptions)
                errors += n;
        }
        requests += lineRequests - m_requestsAtLastStatus.value(line);
        m_requestsAtLastStatus.insert(line, lineRequests);
    }
    const int perSecond = requests;
    if (m_lines.size() > 1)
        m_lineStatus->setFullText(linesSummary());
    else if (StationLine *line = m_lines.value(0))
        m_lineStatus->setFullText(line->state() == LineState::Connected
                                          ? tr("Line: %1").arg(line->settings().portName)
                                          : m_connectionBar->findChild<QLabel *>(QStringLiteral("lineState"))->text());
    m_loadStatus->setText(tr("%1 requests/s").arg(perSecond));
    // Repeated errors are throttled: the newest one, at most once every 5 s.
    const qint64 now = m_lines.isEmpty() ? 0 : m_lines.first()->bus()->clockMs();
    // A lost line sends nothing, so nothing fails: while one is lost, that is what the
    // status says between errors, never "no errors".
    QStringList lost;
    for (StationLine *line : std::as_const(m_lines)) {
        if (line->state() == LineState::Lost)
            lost << line->name();
    }
    const bool due = !m_lastError.isEmpty() && (m_lastErrorShownMs < 0 || now - m_lastErrorShownMs >= 5000);
    if (due) {
        m_lastErrorShownMs = now;
        m_shownError = std::exchange(m_lastError, QString());
    }
    if (!lost.isEmpty()) {
        QString text = m_lines.size() > 1 ? tr("no values read: %n line(s) lost (%1)", nullptr, int(lost.size()))
                                                    .arg(lost.join(QStringLiteral(", ")))
                                          : tr("no values read: the line is lost");
        if (!m_shownError.isEmpty())
            text += QStringLiteral("; ") + tr("last error: %1").arg(m_shownError);
        m_errorStatus->setFullText(text);
    } else if (due) {
        m_errorStatus->setFullText(tr("%n error(s); last: %1", nullptr, errors).arg(m_shownError));
    } else if (errors == 0) {
        m_errorStatus->setFullText(tr("no errors"));
    }
}

bool MainWindow::addDevice(std::shared_ptr<const RegisterMap> map, quint8 address)
{
    return addDevice(m_currentLine, std::move(map), address);
}

bool MainWindow::addDevice(StationLine *line, std::shared_ptr<const RegisterMap> map, quint8 address)
{
    if (!map || !line || indexAt(line, address) >= 0)
        return false;
    Bus *bus = line->bus();
    const DeviceId id = bus->addDevice(map, address);
    if (!m_options.identify)
        m_auditLog->append(QJsonObject{{"device", line->deviceName(id)},
                                       {"entry", QString()},
                                       {"result", QStringLiteral("identity_not_checked")},
                                       {"message", tr("the family is not checked against the device (--no-identify)")}});
    auto *values = new LiveValuesModel(bus, id, this);
    auto *alarms = new AlarmBitsModel(bus, id, this);
    auto *tile = new DeviceTile(id, *map, address, values, alarms, m_overview);
    tile->setCondition(bus->condition(id));
    m_overview->addTile(tile, m_headers.value(line));
    m_devices << DeviceEntry{id, line, values, alarms, tile, nullptr, nullptr};
    auto update = [this, id] { updateNavigationItem(id); };
    connect(alarms, &AlarmBitsModel::activeAlarmsChanged, this, update);
    connect(alarms, &AlarmBitsModel::alarmsKnownChanged, this, update);
    connect(alarms, &QAbstractItemModel::dataChanged, this, update);
    rebuildNavigation();
    if (LineHeader *header = m_headers.value(line))
        header->refresh();
    connect(tile, &DeviceTile::activated, this, [this](DeviceId device) {
        if (const int row = m_navigation->rowOf(device); row >= 0)
            m_navigation->setCurrentRow(row);
    });
    return true;
}

void MainWindow::updateNavigationItem(DeviceId id)
{
    const int index = indexOf(id);
    QListWidgetItem *item = index >= 0 ? m_navigation->item(m_navigation->rowOf(id)) : nullptr;
    if (!item)
        return;
    const Bus *bus = m_devices[index].line->bus();
    const DeviceCondition condition = bus->condition(id);
    const AlarmBitsModel &alarms = *m_devices[index].alarms;
    const auto kind = DeviceStateIcon::kindOf(condition, alarms.activeAlarms(), alarms.alarmsKnown());
    // Repainting an icon for every poll block would cost; only a change is drawn.
    if (item->data(Qt::UserRole).toInt() != int(kind) + 1) {
        item->setData(Qt::UserRole, int(kind) + 1);
        item->setIcon(DeviceStateIcon::icon(kind));
    }
    const std::shared_ptr<const RegisterMap> map = bus->deviceMap(id);
    QString title = item->text().trimmed();
    if (m_lines.size() > 1)
        title = tr("%1 on line %2").arg(title, m_devices[index].line->name());
    const QString tip = QStringLiteral("%1\n%2\n%3\n%4")
                                .arg(title, map->displayName(), DeviceTile::conditionText(condition),
                                     DeviceTile::alarmsText(condition, alarms));
    if (item->toolTip() != tip)
        item->setToolTip(tip);
}

void MainWindow::showOverview()
{
    m_navigation->setCurrentRow(overviewRow);
}

int MainWindow::indexOf(DeviceId id) const
{
    for (int i = 0; i < m_devices.size(); ++i) {
        if (m_devices[i].id == id)
            return i;
    }
    return -1;
}

int MainWindow::indexAt(const StationLine *line, quint8 address) const
{
    for (int i = 0; i < m_devices.size(); ++i) {
        if (m_devices[i].line == line && line->bus()->deviceAddress(m_devices[i].id) == address)
            return i;
    }
    return -1;
}

int MainWindow::indexOf(const StationLine *line, const QString &family, quint8 address) const
{
    for (int i = 0; i < m_devices.size(); ++i) {
        const DeviceEntry &d = m_devices[i];
        if ((!line || d.line == line) && d.line->bus()->deviceMap(d.id)->family == family
            && d.line->bus()->deviceAddress(d.id) == address)
            return i;
    }
    return -1;
}

QString MainWindow::deviceName(const DeviceEntry &d) const
{
    return d.line->deviceName(d.id);
}

void MainWindow::showDevice(const QString &family, quint8 address)
{
    showDevice(devicePage(family, address));
}

DevicePage *MainWindow::ensurePage(int index) const
{
    if (index < 0 || index >= m_devices.size())
        return nullptr;
    DeviceEntry &d = m_devices[index];
    if (!d.page) {
        d.page = new DevicePage(d.line->bus(), d.id, d.values, d.alarms, m_pages);
        d.page->setDeviceTitle(DeviceTitle::full(*d.line->bus()->deviceMap(d.id), d.line->bus()->deviceAddress(d.id),
                                                 d.line->name()));
        d.page->setReadOnly(m_readOnly);
        d.page->setCondition(d.line->bus()->condition(d.id));
        m_pages->addWidget(d.page);
    }
    return d.page;
}

void MainWindow::onNavigation(int row)
{
    if (row == overviewRow) {
        m_pages->setCurrentWidget(m_overview);
    } else if (row == trafficRow) {
        m_pages->setCurrentWidget(m_traffic);
    } else if (row == journalRow) {
        m_pages->setCurrentWidget(m_journalView);
    } else if (row == auditRow) {
        m_pages->setCurrentWidget(m_auditView);
    } else if (m_navigation->isLineRow(row)) {
        // A line's row: the overview at its group, and the line is the current one.
        StationLine *line = m_navigation->lineAt(row);
        setCurrentLine(line);
        m_pages->setCurrentWidget(m_overview);
        m_overview->showGroup(m_headers.value(line));
    } else if (const int index = indexOf(m_navigation->deviceAt(row)); index >= 0) {
        setCurrentLine(m_devices[index].line);
        m_pages->setCurrentWidget(ensurePage(index));
    }
}

void MainWindow::showDevice(DevicePage *page)
{
    for (const DeviceEntry &d : std::as_const(m_devices)) {
        if (page && d.page == page)
            m_navigation->setCurrentRow(m_navigation->rowOf(d.id));
    }
}

DevicePage *MainWindow::devicePage(const QString &family, quint8 address) const
{
    return ensurePage(indexOf(nullptr, family, address));
}

DeviceTile *MainWindow::deviceTile(const QString &family, quint8 address) const
{
    const int index = indexOf(nullptr, family, address);
    return index >= 0 ? m_devices[index].tile : nullptr;
}

DevicePage *MainWindow::devicePage(const QString &lineName, const QString &family, quint8 address) const
{
    const StationLine *l = line(lineName);
    return l ? ensurePage(indexOf(l, family, address)) : nullptr;
}

DeviceTile *MainWindow::deviceTile(const QString &lineName, const QString &family, quint8 address) const
{
    const StationLine *l = line(lineName);
    const int index = l ? indexOf(l, family, address) : -1;
    return index >= 0 ? m_devices[index].tile : nullptr;
}

void MainWindow::removeCurrentDeviceInteractively()
{
    const int index = currentDeviceIndex();
    if (index < 0)
        return;
    // A shortcut pressed by mistake must not end the monitoring of a device: asked first.
    const DeviceEntry &d = m_devices[index];
    QMessageBox box(QMessageBox::Question, tr("Remove device"),
                    tr("Remove %1 from this window?").arg(DeviceTitle::full(*d.line->bus()->deviceMap(d.id),
                                                                            d.line->bus()->deviceAddress(d.id),
                                                                            d.line->name())),
                    QMessageBox::Yes | QMessageBox::No, this);
    box.setInformativeText(tr("It is no longer polled; its page, trend and data logging close. Nothing is written to "
                              "the device."));
    box.setDefaultButton(QMessageBox::No);
    if (box.exec() == QMessageBox::Yes)
        removeCurrentDevice();
}

void MainWindow::removeCurrentDevice()
{
    const int index = currentDeviceIndex();
    if (index < 0)
        return;
    m_navigation->setCurrentRow(overviewRow);
    const DeviceEntry d = m_devices.takeAt(index);
    d.line->bus()->removeDevice(d.id);
    m_overview->removeTile(d.tile);
    if (d.page) {
        m_pages->removeWidget(d.page);
        d.page->deleteLater();
    }
    d.values->deleteLater();
    d.alarms->deleteLater();
    if (d.logger)
        d.logger->deleteLater();
    rebuildNavigation();
    if (LineHeader *header = m_headers.value(d.line))
        header->refresh();
}

void MainWindow::openScanDialog()
{
    StationLine *line = m_currentLine;
    if (!line || line->state() != LineState::Connected) {
        QMessageBox::information(this, tr("Scan"),
                                 m_lines.size() > 1 ? tr("Connect line %1 first, or choose a connected line.")
                                                              .arg(line ? line->name() : QString())
                                                    : tr("Connect to a line first."));
        return;
    }
    auto *dialog = new ScanDialog(line->bus(), m_registry, this);
    dialog->setObjectName(QStringLiteral("scanDialog"));
    if (m_lines.size() > 1)
        dialog->setWindowTitle(tr("Scan line %1").arg(line->name()));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, line = QPointer<StationLine>(line)] {
        if (!line)
            return;
        for (const auto &[map, address] : dialog->chosen())
            addDevice(line, map, address);
    });
    dialog->show();
}

void MainWindow::openFindDialog()
{
    StationLine *line = m_currentLine;
    if (!line)
        return;
    takeSettingsFromBar();
    if (line->settings().portName.isEmpty()) {
        QMessageBox::information(this, tr("Find devices"), tr("Choose the line's serial port first."));
        return;
    }
    if (line->bus()->lineKind() != LineAddress::Kind::Serial) {
        QMessageBox::information(this, tr("Find devices"),
                                 tr("Line %1 is reached through a gateway or a device server, whose serial settings "
                                    "are its own: set them there, then scan the line.")
                                         .arg(line->name()));
        return;
    }
    if (line->state() != LineState::Disconnected) {
        const auto answer = QMessageBox::question(
                this, tr("Find devices"),
                tr("The search needs the port of line %1 for itself and tries other settings on it: disconnect the "
                   "line now? Its devices are not polled while the search runs.")
                        .arg(line->name()));
        if (answer != QMessageBox::Yes)
            return;
        line->close();
    }
    auto *dialog = new FindDialog(line->settings(), m_registry, this);
    dialog->setObjectName(QStringLiteral("findDialog"));
    if (m_lines.size() > 1)
        dialog->setWindowTitle(tr("Find devices on line %1").arg(line->name()));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, line = QPointer<StationLine>(line)] {
        const std::optional<LineFormat> format = dialog->chosenFormat();
        if (!line || !format || line->state() != LineState::Disconnected)
            return;
        BusSettings s = line->settings();
        s.format = *format;
        line->setSettings(s);
        if (line == m_currentLine)
            showLineInBar();
        for (const auto &[map, address] : dialog->chosen())
            addDevice(line, map, address);
        connectLine(line);
    });
    dialog->show();
}

namespace {

// The settings key of a device's report tag: "ipc300@1", "line2/ipc300@1" with several lines.
QString tagKey(const QString &device)
{
    return QStringLiteral("report/tags/") + device;
}

} // namespace

int MainWindow::reportDevice(const QString &family, quint8 address) const
{
    // The device of the current line first: the same address may be used on two lines.
    const int index = indexOf(m_currentLine, family, address);
    return index >= 0 ? index : indexOf(nullptr, family, address);
}

ReportTitle MainWindow::reportTitle(const QString &family, quint8 address)
{
    QSettings &s = settings();
    const int index = reportDevice(family, address);
    const QString device = index >= 0 ? deviceName(m_devices[index]) : QStringLiteral("%1@%2").arg(family).arg(address);
    return {s.value(QStringLiteral("report/site")).toString(), s.value(QStringLiteral("report/cabinet")).toString(),
            s.value(tagKey(device)).toString(), s.value(QStringLiteral("report/engineer")).toString()};
}

void MainWindow::rememberReportTitle(const QString &family, quint8 address, const ReportTitle &title)
{
    QSettings &s = settings();
    const int index = reportDevice(family, address);
    const QString device = index >= 0 ? deviceName(m_devices[index]) : QStringLiteral("%1@%2").arg(family).arg(address);
    s.setValue(QStringLiteral("report/site"), title.site);
    s.setValue(QStringLiteral("report/cabinet"), title.cabinet);
    s.setValue(tagKey(device), title.tag);
    s.setValue(QStringLiteral("report/engineer"), title.engineer);
}

bool MainWindow::writeReport(const QString &family, quint8 address, const QString &path, const ReportTitle &title,
                             QString *error)
{
    const int index = reportDevice(family, address);
    if (index < 0) {
        if (error)
            *error = tr("no device %1@%2").arg(family).arg(address);
        return false;
    }
    const DeviceEntry &d = m_devices[index];
    const Bus *bus = d.line->bus();
    CommissioningReport report(*bus->deviceMap(d.id), address,
                               [bus, id = d.id](const QString &entry) { return bus->entryState(id, entry); });
    // As the audit log names it: with its line where there are several.
    const QString device = deviceName(d);
    QList<QJsonObject> writes;
    for (const QJsonObject &r : std::as_const(m_sessionWrites)) {
        if (r.value("device").toString() == device)
            writes << r;
    }
    report.setWrites(writes, m_sessionStart);
    report.setTitle(title);
    report.setLine(d.line->settings());
    report.setSoftware(QStringLiteral("%1 %2").arg(tr("JUMO HMI"), QStringLiteral(JUMO_VERSION)));
    const ReportWriter::Pages pages{tr("Commissioning report of %1").arg(device), report.pageHeader(),
                                    report.pageFooter()};
    return ReportWriter::write(report.html(), path, pages, error);
}

DataLogger *MainWindow::dataLogger(DeviceId id)
{
    const int index = indexOf(id);
    if (index < 0)
        return nullptr;
    // One logger per device, kept while the window lives, so logging goes on when the
    // dialog is closed.
    DeviceEntry &d = m_devices[index];
    if (!d.logger) {
        d.logger = new DataLogger(d.line->bus(), this);
        connect(d.logger, &DataLogger::failed, this, [this, id](const QString &reason) {
            const int at = indexOf(id);
            const QString device = at >= 0 ? deviceName(m_devices[at]) : QString();
            showLogFailure(QStringLiteral("data ") + device, tr("Data logging of %1 stopped: %2").arg(device, reason));
            journalLogEvent(device, QStringLiteral("data_logging"), QStringLiteral("Data logging"),
                            QStringLiteral("stopped: %1").arg(reason));
        });
    }
    return d.logger;
}

void MainWindow::showLogFailure(const QString &source, const QString &message)
{
    m_logFailures.insert(source, message);
    const QStringList all = m_logFailures.values();
    m_logFailure->setFullText(all.join(QStringLiteral("; ")));
    m_logFailure->show();
}

void MainWindow::journalLogEvent(const QString &device, const QString &id, const QString &label, const QString &state)
{
    m_journalLog->append(QJsonObject{{"device", device},
                                     {"register", QString()},
                                     {"bit", QString()},
                                     {"id", id},
                                     {"label", label},
                                     {"kind", QStringLiteral("log")},
                                     {"state", state}});
}

void MainWindow::restoreSettings()
{
    QSettings &s = settings();
    restoreGeometry(s.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(s.value(QStringLiteral("window/state")).toByteArray());
    for (const StationSettings::Line &kept : StationSettings::load(s)) {
        StationLine *line = addLine(kept.name, kept.settings);
        if (!line)
            continue;   // a name edited by hand into something unfit, or twice
        for (const QString &text : kept.devices) {
            if (const std::optional<DeviceSpec> device = DeviceSpec::parse(text, m_registry, nullptr))
                addDevice(line, m_registry.family(device->family), device->address);
        }
    }
}

void MainWindow::saveSettings()
{
    // The demo's line is gone after the demo: it must not replace the user's own.
    if (m_options.demo)
        return;
    QSettings &s = settings();
    s.setValue(QStringLiteral("window/geometry"), saveGeometry());
    s.setValue(QStringLiteral("window/state"), saveState());
    // Lines from the command line are for this run: the kept ones stay as they were.
    if (!m_options.lines.isEmpty())
        return;
    takeSettingsFromBar();
    QList<StationSettings::Line> lines;
    for (const StationLine *line : std::as_const(m_lines)) {
        StationSettings::Line kept{line->name(), line->settings(), {}};
        for (const DeviceEntry &d : std::as_const(m_devices)) {
            if (d.line == line)
                kept.devices << line->bus()->deviceName(d.id);
        }
        lines << kept;
    }
    StationSettings::save(s, lines);
}

bool MainWindow::event(QEvent *event)
{
    // The override reaches the window when the focused field does not claim the keys
    // itself: QLineEdit (also in spin and combo boxes) leaves its DeleteEndOfWord and
    // DeleteStartOfWord to window shortcuts.
    if (event->type() == QEvent::ShortcutOverride) {
        auto *key = static_cast<QKeyEvent *>(event);
        if (key->matches(QKeySequence::DeleteEndOfWord) || key->matches(QKeySequence::DeleteStartOfWord)) {
            QWidget *focus = QApplication::focusWidget();
            const auto *line = qobject_cast<QLineEdit *>(focus);
            const auto *text = qobject_cast<QTextEdit *>(focus);
            const auto *plain = qobject_cast<QPlainTextEdit *>(focus);
            if ((line && !line->isReadOnly()) || (text && !text->isReadOnly()) || (plain && !plain->isReadOnly())) {
                event->accept();
                return true;
            }
        }
    }
    return QMainWindow::event(event);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    saveSettings();
    event->accept();
}

} // namespace jumo
