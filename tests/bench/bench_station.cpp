// Station scale benchmark (a program, not a test): one station of 8 lines with 31
// simulated devices each (248 in all, on socat pty pairs, replies paced at the baud rate),
// published by the jumo-publisher program to Debian's Mosquitto, watched by 10 remote
// viewers (RemoteStation, each in a process of its own). An alarm or warning bit of one
// device after another is toggled (or set, held and cleared: --hold-ms) in the simulator;
// every viewer reports when it sees it. Prints the station's CPU and memory, the publish
// rate, the latency from the simulator to the viewers (median, 99th percentile, split into
// waiting for the poll and the way from the station to the viewer), the longest any entry
// went unread, and what the viewers show while the broker is killed and after it is
// started again. --dead N makes N devices of each line that never answer.
//
// The same program is the viewer: "--viewer URL" mirrors the station and prints, on
// stdout, one line per marker bit it sees ("M LINE DEVICE STATE RECEIVED_MS READ_MS") and
// one whenever its summary changes ("S MS LIVE DEVICES CURRENT_VALUES"); times are the
// machine's wall clock in ms, which every process here shares.
#include "benchsupport.h"
#include "mqtt/mqttclient.h"
#include "mqtt/mqttsettings.h"
#include "mqtt/remotestation.h"
#include "protocol/familyregistry.h"
#include "sim/ptypair.h"
#include "sim/simulatorline.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QProcess>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <unistd.h>

using namespace jumo;
using namespace jumo::bench;

namespace {

const QString stationName = QStringLiteral("bench");

QString findTool(const QString &name)
{
    const QString found = QStandardPaths::findExecutable(name);
    return found.isEmpty() ? QStandardPaths::findExecutable(name, {QStringLiteral("/usr/sbin")}) : found;
}

// ---- the viewer -------------------------------------------------------------------

int runViewer(const QString &url)
{
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    QString error;
    const std::optional<MqttSettings> broker = MqttSettings::fromUrl(url, &error);
    if (!broker) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 2;
    }
    RemoteStation mirror(registry);
    mirror.setStation(stationName);
    std::setvbuf(stdout, nullptr, _IOLBF, 0);

    QObject::connect(&mirror, &RemoteStation::entriesUpdated, [&](DeviceId id, const QStringList &entries) {
        const RemoteDevice *device = mirror.device(id);
        if (!device)
            return;
        const auto marker = markers().constFind(device->family);
        if (marker == markers().cend() || !entries.contains(marker->entry))
            return;
        const ValueMessage *message = mirror.published(id, marker->entry);
        if (!message)
            return;
        const std::optional<bool> bit = message->bits.value(marker->bit);
        if (!bit)
            return;
        std::printf("M %s %s %d %lld %lld\n", qPrintable(device->line), qPrintable(device->name), *bit ? 1 : 0,
                    wallMs(), message->read.isValid() ? message->read.toMSecsSinceEpoch() : -1LL);
    });

    QString last;
    QTimer summary;
    int ticks = 0;
    int current = 0;
    int mostCurrent = 0;
    QObject::connect(&summary, &QTimer::timeout, [&] {
        // Counting 30000 values costs: every 200 ms while catching up, else every second
        // (what a station not live shows is stale by definition).
        const bool live = mirror.isLive(stationName);
        const QList<DeviceId> devices = mirror.devices();
        if (!live) {
            current = 0;
        } else if (current < mostCurrent || ++ticks % 5 == 0) {
            current = 0;
            for (DeviceId id : devices) {
                for (const QString &entry : mirror.entryIds(id)) {
                    const EntryState *state = mirror.entryState(id, entry);
                    current += state && state->validity == Validity::Current ? 1 : 0;
                }
            }
            mostCurrent = std::max(mostCurrent, current);
        }
        const QString now = QStringLiteral("%1 %2 %3").arg(live ? 1 : 0).arg(devices.size()).arg(current);
        if (now != last) {
            std::printf("S %lld %s\n", wallMs(), qPrintable(now));
            last = now;
        }
    });
    summary.start(200);

    if (!mirror.start(*broker, &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 2;
    }
    return QCoreApplication::exec();
}

// ---- the station side ----------------------------------------------------------------

struct Broker
{
    QProcess process;
    QTemporaryDir dir;
    quint16 port = 0;

