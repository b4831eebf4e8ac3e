#include "remotewindow.h"

#include "devicepage.h"
#include "devicestateicon.h"
#include "devicetile.h"
#include "eventlogview.h"
#include "lineheader.h"
#include "logs/alarmjournal.h"
#include "logs/eventlog.h"
#include "models/alarmbitsmodel.h"
#include "models/livevaluesmodel.h"
#include "mqtt/remotelines.h"
#include "mqtt/remotestation.h"
#include "overviewpage.h"
#include "protocol/familyregistry.h"

#include <QApplication>

#include <climits>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>

namespace jumo {

namespace {

constexpr int overviewRow = 0;
constexpr int journalRow = 1;
constexpr int deviceRole = Qt::UserRole + 1;   // the device id of a device's row

} // namespace

RemoteWindow::RemoteWindow(const FamilyRegistry &registry, const Options &options, QWidget *parent)
    : QMainWindow(parent), m_registry(registry), m_options(options),
      m_station(std::make_unique<RemoteStation>(registry)), m_navigation(new QListWidget(this)),
      m_pages(new QStackedWidget(this)), m_overview(new OverviewPage(this)),
      m_journalLog(new EventLog((options.logFolder.isEmpty() ? EventLog::defaultFolder() : options.logFolder)
                                        + QStringLiteral("/remote-alarm-journal.jsonl"),
                                this)),
      m_journalView(new EventLogView(m_journalLog, AlarmJournal::columns(),
                                     {tr("Time"), tr("Device"), tr("Register"), tr("Bit"), tr("Id"), tr("Signal"),
                                      tr("Kind"), tr("State")},
                                     this)),
      m_brokerStatus(new QLabel(this)), m_stationStatus(new QLabel(this)), m_forgeryBanner(new QLabel(this)),
      m_forgeryStatus(new QLabel(this)), m_reorder(new QTimer(this))
{
    setObjectName(QStringLiteral("remoteWindow"));
    setWindowTitle(tr("JUMO HMI remote view: %1 [read-only]").arg(options.broker.url()));
    m_station->setPrefix(options.prefix);
    m_station->setStation(options.station);
    m_lines = std::make_unique<RemoteLines>(m_station.get());

    m_navigation->setObjectName(QStringLiteral("navigation"));
    m_navigation->setIconSize(QSize(16, 16));
    // Names whole, a short state after them; what does not fit ends in "…" and is in the
    // tooltip: the list never scrolls sideways.
    m_navigation->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_navigation->setTextElideMode(Qt::ElideRight);
    m_navigation->addItem(tr("Overview"));
    m_navigation->addItem(tr("Alarm journal (this viewer)"));
    m_pages->addWidget(m_overview);
    m_pages->addWidget(m_journalView);
    m_journalView->setObjectName(QStringLiteral("alarmJournal"));
    auto *banner = new QLabel(tr("Remote view: values as the stations publish them to the broker. Nothing can be "
                                 "written from here."),
                              this);
    banner->setObjectName(QStringLiteral("remoteBanner"));
    banner->setWordWrap(true);
    banner->setMargin(4);
    // Shown for good once this viewer's own user could publish into a station's tree.
    m_forgeryBanner->setObjectName(QStringLiteral("forgeryBanner"));
    m_forgeryBanner->setWordWrap(true);
    m_forgeryBanner->setMargin(6);
    m_forgeryBanner->setAutoFillBackground(true);
    QPalette warning = m_forgeryBanner->palette();
    warning.setColor(QPalette::Window, QColor(0xff, 0xd5, 0x4f));
    warning.setColor(QPalette::WindowText, Qt::black);
    m_forgeryBanner->setPalette(warning);
    m_forgeryBanner->hide();
    auto *right = new QWidget(this);
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    rightLayout->addWidget(m_forgeryBanner);
    rightLayout->addWidget(banner);
    rightLayout->addWidget(m_pages, 1);
    auto *splitter = new QSplitter(this);
    splitter->addWidget(m_navigation);
    splitter->addWidget(right);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({220, 1000});
    setCentralWidget(splitter);
    connect(m_navigation, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row == overviewRow) {
            m_pages->setCurrentWidget(m_overview);
        } else if (row == journalRow) {
            m_pages->setCurrentWidget(m_journalView);
        } else if (QListWidgetItem *item = m_navigation->item(row)) {
            const QVariant id = item->data(deviceRole);
            if (id.isValid()) {
                if (DevicePage *page = ensurePage(id.toInt()))
                    m_pages->setCurrentWidget(page);
            } else {
                m_pages->setCurrentWidget(m_overview);
            }
        }
    });

    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
    QMenu *view = menuBar()->addMenu(tr("&View"));
    QAction *compact = view->addAction(tr("&Compact overview"));
    compact->setCheckable(true);
    connect(compact, &QAction::toggled, m_overview, &OverviewPage::setAlwaysCompact);

    statusBar()->addWidget(m_brokerStatus, 1);
    statusBar()->addPermanentWidget(m_forgeryStatus);
    statusBar()->addPermanentWidget(m_stationStatus);
    m_brokerStatus->setObjectName(QStringLiteral("brokerStatus"));
    m_stationStatus->setObjectName(QStringLiteral("stationStatus"));
    m_forgeryStatus->setObjectName(QStringLiteral("forgeryStatus"));
    m_forgeryStatus->hide();

    m_reorder->setSingleShot(true);
    m_reorder->setInterval(50);
    connect(m_reorder, &QTimer::timeout, this, &RemoteWindow::reorder);
    connect(m_lines.get(), &RemoteLines::lineAdded, this, &RemoteWindow::onLineAdded);
    connect(m_lines.get(), &RemoteLines::lineRemoving, this, &RemoteWindow::onLineRemoving);
    connect(m_lines.get(), &RemoteLines::deviceAdded, this, &RemoteWindow::onDeviceAdded);
    connect(m_lines.get(), &RemoteLines::deviceRemoving, this, &RemoteWindow::onDeviceRemoving);
    connect(m_lines.get(), &RemoteLines::orderChanged, m_reorder, qOverload<>(&QTimer::start));
    connect(m_station.get(), &RemoteStation::refused, this, [this](const QString &what, const QString &reason) {
        statusBar()->showMessage(tr("Not shown: %1 (%2)").arg(what.left(120), reason), 10000);
    });
    connect(m_station.get(), &RemoteStation::forgeryPossible, this, &RemoteWindow::showForgeryWarning);
    connect(m_station.get(), &RemoteStation::connectionChanged, this, [this](bool, const QString &reason) {
        m_brokerError = reason;
        updateStatus();
    });
    connect(m_station.get(), &RemoteStation::stationChanged, this, &RemoteWindow::updateStatus);
    m_navigation->setCurrentRow(overviewRow);
    updateStatus();
}

