// jumo-hmi --remote: the control-room viewer, with real parts end to end: the simulator on
// a pty line, the jumo-publisher program owning that line, Debian's Mosquitto between,
// and the viewer's window on the offscreen platform. It must show what the station sees,
// say so when the station, the line or the broker is gone, and hold nothing that writes.
#include "mosquittobroker.h"
#include "devicepage.h"
#include "devicetile.h"
#include "lineheader.h"
#include "models/livevaluesmodel.h"
#include "mqtt/remotestation.h"
#include "protocol/valuecodec.h"
#include "remotewindow.h"
#include "testpeers.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QHostInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPointer>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTemporaryDir>

using namespace jumo;
using namespace jumo::test;

namespace {

const QString station = QStringLiteral("hall3");

// How long the long runs go on: JUMO_REMOTE_RUN_S seconds (with QTEST_FUNCTION_TIMEOUT
// raised to match), else the short version that every test run has.
int runSeconds(int fallback)
{
    bool ok = false;
    const int seconds = qEnvironmentVariableIntValue("JUMO_REMOTE_RUN_S", &ok);
    return ok && seconds > 0 ? seconds : fallback;
}

// The journal's rows of devices lost and restored, in the folder's journal.
QStringList communicationRows(const QString &folder)
{
    QFile journal(folder + QStringLiteral("/remote-alarm-journal.jsonl"));
    QStringList rows;
    if (journal.open(QIODevice::ReadOnly)) {
        for (const QByteArray &row : journal.readAll().split('\n')) {
            if (row.contains("\"communication\""))
                rows << QString::fromUtf8(row);
        }
    }
    return rows;
}

// The device is heard and its alarms are known (the simulated IPC 300 reports a min.
// alarm with no load: an alarm is what the station sees too).
bool heard(const DeviceTile *tile)
{
    return tile->summary() == DeviceTile::Summary::Normal || tile->summary() == DeviceTile::Summary::Alarm
            || tile->summary() == DeviceTile::Summary::Warning;
}

} // namespace

class TstRemoteView : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void showsTheStationsValues();
    void lateViewerSeesWhatNeverChanges();
    void nothingInItCanWrite();
    void deadStationShowsWithinTwoSeconds();
    void brokerRestartComesBackByItself();
    void aDeviceLeavesAndComesBack();
    void aLineLeavesAndComesBack();
    void aClearedInfoTakesTheDeviceOut();
    void everyViewerShowsTheStationsOrder();
    void noLossRecordedAtTheStart();
    void forgeryBannerStays();
    void pageListShowsLineNamesWhole();
    void terminatedViewerEndsPromptly();
    void restartsWithFewerDevicesAndLines();
    void forgedValuesAreUndoneInEveryViewer();

private:
    // The devices as "LINE/FAMILY@ADDRESS" in the station's order; empty: the default two.
    bool startPublisher(const QStringList &devices = {}, const QStringList &extraLines = {});
    void restartPublisher(const QStringList &devices, const QStringList &extraLines = {});
    static QStringList shownOrder(const RemoteWindow &window);
    std::unique_ptr<RemoteWindow> openViewer();
    QString brokerUrl() const { return QStringLiteral("mqtt://127.0.0.1:%1").arg(m_broker->port()); }
    void setVoltage(float volts);

    std::unique_ptr<MosquittoBroker> m_broker;
    std::unique_ptr<TestLine> m_line;
    std::unique_ptr<SimulatorPeer> m_peer;
    std::unique_ptr<QProcess> m_publisher;
    std::unique_ptr<QTemporaryDir> m_logs;   // a journal of its own for each case
};

void TstRemoteView::init()
{
    m_logs = std::make_unique<QTemporaryDir>();
    m_broker = std::make_unique<MosquittoBroker>();
    QVERIFY(m_broker->start());
    m_line = std::make_unique<TestLine>();
    QVERIFY(m_line->start());
    m_peer = std::make_unique<SimulatorPeer>(QStringLiteral("ipc300"));
    m_peer->line().addDevice(families().family(QStringLiteral("dtron300")), 2);
    QVERIFY(m_peer->start(m_line->deviceEnd(), {1}));
    QVERIFY(startPublisher());
}