    bool start()
    {
        if (port == 0) {
            QTcpServer probe;
            if (!probe.listen(QHostAddress::LocalHost))
                return false;
            port = probe.serverPort();
        }
        QFile config(dir.filePath(QStringLiteral("mosquitto.conf")));
        if (!config.open(QIODevice::WriteOnly))
            return false;
        QByteArray text = "persistence false\nlog_dest stderr\nlog_type error\n";
        if (::geteuid() == 0)
            text += "user root\n";
        text += QStringLiteral("listener %1 127.0.0.1\nallow_anonymous true\n").arg(port).toUtf8();
        config.write(text);
        config.close();
        process.setProcessChannelMode(QProcess::MergedChannels);
        process.setStandardOutputFile(dir.filePath(QStringLiteral("mosquitto.log")), QIODevice::Append);
        process.start(findTool(QStringLiteral("mosquitto")), {QStringLiteral("-c"), config.fileName()});
        if (!process.waitForStarted(10000))
            return false;
        return waitUntil(
            [this] {
                QTcpSocket socket;
                socket.connectToHost(QHostAddress::LocalHost, port);
                return socket.waitForConnected(100);
            },
            10000);
    }
    void kill()
    {
        process.kill();
        process.waitForFinished(10000);
    }
};

struct Viewer
{
    std::unique_ptr<QProcess> process;
    QByteArray pending;
    bool live = false;
    int devices = 0;
    int current = 0;
    qint64 lastSummaryMs = 0;
    QList<std::tuple<qint64, bool, int, int>> summaries;   // ms, live, devices, current
};

} // namespace