RemoteWindow::~RemoteWindow()
{
    // Pages and tiles hold models of lines that RemoteLines owns: they go first.
    m_station->stop();
    delete m_pages;
    m_pages = nullptr;
    m_overview = nullptr;
}

bool RemoteWindow::start(QString *error)
{
    return m_station->start(m_options.broker, error);
}

QString RemoteWindow::lineLabel(MirroredLine *line) const
{
    return m_station->stations().size() > 1 ? m_lines->stationOf(line) + QLatin1Char('/') + line->name()
                                            : line->name();
}

QString RemoteWindow::lineStateText(MirroredLine *line) const
{
    switch (line->state()) {
    case LineState::Connected:
        return tr("Connected");
    case LineState::Lost: {
        const QString reason = line->stateReason();
        if (reason.isEmpty())
            return tr("Line lost");
        // The station's own words may say it already ("line lost: Resource error.").
        if (reason.startsWith(tr("line lost"), Qt::CaseInsensitive))
            return reason.at(0).toUpper() + reason.mid(1);
        return tr("Line lost: %1").arg(reason);
    }
    case LineState::Disconnected:
        break;
    }
    return line->stateReason().isEmpty() ? tr("Disconnected") : tr("Disconnected: %1").arg(line->stateReason());
}

void RemoteWindow::onLineAdded(MirroredLine *line)
{
    Line entry;
    entry.header = new LineHeader(line->name(), m_overview);
    m_overview->addGroup(entry.header);
    m_overview->setHeadersShown(true);
    entry.item = new QListWidgetItem(m_navigation);
    QFont bold = entry.item->font();
    bold.setBold(true);
    entry.item->setFont(bold);
    entry.journal = new AlarmJournal(line, m_journalLog, this);
    entry.journal->setDevicePrefix(m_lines->stationOf(line) + QLatin1Char('/') + line->name() + QLatin1Char('/'));
    m_lineEntries.insert(line, entry);
    connect(line, &DeviceSource::stateChanged, this, [this, line] { updateLine(line); });
    connect(line, &DeviceSource::conditionChanged, this, [this](DeviceId id, const DeviceCondition &condition) {
        auto it = m_devices.find(id);
        if (it == m_devices.end())
            return;
        it->tile->setCondition(condition);
        if (it->page)
            it->page->setCondition(condition);
        updateDevice(id);
    });
    updateLine(line);
}

