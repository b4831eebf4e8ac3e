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
#include <QComboBox>
#include <QLineEdit>
#include <QTemporaryDir>

using namespace jumo;
using namespace jumo::test;

namespace {

const QString station = QStringLiteral("hall3");

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

private:
    bool startPublisher();
    std::unique_ptr<RemoteWindow> openViewer();
    QString brokerUrl() const { return QStringLiteral("mqtt://127.0.0.1:%1").arg(m_broker->port()); }
    void setVoltage(float volts);

    std::unique_ptr<MosquittoBroker> m_broker;
    std::unique_ptr<TestLine> m_line;
    std::unique_ptr<SimulatorPeer> m_peer;
    std::unique_ptr<QProcess> m_publisher;
    QTemporaryDir m_logs;
};

void TstRemoteView::init()
{
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

bool TstRemoteView::startPublisher()
{
    m_publisher = std::make_unique<QProcess>();
    m_publisher->start(QStringLiteral(JUMO_PUBLISHER_PATH),
                       {QStringLiteral("--broker"), brokerUrl(), QStringLiteral("--name"), station,
                        QStringLiteral("--line"), m_line->masterEnd() + QStringLiteral(",name=cabinet-a,baud=19200"),
                        QStringLiteral("--device"), QStringLiteral("cabinet-a/ipc300@1"), QStringLiteral("--device"),
                        QStringLiteral("cabinet-a/dtron300@2")});
    return m_publisher->waitForStarted(10000);
}

std::unique_ptr<RemoteWindow> TstRemoteView::openViewer()
{
    RemoteWindow::Options options;
    options.broker = *MqttSettings::fromUrl(brokerUrl(), nullptr);
    options.logFolder = m_logs.path();
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

QTEST_MAIN(TstRemoteView)
#include "tst_remoteview.moc"