int main(int argc, char **argv)
{
    jumo::bench::warnIfUnoptimised();
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("qt.modbus*=false\njumo.*=false"));
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Station scale benchmark: 8 lines of 31 simulated devices, jumo-publisher, Mosquitto and 10 "
                       "remote viewers."));
    parser.addHelpOption();
    const auto option = [&parser](const char *name, const char *text, const char *value) {
        addNumberOption(parser, name, text, value);
    };
    option("lines", "Lines (default 8).", "8");
    option("devices", "Devices per line, 1..31 (default 31).", "31");
    option("viewers", "Remote viewers (default 10).", "10");
    option("baud", "Baud rate of the lines (default 38400).", "38400");
    option("warmup", "Seconds after every device is online before measuring (default 20).", "20");
    option("seconds", "Seconds measured (default 120).", "120");
    option("change-ms", "A marker bit is toggled this often (default 200).", "200");
    option("dead", "Devices per line that never answer, the highest addresses (default 0).", "0");
    option("hold-ms",
           "A marker bit set is cleared again after this long, seen or not; a state no viewer saw "
           "before it ended counts as missed (default 0: toggled back only once every viewer saw it).",
           "0");
    parser.addOption({QStringLiteral("publisher"), QStringLiteral("The jumo-publisher program."), QStringLiteral("path"),
                      QStringLiteral(JUMO_BIN_DIR "/jumo-publisher")});
    parser.addOption({QStringLiteral("poll"),
                      QStringLiteral("The publisher polls these words of every family and the marker bit's entry "
                                     "(--poll FAMILY:WORDS,ENTRY) instead of whole maps, e.g. 'alarms' or "
                                     "'faceplate,alarms'."),
                      QStringLiteral("words")});
    parser.addOption({QStringLiteral("viewer"), QStringLiteral("Internal: be a viewer of this broker."), QStringLiteral("url")});
    parser.process(app);
    if (parser.isSet(QStringLiteral("viewer")))
        return runViewer(parser.value(QStringLiteral("viewer")));
    std::setvbuf(stdout, nullptr, _IOLBF, 0);

    const int lineCount = std::clamp(parser.value(QStringLiteral("lines")).toInt(), 1, 32);
    const int devicesPerLine = std::clamp(parser.value(QStringLiteral("devices")).toInt(), 1, 31);
    const int viewerCount = std::clamp(parser.value(QStringLiteral("viewers")).toInt(), 1, 50);
    const int baud = parser.value(QStringLiteral("baud")).toInt();
    const int warmupS = std::max(0, parser.value(QStringLiteral("warmup")).toInt());
    const int seconds = std::max(5, parser.value(QStringLiteral("seconds")).toInt());
    const int changeMs = std::max(10, parser.value(QStringLiteral("change-ms")).toInt());
    const int holdMs = std::max(0, parser.value(QStringLiteral("hold-ms")).toInt());
    const int deadPerLine = std::clamp(parser.value(QStringLiteral("dead")).toInt(), 0, devicesPerLine - 1);
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    const BenchLine setup = benchLine(registry, baud);
    if (setup.exitCode != 0)
        return setup.exitCode;
    const QStringList &families = setup.families;
    std::printf("station: %d lines x %d devices (%s) at %d baud, %d of them per line dead, %d viewers\n", lineCount,
                devicesPerLine, qPrintable(families.join(QLatin1Char('/'))), baud, deadPerLine, viewerCount);
    std::printf("marker bits (alarm or warning bits of alarm words):");
    for (const QString &family : families)
        std::printf(" %s %s", qPrintable(family), qPrintable(markers().value(family).reference()));
    std::printf("\nload average at the start: %s\n", qPrintable(loadAverage()));

    Broker broker;
    if (!broker.start()) {
        std::fprintf(stderr, "mosquitto did not start (bash .ci/setup installs it)\n");
        return 1;
    }
    const QString url = QStringLiteral("mqtt://127.0.0.1:%1").arg(broker.port);
    std::printf("broker %s\n", qPrintable(url));

    // The lines: a pty pair and a simulated line each, every device's marker bit off.
    QTemporaryDir dir;
    std::vector<std::unique_ptr<PtyPair>> ptys;
    std::vector<std::unique_ptr<SimulatorLine>> sims;
    QHash<QString, SimulatedDevice *> simulated;   // "LINE FAMILY@ADDRESS", the live ones
    QSet<QString> deadNames;                       // "LINE/FAMILY@ADDRESS", as the topics name them
    ReadAges readAges;
    QJsonArray lineArray;
    for (int l = 0; l < lineCount; ++l) {
        auto pty = std::make_unique<PtyPair>();
        bool ready = false;
        QObject::connect(pty.get(), &PtyPair::ready, [&ready] { ready = true; });
        pty->start(dir.filePath(QStringLiteral("line%1").arg(l + 1)));
        if (!waitUntil([&] { return ready; }, 10000)) {
            std::fprintf(stderr, "no pty pair (is socat installed?)\n");
            return 1;
        }
        auto sim = std::make_unique<SimulatorLine>();
        sim->setPacing(true);
        sim->setTickInterval(500);
        const QString lineName = QStringLiteral("line%1").arg(l + 1);
        QJsonArray devices;
        QList<SimulatedDevice *> live;
        for (int a = 1; a <= devicesPerLine; ++a) {
            const QString family = families.at((a + l - 1) % families.size());
            SimulatedDevice *device = sim->addDevice(registry.family(family), quint8(a));
            setMarker(device, false);
            devices.append(family + QLatin1Char('@') + QString::number(a));
            if (a > devicesPerLine - deadPerLine) {
                sim->setFault(quint8(a), Fault{FaultMode::Dead, -1, 0, 0});
                deadNames.insert(lineName + QLatin1Char('/') + family + QLatin1Char('@') + QString::number(a));
                continue;
            }
            simulated.insert(lineName + QLatin1Char(' ') + family + QLatin1Char('@') + QString::number(a), device);
            live << device;
        }
        readAges.watch(sim.get(), lineName, live);
        if (!sim->open(pty->deviceEnd(), setup.format))
            return 1;
        lineArray.append(QJsonObject{{QStringLiteral("name"), lineName},
                                     {QStringLiteral("port"), pty->masterEnd()},
                                     {QStringLiteral("baud"), baud},
                                     {QStringLiteral("devices"), devices}});
        ptys.push_back(std::move(pty));
        sims.push_back(std::move(sim));
    }
    QFile stationFile(dir.filePath(QStringLiteral("station.json")));
    if (!stationFile.open(QIODevice::WriteOnly))
        return 1;
    stationFile.write(QJsonDocument(QJsonObject{{QStringLiteral("format"), QStringLiteral("jumo-station")},
                                                {QStringLiteral("version"), 1},
                                                {QStringLiteral("name"), stationName},
                                                {QStringLiteral("lines"), lineArray}})
                          .toJson());
    stationFile.close();

    // A subscriber of its own counts what the station publishes.
    MqttClient counter;
    QString error;
    counter.setSettings(*MqttSettings::fromUrl(url, &error));
    qint64 messages = 0;
    qint64 bytes = 0;
    QSet<QString> devicesOnline;
    int conditionLosses = 0;   // a device that was online said otherwise
    QHash<QString, qint64> deadOffline;   // "LINE/FAMILY@ADDRESS" of a dead device -> first said offline
    QObject::connect(&counter, &MqttClient::connected,
                     [&] { counter.subscribe(QStringLiteral("jumo/%1/#").arg(stationName)); });
    QObject::connect(&counter, &MqttClient::messageReceived, [&](const QString &topic, const QByteArray &payload, bool) {
        ++messages;
        bytes += payload.size() + topic.size();
        if (topic.endsWith(QLatin1String("/condition"))) {
            const QString device = topic.section(QLatin1Char('/'), 3, 4);
            if (payload.contains("\"online\"")) {
                devicesOnline.insert(device);
            } else if (devicesOnline.remove(device)) {
                ++conditionLosses;
            }
            if (payload.contains("\"offline\"") && deadNames.contains(device) && !deadOffline.contains(device))
                deadOffline.insert(device, wallMs());
        }
    });
    counter.connectToBroker();

    QProcess publisher;
    publisher.setProcessChannelMode(QProcess::MergedChannels);
    publisher.setStandardOutputFile(dir.filePath(QStringLiteral("publisher.log")));
    QStringList publisherArguments{QStringLiteral("--broker"), url, QStringLiteral("--station"), stationFile.fileName()};
    if (parser.isSet(QStringLiteral("poll"))) {
        for (const QString &family : std::as_const(families)) {
            publisherArguments << QStringLiteral("--poll")
                               << QStringLiteral("%1:%2,%3")
                                          .arg(family, parser.value(QStringLiteral("poll")), markers().value(family).entry);
        }
    }
    std::printf("jumo-publisher --station FILE %s\n", qPrintable(publisherArguments.mid(4).join(QLatin1Char(' '))));
    publisher.start(parser.value(QStringLiteral("publisher")), publisherArguments);
    if (!publisher.waitForStarted(10000)) {
        std::fprintf(stderr, "cannot start %s\n", qPrintable(parser.value(QStringLiteral("publisher"))));
        return 1;
    }
    const qint64 publisherPid = publisher.processId();
    const qint64 publisherStartMs = wallMs();
    const int deviceCount = lineCount * devicesPerLine;
    const int liveCount = int(simulated.size());
    QElapsedTimer startup;
    startup.start();
    if (!waitUntil([&] { return devicesOnline.size() == liveCount; }, 300000)) {
        std::fprintf(stderr, "only %lld of %d devices came online\n", qint64(devicesOnline.size()), liveCount);
        return 1;
    }
    std::printf("every live device online after %.1f s\n", double(startup.elapsed()) / 1000.0);
    // A line with a dead device is measured once the station has given up on it (it is
    // probed with back-off from then on); how long that took is a figure of its own.
    if (!waitUntil([&] { return deadOffline.size() == deadNames.size(); }, 600000)) {
        std::fprintf(stderr, "the station never said the dead devices are offline\n");
        return 1;
    }
    if (!deadNames.isEmpty())
        std::printf("every dead device offline %.1f s after the publisher's start\n",
                    double(*std::max_element(deadOffline.cbegin(), deadOffline.cend()) - publisherStartMs) / 1000.0);

    // The viewers.
    std::vector<Viewer> viewers(static_cast<size_t>(viewerCount));
    AlarmChanges alarms(simulated, viewerCount, changeMs, holdMs);   // keys "LINE DEVICE"
    // The station publishes what changed: the clear of a set state it never read is no news.
    alarms.setClearsAfterUnseenSet(false);
    QList<double> total;              // simulator -> viewer
    QList<double> polled;             // simulator -> read by the station
    QList<double> delivered;          // read by the station -> viewer
    bool measuring = false;
    const auto onLine = [&](int v, const QByteArray &line) {
        const QList<QByteArray> f = line.trimmed().split(' ');
        if (f.value(0) == "S" && f.size() == 5) {
            Viewer &viewer = viewers[size_t(v)];
            viewer.live = f.at(2) == "1";
            viewer.devices = f.at(3).toInt();
            viewer.current = f.at(4).toInt();
            viewer.summaries.append({f.at(1).toLongLong(), viewer.live, viewer.devices, viewer.current});
        } else if (f.value(0) == "M" && f.size() == 6) {
            const std::optional<AlarmChanges::Change> change =
                    alarms.observe(QString::fromUtf8(f.at(1) + ' ' + f.at(2)), f.at(3) == "1", v);
            if (!change || !measuring)
                return;
            const qint64 received = f.at(4).toLongLong();
            const qint64 read = f.at(5).toLongLong();
            total << double(received - change->t0);
            delivered << double(received - read);
            if (change->seenBy.size() == 1)
                polled << double(read - change->t0);
        }
    };
    for (int v = 0; v < viewerCount; ++v) {
        Viewer &viewer = viewers[size_t(v)];
        viewer.process = std::make_unique<QProcess>();
        QProcess *process = viewer.process.get();
        process->setProcessChannelMode(QProcess::SeparateChannels);
        process->setStandardErrorFile(dir.filePath(QStringLiteral("viewer%1.log").arg(v)));
        QObject::connect(process, &QProcess::readyReadStandardOutput, [&, v, process] {
            Viewer &self = viewers[size_t(v)];
            self.pending += process->readAllStandardOutput();
            qsizetype end;
            while ((end = self.pending.indexOf('\n')) >= 0) {
                onLine(v, self.pending.left(end));
                self.pending.remove(0, end + 1);
            }
        });
        process->start(QCoreApplication::applicationFilePath(), {QStringLiteral("--viewer"), url});
    }
    const auto allViewers = [&](const std::function<bool(const Viewer &)> &test) {
        return std::all_of(viewers.begin(), viewers.end(), test);
    };
    if (!waitUntil([&] { return allViewers([&](const Viewer &w) { return w.live && w.devices == deviceCount; }); },
                   120000)) {
        std::fprintf(stderr, "the viewers do not see every device:\n");
        for (const Viewer &viewer : viewers)
            std::fprintf(stderr, "  live %d, %d devices, %d values current\n", int(viewer.live), viewer.devices,
                         viewer.current);
        return 1;
    }
    std::printf("warm-up %d s\n", warmupS);
    spin(warmupS * 1000);

    // Measured: a marker bit changed every changeMs on a device with no change under way.
    measuring = true;
    const qint64 messagesBefore = messages;
    const int lossesBefore = conditionLosses;
    const qint64 bytesBefore = bytes;
    const double cpuBefore = cpuSeconds(publisherPid);
    QList<double> viewerCpuBefore;
    for (const Viewer &viewer : viewers)
        viewerCpuBefore << cpuSeconds(viewer.process->processId());
    QList<int> requestsBefore;
    for (const auto &sim : sims)
        requestsBefore << sim->requestsReceived();
    QElapsedTimer window;
    window.start();
    readAges.start();
    alarms.start();
    spin(seconds * 1000);
    alarms.stopChanging();
    const ReadAges::Longest unread = readAges.stop();
    const QString loadAtEnd = loadAverage();
    const double elapsedS = double(window.elapsed()) / 1000.0;
    const double cpu = cpuSeconds(publisherPid) - cpuBefore;
    double viewerCpu = 0;
    for (size_t v = 0; v < viewers.size(); ++v)
        viewerCpu += cpuSeconds(viewers[v].process->processId()) - viewerCpuBefore.at(qsizetype(v));
    const qint64 published = messages - messagesBefore;
    const qint64 publishedBytes = bytes - bytesBefore;
    int requests = 0;
    for (size_t l = 0; l < sims.size(); ++l)
        requests += sims[l]->requestsReceived() - requestsBefore.at(int(l));
    // The last changes get their time to arrive.
    waitUntil([&] { return alarms.idle(); }, 30000 + holdMs);
    measuring = false;
    alarms.finish();
    alarms.giveUp();

    std::printf("\n| figure | measured |\n| --- | --- |\n");
    std::printf("| station CPU (jumo-publisher, %.0f s) | %.1f s = %.1f %% of one core |\n", elapsedS, cpu,
                100.0 * cpu / elapsedS);
    std::printf("| station memory (VmRSS / VmHWM) | %.1f MiB / %.1f MiB |\n", statusKiB("VmRSS", publisherPid) / 1024.0,
                statusKiB("VmHWM", publisherPid) / 1024.0);
    std::printf("| Modbus requests on the lines | %.0f /s (%.1f /s per line) |\n", double(requests) / elapsedS,
                double(requests) / elapsedS / lineCount);
    std::printf("| published (as a subscriber receives it) | %.0f messages/s, %.0f KiB/s |\n",
                double(published) / elapsedS, double(publishedBytes) / elapsedS / 1024.0);
    std::printf("| marker changes / not seen by every viewer | %d / %d |\n", alarms.made(),
                alarms.lost() + alarms.missed());
    if (holdMs > 0)
        std::printf("| alarm states held %d ms that ended before every viewer saw them | %d of %d |\n", holdMs,
                    alarms.missed(), alarms.setStates());
    std::printf("| longest an entry of a live device went unread (requests at the simulator) | %.1f s (%s) |\n",
                double(unread.ms) / 1000.0, qPrintable(unread.where));
    std::printf("| devices that stopped answering for a while (timeouts under load) | %d |\n",
                conditionLosses - lossesBefore);
    std::printf("| simulator -> viewer | %s |\n", qPrintable(figures(total)));
    std::printf("| simulator -> read by the station (waiting for the poll) | %s |\n", qPrintable(figures(polled)));
    std::printf("| read by the station -> viewer | %s |\n", qPrintable(figures(delivered)));
    std::printf("| viewer CPU (RemoteStation, each, mean) | %.1f %% of one core |\n",
                100.0 * viewerCpu / double(viewerCount) / elapsedS);
    std::printf("| load average at the end of the measurement (1, 5, 15 min) | %s |\n", qPrintable(loadAtEnd));

    // The broker killed (no goodbye to anyone) and started again 5 s later.
    QList<int> currentBefore;
    for (const Viewer &viewer : viewers)
        currentBefore << viewer.current;
    const qint64 killedMs = wallMs();
    broker.kill();
    spin(5000);
    const qint64 restartedMs = wallMs();
    if (!broker.start()) {
        std::fprintf(stderr, "mosquitto did not start again\n");
        return 1;
    }
    waitUntil(
        [&] {
            for (int v = 0; v < viewerCount; ++v) {
                if (!viewers[size_t(v)].live || viewers[size_t(v)].current < currentBefore.at(v))
                    return false;
            }
            return true;
        },
        60000);
    spin(1000);
    QList<double> staleAfter;
    QList<double> recoveredAfter;
    int recovered = 0;
    int fewer = 0;
    for (int v = 0; v < viewerCount; ++v) {
        const Viewer &viewer = viewers[size_t(v)];
        qint64 stale = -1;
        qint64 back = -1;
        for (const auto &[ms, live, devices, current] : viewer.summaries) {
            if (ms >= killedMs && !live && stale < 0)
                stale = ms;
            if (ms >= restartedMs && live && current >= currentBefore.at(v) && back < 0)
                back = ms;
        }
        if (stale >= 0)
            staleAfter << double(stale - killedMs);
        if (back >= 0) {
            recoveredAfter << double(back - restartedMs);
            ++recovered;
        }
        fewer += viewer.current < currentBefore.at(v) ? 1 : 0;
    }
    std::printf("| broker killed: viewers showing the station stale | %lld of %d, after %s |\n",
                qint64(staleAfter.size()), viewerCount, qPrintable(figures(staleAfter)));
    std::printf("| broker back: viewers live with every value current again | %d of %d, after %s |\n", recovered,
                viewerCount, qPrintable(figures(recoveredAfter)));
    std::printf("| viewers with fewer current values than before the kill | %d (before: %d values each) |\n", fewer,
                currentBefore.value(0));

    for (Viewer &viewer : viewers) {
        viewer.process->terminate();
        viewer.process->waitForFinished(5000);
    }
    publisher.terminate();
    publisher.waitForFinished(10000);
    broker.kill();
    return 0;
}