void TstRemoteView::cleanup()
{
    if (m_publisher && m_publisher->state() != QProcess::NotRunning) {
        m_publisher->kill();
        m_publisher->waitForFinished(10000);
    }
    if (QTest::currentTestFailed() && m_publisher)
        qWarning().noquote() << "publisher:" << m_publisher->readAllStandardError();
    m_publisher.reset();
    m_peer.reset();
    m_line.reset();
    m_broker.reset();
}

bool TstRemoteView::startPublisher(const QStringList &devices, const QStringList &extraLines)
{
    QStringList arguments{QStringLiteral("--broker"), brokerUrl(), QStringLiteral("--name"), station,
                          QStringLiteral("--line"), m_line->masterEnd() + QStringLiteral(",name=cabinet-a,baud=19200")};
    for (const QString &line : extraLines)
        arguments << QStringLiteral("--line") << line;
    for (const QString &device :
         devices.isEmpty() ? QStringList{QStringLiteral("cabinet-a/ipc300@1"), QStringLiteral("cabinet-a/dtron300@2")} : devices)
        arguments << QStringLiteral("--device") << device;
    m_publisher = std::make_unique<QProcess>();
    m_publisher->start(QStringLiteral(JUMO_PUBLISHER_PATH), arguments);
    return m_publisher->waitForStarted(10000);
}

void TstRemoteView::restartPublisher(const QStringList &devices, const QStringList &extraLines)
{
    m_publisher->terminate();
    QVERIFY(m_publisher->waitForFinished(10000));
    QVERIFY(startPublisher(devices, extraLines));
}

QStringList TstRemoteView::shownOrder(const RemoteWindow &window)
{
    QStringList shown;
    for (DeviceTile *tile : window.tilesInOrder())
        shown << tile->objectName();
    return shown;
}

std::unique_ptr<RemoteWindow> TstRemoteView::openViewer()
{
    RemoteWindow::Options options;
    options.broker = *MqttSettings::fromUrl(brokerUrl(), nullptr);
    options.logFolder = m_logs->path();
    auto window = std::make_unique<RemoteWindow>(families(), options);
    QString error;
    if (!window->start(&error)) {
        qWarning().noquote() << error;
        return nullptr;
    }
    window->resize(1280, 800);
    window->show();
    return window;
}

void TstRemoteView::setVoltage(float volts)
{
    const auto map = families().family(QStringLiteral("ipc300"));
    QVERIFY(m_peer->setWords(1, map->entry(QStringLiteral("load_voltage"))->address,
                             ValueCodec::encodeFloat(volts, map->protocol.floatWordOrder)));
}

void TstRemoteView::showsTheStationsValues()
{
    auto window = openViewer();
    QVERIFY(window);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("ipc300"), 1), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("dtron300"), 2), 30000);
    DeviceTile *ipc = window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("ipc300"), 1);
    QTRY_VERIFY_WITH_TIMEOUT(heard(ipc), 30000);
    setVoltage(228.5f);
    QTRY_VERIFY_WITH_TIMEOUT(ipc->valuesText().contains(QLatin1String("228.5 V")), 10000);
    LineHeader *header = window->lineHeader(QStringLiteral("cabinet-a"));
    QVERIFY(header);
    QVERIFY2(header->stateText().contains(QLatin1String("Connected")), qPrintable(header->stateText()));

    // The device page: live values from the broker, current, the same text the tile shows.
    DevicePage *page = window->devicePage(QStringLiteral("cabinet-a"), QStringLiteral("ipc300"), 1);
    QVERIFY(page);
    window->showDevice(page);
    const int row = page->values()->rowOf(QStringLiteral("load_voltage"));
    const QModelIndex value = page->values()->index(row, LiveValuesModel::ValueColumn);
    QTRY_COMPARE_WITH_TIMEOUT(page->values()->data(value, LiveValuesModel::ValidityRole).toInt(), int(Validity::Current),
                              10000);
    QCOMPARE(page->values()->data(value, LiveValuesModel::ValueWithUnitRole).toString(), QStringLiteral("228.5 V"));
    QVERIFY(page->ledGrid());
    QVERIFY(page->trend());
}

// A viewer opened long after the station published: values that never changed since
// come from the retained messages alone, read before this program started.
void TstRemoteView::lateViewerSeesWhatNeverChanges()
{
    // The station reads and publishes within a second or two; the viewer comes later.
    // (The in-process simulator needs the event loop: a blocking wait would starve it.)
    QTest::qWait(5000);
    auto window = openViewer();
    QVERIFY(window);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("ipc300"), 1), 30000);
    DeviceTile *ipc = window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("ipc300"), 1);
    QTRY_VERIFY_WITH_TIMEOUT(heard(ipc), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(ipc->valuesText().contains(QLatin1String("Setpoint: 40.0 %")), 10000);
    QVERIFY2(heard(ipc), qPrintable(ipc->alarmText()));   // alarms known: not "Alarms unknown"
}