void RemoteWindow::updateLine(MirroredLine *line)
{
    const auto it = m_lineEntries.constFind(line);
    if (it == m_lineEntries.cend())
        return;
    const QString station = m_lines->stationOf(line);
    const LineMessage *published = m_station->line(station, line->name());
    const QString state = lineStateText(line);
    it->header->display(published ? published->address : QString(), int(line->devices().size()), line->state(),
                        state);
    // The name whole and the state in a word; the reason in the tooltip and the header.
    QString word = tr("connected");
    if (line->state() == LineState::Lost)
        word = tr("line lost");
    else if (line->state() == LineState::Disconnected)
        word = tr("disconnected");
    it->item->setText(tr("%1 (%2)").arg(lineLabel(line), word));
    it->item->setToolTip(tr("%1: %2").arg(lineLabel(line), state));
    updateStatus();
}

void RemoteWindow::onLineRemoving(MirroredLine *line)
{
    const Line entry = m_lineEntries.take(line);
    if (!entry.header)
        return;
    // Its devices left before it; what is left of the line goes with it.
    m_overview->removeGroup(entry.header);
    if (m_navigation->currentItem() == entry.item)
        m_navigation->setCurrentRow(overviewRow);
    delete entry.item;
    entry.journal->deleteLater();
    m_reorder->start();
    updateStatus();
}

void RemoteWindow::onDeviceAdded(MirroredLine *line, DeviceId id)
{
    const auto map = line->deviceMap(id);
    if (!map)
        return;
    Device d;
    d.line = line;
    d.values = new LiveValuesModel(line, id, this);
    d.alarms = new AlarmBitsModel(line, id, this);
    d.tile = new DeviceTile(id, *map, line->deviceAddress(id), d.values, d.alarms, m_overview);
    d.tile->setCondition(line->condition(id));
    m_overview->addTile(d.tile, m_lineEntries.value(line).header);
    // After its line's row for now; reorder() puts it where its station lists it.
    int row = m_navigation->row(m_lineEntries.value(line).item) + 1;
    while (row < m_navigation->count() && m_navigation->item(row)->data(deviceRole).isValid())
        ++row;
    d.item = new QListWidgetItem(QStringLiteral("    %1 @ %2").arg(map->shortName).arg(line->deviceAddress(id)));
    d.item->setData(deviceRole, id);
    m_navigation->insertItem(row, d.item);
    m_devices.insert(id, d);
    m_reorder->start();
    auto update = [this, id] { updateDevice(id); };
    connect(d.alarms, &AlarmBitsModel::activeAlarmsChanged, this, update);
    connect(d.alarms, &AlarmBitsModel::alarmsKnownChanged, this, update);
    connect(d.tile, &DeviceTile::activated, this, [this](DeviceId device) {
        const auto it = m_devices.constFind(device);
        if (it != m_devices.cend())
            m_navigation->setCurrentItem(it->item);
    });
    updateDevice(id);
    updateLine(line);
}