void TstRemoteView::nothingInItCanWrite()
{
    auto window = openViewer();
    QVERIFY(window);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("dtron300"), 2), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("ipc300"), 1), 30000);
    for (const char *family : {"ipc300", "dtron300"}) {
        const quint8 address = QLatin1String(family) == QLatin1String("ipc300") ? 1 : 2;
        DevicePage *page = window->devicePage(QStringLiteral("cabinet-a"), QLatin1String(family), address);
        QVERIFY(page);
        window->showDevice(page);
        QVERIFY(!page->controls());
        QVERIFY(!page->parameters());
        QStringList tabs;
        for (int i = 0; i < page->tabs()->count(); ++i)
            tabs << page->tabs()->tabText(i);
        QCOMPARE(tabs.size(), 3);   // live values, alarms and status, trend
    }
    // No field anywhere takes a value to send; the only buttons are the views' own.
    for (QLineEdit *edit : window->findChildren<QLineEdit *>())
        QVERIFY2(edit->isReadOnly() || !edit->isVisible(), qPrintable(edit->objectName()));
    QVERIFY(window->findChildren<QAbstractSpinBox *>().isEmpty());
    const int writesBefore = m_peer->writeFrames();
    QTest::qWait(500);
    QCOMPARE(m_peer->writeFrames(), writesBefore);   // the publisher never writes either
    QCOMPARE(writesBefore, 0);
}

void TstRemoteView::deadStationShowsWithinTwoSeconds()
{
    auto window = openViewer();
    QVERIFY(window);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("ipc300"), 1), 30000);
    DeviceTile *ipc = window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("ipc300"), 1);
    QTRY_VERIFY_WITH_TIMEOUT(heard(ipc), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(ipc->barsFilled() > 0, 10000);

    // The pty line dies under the station: the station says so, the viewer shows it.
    m_line->stop();
    QTRY_COMPARE_WITH_TIMEOUT(ipc->summary(), DeviceTile::Summary::LineLost, 5000);
    QVERIFY(window->lineHeader(QStringLiteral("cabinet-a"))->stateText().contains(QLatin1String("lost")));
    QTRY_COMPARE_WITH_TIMEOUT(ipc->barsFilled(), 0, 2000);   // drawn at the next coalesced refresh
    m_peer->stop();   // the simulator's end of the old pair
    QVERIFY(m_line->restart());
    QVERIFY(m_peer->reopen());
    QTRY_VERIFY_WITH_TIMEOUT(heard(ipc), 30000);

    // The station itself dies (SIGKILL): its will reaches the viewer within 2 s.
    QTRY_VERIFY_WITH_TIMEOUT(ipc->barsFilled() > 0, 10000);
    m_publisher->kill();
    QVERIFY(m_publisher->waitForFinished(10000));
    QTRY_COMPARE_WITH_TIMEOUT(ipc->summary(), DeviceTile::Summary::LineLost, 2000);
    QTRY_COMPARE_WITH_TIMEOUT(ipc->barsFilled(), 0, 2000);   // drawn at the next coalesced refresh
    QVERIFY2(window->lineHeader(QStringLiteral("cabinet-a"))->stateText().contains(station),
             qPrintable(window->lineHeader(QStringLiteral("cabinet-a"))->stateText()));
}

void TstRemoteView::brokerRestartComesBackByItself()
{
    auto window = openViewer();
    QVERIFY(window);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("ipc300"), 1), 30000);
    DeviceTile *ipc = window->deviceTile(QStringLiteral("cabinet-a"), QStringLiteral("ipc300"), 1);
    setVoltage(231.25f);
    QTRY_VERIFY_WITH_TIMEOUT(ipc->valuesText().contains(QLatin1String("231.3 V")), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(heard(ipc), 30000);

    m_broker->kill();
    QTRY_COMPARE_WITH_TIMEOUT(ipc->summary(), DeviceTile::Summary::LineLost, 10000);
    QVERIFY(ipc->valuesText().contains(QLatin1String("231.3 V")));   // the last known value stays, not as current
    QTRY_COMPARE_WITH_TIMEOUT(ipc->barsFilled(), 0, 2000);   // drawn at the next coalesced refresh
    QVERIFY(m_broker->restart());
    QTRY_VERIFY_WITH_TIMEOUT(heard(ipc), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(ipc->barsFilled() > 0, 10000);
    QVERIFY(ipc->valuesText().contains(QLatin1String("231.3 V")));
}

void TstRemoteView::aDeviceLeavesAndComesBack()
{
    auto window = openViewer();
    QVERIFY(window);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-a", "dtron300", 2), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-a", "ipc300", 1), 30000);
    // Its page is open when it goes.
    DevicePage *page = window->devicePage("cabinet-a", "dtron300", 2);
    QVERIFY(page);
    window->showDevice(page);
    QPointer<DevicePage> watched(page);

    restartPublisher({"cabinet-a/ipc300@1"});
    QTRY_VERIFY_WITH_TIMEOUT(!window->deviceTile("cabinet-a", "dtron300", 2), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(watched.isNull(), 10000);
    auto *navigation = window->findChild<QListWidget *>(QStringLiteral("navigation"));
    QCOMPARE(navigation->currentRow(), 0);
    for (int row = 0; row < navigation->count(); ++row)
        QVERIFY2(!navigation->item(row)->text().contains(QLatin1String("dTRON")), qPrintable(navigation->item(row)->text()));
    QTRY_VERIFY_WITH_TIMEOUT(heard(window->deviceTile("cabinet-a", "ipc300", 1)), 30000);

    restartPublisher({"cabinet-a/ipc300@1", "cabinet-a/dtron300@2"});
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-a", "dtron300", 2), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(heard(window->deviceTile("cabinet-a", "dtron300", 2)), 30000);
    QVERIFY(window->devicePage("cabinet-a", "dtron300", 2));
}