void RemoteWindow::onDeviceRemoving(MirroredLine *line, DeviceId id)
{
    // Taken out once, by its id: whatever asks for it later finds nothing.
    const Device d = m_devices.take(id);
    if (!d.tile)
        return;
    if (m_navigation->currentItem() == d.item)
        m_navigation->setCurrentRow(overviewRow);
    delete d.item;
    // The overview deletes the faceplate. The page and the models may be in the middle of
    // a signal of theirs: deleted later, the page before the models it shows.
    m_overview->removeTile(d.tile);
    if (d.page) {
        m_pages->removeWidget(d.page);
        d.page->hide();
        d.page->deleteLater();
    }
    d.values->deleteLater();
    d.alarms->deleteLater();
    updateLine(line);
}

void RemoteWindow::reorder()
{
    const QList<MirroredLine *> lines = m_lines->orderedLines();
    QList<QWidget *> headers;
    QList<QListWidgetItem *> rows;
    for (MirroredLine *line : lines) {
        const auto entry = m_lineEntries.constFind(line);
        if (entry == m_lineEntries.cend())
            continue;
        headers << entry->header;
        rows << entry->item;
        QList<DeviceTile *> tiles;
        for (DeviceId id : m_lines->orderedDevices(line)) {
            const auto d = m_devices.constFind(id);
            if (d == m_devices.cend())
                continue;
            tiles << d->tile;
            rows << d->item;
        }
        m_overview->setGroupTiles(entry->header, tiles);
    }
    m_overview->setGroupOrder(headers);
    // The page list: the fixed pages, then the lines with their devices, in that order.
    bool same = m_navigation->count() == journalRow + 1 + rows.size();
    for (qsizetype i = 0; same && i < rows.size(); ++i)
        same = m_navigation->item(int(journalRow + 1 + i)) == rows[i];
    if (!same) {
        QListWidgetItem *current = m_navigation->currentItem();
        const QSignalBlocker blocker(m_navigation);
        while (m_navigation->count() > journalRow + 1)
            m_navigation->takeItem(journalRow + 1);
        for (QListWidgetItem *row : std::as_const(rows))
            m_navigation->addItem(row);
        m_navigation->setCurrentItem(current);
    }
    fitNavigationWidth();
}

void RemoteWindow::fitNavigationWidth()
{
    // As wide as the widest line name with its state word, within reason.
    QFont bold = m_navigation->font();
    bold.setBold(true);
    const QFontMetrics metrics(bold);
    int width = m_navigation->sizeHintForColumn(0);
    for (auto it = m_lineEntries.cbegin(); it != m_lineEntries.cend(); ++it)
        width = std::max(width, metrics.horizontalAdvance(it->item->text()) + 16 + 12);
    width = std::min(width + 2 * m_navigation->frameWidth() + 8, 480);
    if (m_navigation->minimumWidth() != width)
        m_navigation->setMinimumWidth(width);
}

void RemoteWindow::showForgeryWarning()
{
    const QString text = tr("This broker lets anyone publish station data: values and liveness may be forged.");
    m_forgeryBanner->setText(text + QLatin1Char(' ')
                             + tr("This viewer's own user could publish into a station's topics; give the broker "
                                  "users and an ACL (README, \"MQTT\")."));
    m_forgeryBanner->show();
    m_forgeryStatus->setText(text);
    m_forgeryStatus->setToolTip(m_forgeryBanner->text());
    m_forgeryStatus->show();
}

QList<DeviceTile *> RemoteWindow::tilesInOrder() const
{
    return m_overview->tiles();
}