void TstRemoteView::aLineLeavesAndComesBack()
{
    TestLine second;
    QVERIFY(second.start());
    SimulatorPeer secondPeer(QStringLiteral("quantrol"));
    QVERIFY(secondPeer.start(second.deviceEnd(), {1}));
    const QStringList cabinetB{second.masterEnd() + QStringLiteral(",name=cabinet-b,baud=19200")};
    restartPublisher({"cabinet-a/ipc300@1", "cabinet-a/dtron300@2", "cabinet-b/quantrol@1"}, cabinetB);
    auto window = openViewer();
    QVERIFY(window);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-b", "quantrol", 1), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(window->lineHeader("cabinet-b"), 30000);
    DevicePage *page = window->devicePage("cabinet-b", "quantrol", 1);
    QVERIFY(page);
    window->showDevice(page);

    restartPublisher({"cabinet-a/ipc300@1", "cabinet-a/dtron300@2"});
    QTRY_VERIFY_WITH_TIMEOUT(!window->lineHeader("cabinet-b"), 30000);
    QVERIFY(!window->deviceTile("cabinet-b", "quantrol", 1));
    auto *navigation = window->findChild<QListWidget *>(QStringLiteral("navigation"));
    for (int row = 0; row < navigation->count(); ++row)
        QVERIFY2(!navigation->item(row)->text().contains(QLatin1String("cabinet-b")), qPrintable(navigation->item(row)->text()));
    QTRY_VERIFY_WITH_TIMEOUT(heard(window->deviceTile("cabinet-a", "ipc300", 1)), 30000);

    restartPublisher({"cabinet-a/ipc300@1", "cabinet-a/dtron300@2", "cabinet-b/quantrol@1"}, cabinetB);
    QTRY_VERIFY_WITH_TIMEOUT(window->lineHeader("cabinet-b"), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-b", "quantrol", 1), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(heard(window->deviceTile("cabinet-b", "quantrol", 1)), 30000);
}

void TstRemoteView::aClearedInfoTakesTheDeviceOut()
{
    auto window = openViewer();
    QVERIFY(window);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-a", "dtron300", 2), 30000);
    QPointer<DeviceTile> tile(window->deviceTile("cabinet-a", "dtron300", 2));
    window->showDevice(window->devicePage("cabinet-a", "dtron300", 2));
    // Anyone publishing an empty retained info: out of every viewer at once; the station
    // publishes its own again and the device is back.
    MqttClient vandal;
    vandal.setSettings(*MqttSettings::fromUrl(brokerUrl(), nullptr));
    QVERIFY(vandal.connectToBroker());
    QTRY_VERIFY_WITH_TIMEOUT(vandal.isConnected(), 10000);
    QSignalSpy removed(window->station(), &RemoteStation::deviceRemoved);
    QVERIFY(vandal.publish(QStringLiteral("jumo/%1/devices/cabinet-a/dtron300@2/info").arg(station), {}, true));
    QTRY_COMPARE_WITH_TIMEOUT(removed.size(), 1, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(tile.isNull(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-a", "dtron300", 2), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(heard(window->deviceTile("cabinet-a", "dtron300", 2)), 20000);
}

void TstRemoteView::everyViewerShowsTheStationsOrder()
{
    // Not by address and not by arrival: as the station lists them.
    restartPublisher({"cabinet-a/dtron300@2", "cabinet-a/ipc300@1"});
    const QStringList expected{QStringLiteral("tile_dtron300_2"), QStringLiteral("tile_ipc300_1")};
    auto first = openViewer();
    QVERIFY(first);
    QTRY_COMPARE_WITH_TIMEOUT(shownOrder(*first), expected, 30000);
    auto second = openViewer();
    QVERIFY(second);
    QTRY_COMPARE_WITH_TIMEOUT(shownOrder(*second), expected, 30000);
    auto *navigation = second->findChild<QListWidget *>(QStringLiteral("navigation"));
    QTRY_VERIFY_WITH_TIMEOUT(navigation->count() == 5, 10000);
    QVERIFY2(navigation->item(3)->text().contains(QLatin1String("dTRON")), qPrintable(navigation->item(3)->text()));
    QVERIFY2(navigation->item(4)->text().contains(QLatin1String("IPC")), qPrintable(navigation->item(4)->text()));
}

void TstRemoteView::noLossRecordedAtTheStart()
{
    // A viewer that starts while the station is live records no loss and no return: it
    // lost nothing.
    auto window = openViewer();
    QVERIFY(window);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-a", "ipc300", 1), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(heard(window->deviceTile("cabinet-a", "ipc300", 1)), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-a", "dtron300", 2)
                                     && heard(window->deviceTile("cabinet-a", "dtron300", 2)),
                             30000);
    QFile journal(m_logs->filePath(QStringLiteral("remote-alarm-journal.jsonl")));
    const QByteArray rows = journal.open(QIODevice::ReadOnly) ? journal.readAll() : QByteArray();
    for (const QByteArray &row : rows.split('\n'))
        QVERIFY2(!row.contains("\"communication\""), row.constData());
}

void TstRemoteView::forgeryBannerStays()
{
    // The test broker is anonymous: the viewer's own probe comes back.
    auto window = openViewer();
    QVERIFY(window);
    auto *banner = window->findChild<QLabel *>(QStringLiteral("forgeryBanner"));
    auto *status = window->findChild<QLabel *>(QStringLiteral("forgeryStatus"));
    QVERIFY(banner && status);
    QTRY_VERIFY_WITH_TIMEOUT(banner->isVisible(), 30000);
    QVERIFY(banner->text().contains(QLatin1String("values and liveness may be forged")));
    QVERIFY(status->isVisible());
    QVERIFY(status->text().contains(QLatin1String("values and liveness may be forged")));
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile("cabinet-a", "ipc300", 1)
                                     && heard(window->deviceTile("cabinet-a", "ipc300", 1)),
                             30000);
    if (const QString folder = qEnvironmentVariable("JUMO_SCREENSHOT_DIR"); !folder.isEmpty())
        window->grab().save(folder + QStringLiteral("/remote-forgery-banner.png"));
    // It stays: through a broker restart and the station coming back.
    m_broker->kill();
    QTRY_VERIFY_WITH_TIMEOUT(!window->station()->isConnected(), 10000);
    QVERIFY(m_broker->restart());
    QTRY_VERIFY_WITH_TIMEOUT(heard(window->deviceTile("cabinet-a", "ipc300", 1)), 30000);
    QVERIFY(banner->isVisible());
    QVERIFY(status->isVisible());
}

void TstRemoteView::pageListShowsLineNamesWhole()
{
    // A long line name, the state in a word after it: no sideways scroll bar, the name whole.
    const QString longName = QStringLiteral("north-hall-feeders-2");
    m_publisher->terminate();
    QVERIFY(m_publisher->waitForFinished(10000));
    m_publisher = std::make_unique<QProcess>();
    m_publisher->start(QStringLiteral(JUMO_PUBLISHER_PATH),
                       {QStringLiteral("--broker"), brokerUrl(), QStringLiteral("--name"), station, QStringLiteral("--line"),
                        m_line->masterEnd() + QStringLiteral(",name=%1,baud=19200").arg(longName), QStringLiteral("--device"),
                        longName + QStringLiteral("/ipc300@1")});
    QVERIFY(m_publisher->waitForStarted(10000));
    auto window = openViewer();
    QVERIFY(window);
    QTRY_VERIFY_WITH_TIMEOUT(window->deviceTile(longName, "ipc300", 1), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(heard(window->deviceTile(longName, "ipc300", 1)), 30000);
    auto *navigation = window->findChild<QListWidget *>(QStringLiteral("navigation"));
    QListWidgetItem *lineRow = nullptr;
    for (int row = 0; row < navigation->count(); ++row) {
        if (navigation->item(row)->text().startsWith(longName))
            lineRow = navigation->item(row);
    }
    QVERIFY(lineRow);
    QApplication::processEvents();
    QVERIFY(!navigation->horizontalScrollBar()->isVisible());
    const QFontMetrics metrics(lineRow->font());
    QVERIFY2(metrics.horizontalAdvance(lineRow->text()) + 16 < navigation->viewport()->width(),
             qPrintable(QStringLiteral("%1 in %2 px").arg(lineRow->text()).arg(navigation->viewport()->width())));
    // Lost, it still fits: the reason is in the tooltip.
    m_publisher->kill();
    QVERIFY(m_publisher->waitForFinished(10000));
    QTRY_VERIFY_WITH_TIMEOUT(lineRow->text().contains(QLatin1String("lost")), 10000);
    QVERIFY(lineRow->toolTip().contains(station));
    QVERIFY(metrics.horizontalAdvance(lineRow->text()) + 16 < navigation->viewport()->width());
}

void TstRemoteView::terminatedViewerEndsPromptly()
{
    // jumo-hmi --remote as a program: SIGTERM ends it with its goodbye, at once.
    QProcess viewer;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    environment.insert(QStringLiteral("JUMO_LOG_DIR"), m_logs->path());
    viewer.setProcessEnvironment(environment);
    viewer.start(QStringLiteral(JUMO_HMI_PATH), {QStringLiteral("--remote"), brokerUrl(), QStringLiteral("--remote-station"), station});
    QVERIFY(viewer.waitForStarted(10000));
    const QString viewers = QStringLiteral("jumo/%1/viewers/+").arg(station);
    QTRY_VERIFY_WITH_TIMEOUT(retainedMessages(m_broker->port(), viewers, {}, 2).values().contains(
                                     TopicScheme::viewerPayload(QHostInfo::localHostName())),
                             30000);
    QElapsedTimer stopping;
    stopping.start();
    viewer.terminate();
    QVERIFY(viewer.waitForFinished(30000));
    qInfo("jumo-hmi --remote ended %lld ms after SIGTERM", qint64(stopping.elapsed()));
    QCOMPARE(viewer.exitStatus(), QProcess::NormalExit);
    QCOMPARE(viewer.exitCode(), 0);
    QVERIFY2(stopping.elapsed() < 5000, qPrintable(QString::number(stopping.elapsed())));
    QTRY_VERIFY_WITH_TIMEOUT(retainedMessages(m_broker->port(), viewers, {}, 2).values().contains(
                                     TopicScheme::viewerGonePayload()),
                             10000);
}

void TstRemoteView::restartsWithFewerDevicesAndLines()
{
    // The station restarted again and again with one device fewer, one line fewer, and
    // all again, under a window of every station and the jumo-hmi --remote program of
    // this station: nothing crashes, devices and lines leave and come back.
    TestLine second;
    QVERIFY(second.start());
    SimulatorPeer secondPeer(QStringLiteral("quantrol"));
    QVERIFY(secondPeer.start(second.deviceEnd(), {1}));
    const QStringList cabinetB{second.masterEnd() + QStringLiteral(",name=cabinet-b,baud=19200")};
    const QStringList all{"cabinet-a/ipc300@1", "cabinet-a/dtron300@2", "cabinet-b/quantrol@1"};
    restartPublisher(all, cabinetB);
    auto window = openViewer();
    QVERIFY(window);
    QProcess program;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    environment.insert(QStringLiteral("JUMO_LOG_DIR"), m_logs->path());
    program.setProcessEnvironment(environment);
    program.start(QStringLiteral(JUMO_HMI_PATH), {QStringLiteral("--remote"), brokerUrl(), QStringLiteral("--remote-station"), station});
    QVERIFY(program.waitForStarted(10000));
    auto heardNow = [&](const QString &line, const QString &family, quint8 address) {
        DeviceTile *tile = window->deviceTile(line, family, address);
        return tile && heard(tile);
    };
    QElapsedTimer run;
    run.start();
    int rounds = 0;
    do {
        QTRY_VERIFY_WITH_TIMEOUT(heardNow("cabinet-a", "ipc300", 1) && heardNow("cabinet-a", "dtron300", 2)
                                         && heardNow("cabinet-b", "quantrol", 1),
                                 60000);
        restartPublisher({"cabinet-a/ipc300@1", "cabinet-b/quantrol@1"}, cabinetB);
        QTRY_VERIFY_WITH_TIMEOUT(!window->deviceTile("cabinet-a", "dtron300", 2), 60000);
        QTRY_VERIFY_WITH_TIMEOUT(heardNow("cabinet-a", "ipc300", 1) && heardNow("cabinet-b", "quantrol", 1), 60000);
        restartPublisher({"cabinet-a/ipc300@1", "cabinet-a/dtron300@2"});
        QTRY_VERIFY_WITH_TIMEOUT(!window->lineHeader("cabinet-b") && !window->deviceTile("cabinet-b", "quantrol", 1), 60000);
        QTRY_VERIFY_WITH_TIMEOUT(heardNow("cabinet-a", "ipc300", 1) && heardNow("cabinet-a", "dtron300", 2), 60000);
        restartPublisher(all, cabinetB);
        ++rounds;
        QVERIFY(program.state() == QProcess::Running);
    } while (run.elapsed() < runSeconds(0) * 1000LL);
    QTRY_VERIFY_WITH_TIMEOUT(heardNow("cabinet-a", "ipc300", 1) && heardNow("cabinet-a", "dtron300", 2)
                                     && heardNow("cabinet-b", "quantrol", 1),
                             60000);
    // Each restart is a real loss: the devices of the station that stopped are lost and
    // restored, in the window and in the program, both keeping this folder's journal.
    const QStringList rows = communicationRows(m_logs->path());
    qInfo("%d rounds of restarts (one device fewer, one line fewer, all) in %lld s; the window and the program ran "
          "through; %lld journal rows of lost and restored devices (%lld lost, %lld restored)",
          rounds, qint64(run.elapsed() / 1000), qint64(rows.size()),
          qint64(rows.filter(QStringLiteral("\"lost")).size()), qint64(rows.filter(QStringLiteral("\"restored\"")).size()));
    if (const QString folder = qEnvironmentVariable("JUMO_SCREENSHOT_DIR"); !folder.isEmpty())
        window->grab().save(folder + QStringLiteral("/remote-after-restarts.png"));
    program.terminate();
    QVERIFY(program.waitForFinished(30000));
    QCOMPARE(program.exitStatus(), QProcess::NormalExit);
    QCOMPARE(program.exitCode(), 0);
}

void TstRemoteView::forgedValuesAreUndoneInEveryViewer()
{
    // A rogue client on this anonymous broker publishes fake current values (retained or
    // not) of entries that never change, and fake heartbeats. Every viewer shows the
    // forgery banner, and no fake value stays current longer than the station takes to
    // publish its own again.
    std::vector<std::unique_ptr<RemoteWindow>> viewers;
    for (int i = 0; i < 2; ++i) {
        viewers.push_back(openViewer());
        QVERIFY(viewers.back());
    }
    for (const auto &viewer : viewers) {
        QTRY_VERIFY_WITH_TIMEOUT(viewer->deviceTile("cabinet-a", "ipc300", 1)
                                         && heard(viewer->deviceTile("cabinet-a", "ipc300", 1)),
                                 30000);
        QTRY_VERIFY_WITH_TIMEOUT(viewer->deviceTile("cabinet-a", "dtron300", 2)
                                         && heard(viewer->deviceTile("cabinet-a", "dtron300", 2)),
                                 30000);
    }
    const QList<QPair<QString, QString>> targets{{"ipc300@1", "device_name"},
                                                 {"ipc300@1", "software_version"},
                                                 {"ipc300@1", "fabrication_number"},
                                                 {"dtron300@2", "sampling_cycle_time"}};
    // Per viewer and target: since when a fake is shown as current.
    QHash<QString, QElapsedTimer> shownSince;
    QList<qint64> shownMs;
    int fakesShown = 0;
    QObject watching;   // goes before what its connections use
    for (int v = 0; v < int(viewers.size()); ++v) {
        RemoteStation *mirror = viewers[v]->station();
        connect(mirror, &RemoteStation::entriesUpdated, &watching, [&, mirror, v](DeviceId id, const QStringList &ids) {
            for (const QString &entry : ids) {
                const QString key = QStringLiteral("%1/%2/%3").arg(v).arg(mirror->deviceName(id), entry);
                const ValueMessage *published = mirror->published(id, entry);
                const EntryState *state = mirror->entryState(id, entry);
                const bool fake = published && state && published->text.startsWith(QLatin1String("FAKE"))
                        && state->validity == Validity::Current;
                if (fake && !shownSince.contains(key)) {
                    shownSince[key].start();
                    ++fakesShown;
                } else if (!fake && shownSince.contains(key)) {
                    shownMs << shownSince.take(key).elapsed();
                }
            }
        });
    }
    MqttClient rogue;
    rogue.setSettings(*MqttSettings::fromUrl(brokerUrl(), nullptr));
    QVERIFY(rogue.connectToBroker());
    QTRY_VERIFY_WITH_TIMEOUT(rogue.isConnected(), 10000);
    int sent = 0;
    QTimer forging;
    connect(&forging, &QTimer::timeout, this, [&] {
        const auto &[device, entry] = targets.at(sent % targets.size());
        const QByteArray fake = QJsonDocument(QJsonObject{{"value", QStringLiteral("FAKE-%1").arg(sent)},
                                                          {"text", QStringLiteral("FAKE-%1").arg(sent)},
                                                          {"unit", ""}, {"status", "ok"}, {"validity", "current"},
                                                          {"words", QJsonArray{}},
                                                          {"read", TopicScheme::timeText(QDateTime::currentDateTimeUtc())}})
                                        .toJson(QJsonDocument::Compact);
        rogue.publish(QStringLiteral("jumo/%1/devices/cabinet-a/%2/values/%3").arg(station, device, entry), fake,
                      sent % 2 == 0);
        if (sent % 5 == 0)
            rogue.publish(QStringLiteral("jumo/%1/heartbeat").arg(station),
                          TopicScheme::heartbeatPayload(QDateTime::currentDateTimeUtc()), false);
        ++sent;
    });
    forging.start(200);
    QElapsedTimer run;
    run.start();
    while (run.elapsed() < runSeconds(10) * 1000LL)
        QTest::qWait(1000);
    forging.stop();
    // Every fake shown was undone.
    QTRY_VERIFY_WITH_TIMEOUT(shownSince.isEmpty(), 20000);
    std::sort(shownMs.begin(), shownMs.end());
    const qint64 longest = shownMs.isEmpty() ? 0 : shownMs.last();
    qInfo("%d fake values in %lld s, %d shown as current by %d viewers, each undone after: median %lld ms, 99th "
          "percentile %lld ms, longest %lld ms",
          sent, qint64(run.elapsed() / 1000), fakesShown, int(viewers.size()),
          shownMs.isEmpty() ? 0 : shownMs.at(shownMs.size() / 2),
          shownMs.isEmpty() ? 0 : shownMs.at(std::min<qsizetype>(shownMs.size() - 1, shownMs.size() * 99 / 100)),
          longest);
    QVERIFY(sent > 0);
    QCOMPARE(shownMs.size(), fakesShown);
    // The station was live all along, fake heartbeats or not: no viewer lost anything.
    const QStringList rows = communicationRows(m_logs->path());
    qInfo("%lld journal rows of lost or restored devices", qint64(rows.size()));
    QVERIFY2(rows.isEmpty(), qPrintable(rows.join(QLatin1Char('\n'))));
    QVERIFY2(longest < 10000, qPrintable(QString::number(longest)));
    for (const auto &viewer : viewers) {
        QVERIFY(viewer->findChild<QLabel *>(QStringLiteral("forgeryBanner"))->isVisible());
        QVERIFY(viewer->findChild<QLabel *>(QStringLiteral("forgeryStatus"))->isVisible());
        QVERIFY(viewer->station()->station(station)->status.restored > 0);
    }
}

QTEST_MAIN(TstRemoteView)
#include "tst_remoteview.moc"