void RemoteWindow::updateDevice(DeviceId id)
{
    const auto it = m_devices.constFind(id);
    if (it == m_devices.cend())
        return;
    const DeviceCondition condition = it->line->condition(id);
    const auto kind = DeviceStateIcon::kindOf(condition, it->alarms->activeAlarms(), it->alarms->alarmsKnown());
    if (it->item->data(Qt::UserRole).toInt() != int(kind) + 1) {
        it->item->setData(Qt::UserRole, int(kind) + 1);
        it->item->setIcon(DeviceStateIcon::icon(kind));
    }
    it->item->setToolTip(QStringLiteral("%1\n%2\n%3\n%4")
                                 .arg(it->item->text().trimmed(), it->line->deviceMap(id)->name,
                                      DeviceTile::conditionText(condition),
                                      DeviceTile::alarmsText(condition, *it->alarms)));
}

void RemoteWindow::updateStatus()
{
    if (m_station->isConnected())
        m_brokerStatus->setText(tr("Broker %1: connected").arg(m_options.broker.url()));
    else if (m_brokerError.isEmpty())
        m_brokerStatus->setText(tr("Broker %1: connecting").arg(m_options.broker.url()));
    else
        m_brokerStatus->setText(tr("Broker %1: not reachable (%2); values are the last ones received")
                                        .arg(m_options.broker.url(), m_brokerError));
    QStringList live;
    QStringList receiving;
    QStringList silent;
    for (const QString &name : m_station->stations()) {
        const RemoteStationState *s = m_station->station(name);
        if (m_station->isLive(name))
            live << name;
        else if (m_station->isConnected() && s->statusKnown && s->status.online && !s->silent)
            receiving << name;   // online, its state still on the way behind other messages
        else
            silent << name;
    }
    QStringList parts;
    // What a station undid of other clients' messages under it (the broker lets them in).
    for (const QString &name : m_station->stations()) {
        const RemoteStationState *s = m_station->station(name);
        if (const qint64 undone = s->status.restored + s->status.cleared; s->statusKnown && undone > 0)
            parts << tr("%1 undid %n message(s) of other clients", nullptr, int(std::min<qint64>(undone, INT_MAX))).arg(name);
    }
    if (!live.isEmpty())
        parts << tr("Live: %1").arg(live.join(QStringLiteral(", ")));
    if (!receiving.isEmpty())
        parts << tr("Online, receiving its state: %1").arg(receiving.join(QStringLiteral(", ")));
    if (!silent.isEmpty())
        parts << tr("Not live: %1").arg(silent.join(QStringLiteral(", ")));
    m_stationStatus->setText(parts.isEmpty() ? tr("No station heard yet") : parts.join(QStringLiteral("  ")));
}

DevicePage *RemoteWindow::ensurePage(DeviceId id)
{
    auto it = m_devices.find(id);
    if (it == m_devices.end())
        return nullptr;
    if (!it->page) {
        it->page = new DevicePage(static_cast<const DeviceSource *>(it->line), id, it->values, it->alarms, m_pages);
        it->page->setCondition(it->line->condition(id));
        m_pages->addWidget(it->page);
    }
    return it->page;
}

DeviceId RemoteWindow::find(const QString &line, const QString &family, quint8 address) const
{
    for (auto it = m_devices.cbegin(); it != m_devices.cend(); ++it) {
        if (it->line->name() == line && it->line->deviceAddress(it.key()) == address
            && it->line->deviceMap(it.key())->family == family)
            return it.key();
    }
    return -1;
}

DeviceTile *RemoteWindow::deviceTile(const QString &line, const QString &family, quint8 address) const
{
    const auto it = m_devices.constFind(find(line, family, address));
    return it == m_devices.cend() ? nullptr : it->tile;
}

DevicePage *RemoteWindow::devicePage(const QString &line, const QString &family, quint8 address)
{
    return ensurePage(find(line, family, address));
}

LineHeader *RemoteWindow::lineHeader(const QString &line) const
{
    for (auto it = m_lineEntries.cbegin(); it != m_lineEntries.cend(); ++it) {
        if (it.key()->name() == line)
            return it->header;
    }
    return nullptr;
}

void RemoteWindow::showDevice(DevicePage *page)
{
    for (auto it = m_devices.cbegin(); it != m_devices.cend(); ++it) {
        if (it->page == page)
            m_navigation->setCurrentItem(it->item);
    }
}

} // namespace jumo
