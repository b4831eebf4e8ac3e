// HMI benchmark (a program, not a test): jumo-hmi, a process of its own on the offscreen
// platform in a 1920x1080 window with every faceplate on screen, monitors a line of
// simulated devices (31 by default, IPC 300, TYA 200 and dTRON 300 in turn at 38400 baud,
// the Quantrol too at 19200 and below; --dead N of them never answer) with its default
// settings. The simulator runs in this process, replies paced at the baud rate: an alarm
// or warning bit of a random live device is set, held (--hold-ms) and cleared, over and
// over, and the HMI's alarm journal (a JSON-lines file in its log folder, written when its
// bus reads the bit) tells when the HMI saw each state. Prints the time from an alarm
// change to the HMI (median, p99, max), the alarm states that ended unseen, the age of
// the values the faceplates show (sampled every second: --report-faceplate-ages), the
// longest any entry went unread, the HMI's CPU time and peak memory, and the time from
// start to the first live value in demo mode.
#include "benchsupport.h"
#include "sim/ptypair.h"
#include "sim/simulatorline.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QProcess>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>
#include <memory>

using namespace jumo;
using namespace jumo::bench;

namespace {

bool waitForOutput(QProcess &process, const QByteArray &text, int timeoutMs, QByteArray *seen)
{
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < timeoutMs) {
        *seen += process.readAllStandardOutput() + process.readAllStandardError();
        if (seen->contains(text))
            return true;
        if (process.state() == QProcess::NotRunning)
            return false;
        spin(5);
    }
    return false;
}

// A home of its own for the HMI: its settings are the defaults, and its logs are where
// EventLog::defaultFolder() puts them without JUMO_LOG_DIR: XDG_DATA_HOME/jumo.
struct Home
{
    QTemporaryDir dir;

    QProcessEnvironment environment(const QString &platform) const
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), platform);
        env.insert(QStringLiteral("HOME"), dir.path());
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral(".config")));
        env.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral(".local/share")));
        env.insert(QStringLiteral("XDG_CACHE_HOME"), dir.filePath(QStringLiteral(".cache")));
        env.insert(QStringLiteral("XDG_STATE_HOME"), dir.filePath(QStringLiteral(".local/state")));
        env.insert(QStringLiteral("XDG_RUNTIME_DIR"), dir.filePath(QStringLiteral("runtime")));
        env.remove(QStringLiteral("JUMO_LOG_DIR"));
        return env;
    }
    bool make() const
    {
        QDir root(dir.path());
        return dir.isValid() && root.mkpath(QStringLiteral("runtime"))
                && QFile::setPermissions(dir.filePath(QStringLiteral("runtime")), QFileDevice::ReadOwner
                                                 | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    }
    QString journal() const { return dir.filePath(QStringLiteral(".local/share/jumo/alarm-journal.jsonl")); }
};

// Reads the records a JSON-lines file gains, as they are appended.
class JournalTail
{
public:
    explicit JournalTail(const QString &path) : m_file(path) { }

    QList<QJsonObject> take()
    {
        QList<QJsonObject> records;
        if (!m_file.isOpen() && !m_file.open(QIODevice::ReadOnly))
            return records;   // not written yet
        m_pending += m_file.readAll();
        qsizetype end;
        while ((end = m_pending.indexOf('\n')) >= 0) {
            const QJsonDocument doc = QJsonDocument::fromJson(m_pending.left(end));
            m_pending.remove(0, end + 1);
            if (doc.isObject())
                records << doc.object();
        }
        return records;
    }

private:
    QFile m_file;
    QByteArray m_pending;
};

} // namespace

int main(int argc, char *argv[])
{
    jumo::bench::warnIfUnoptimised();
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("qt.modbus*=false\njumo.*=false"));
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
            "HMI benchmark: alarm change to HMI, faceplate value age, CPU, memory and start-up time of jumo-hmi."));
    parser.addHelpOption();
    const auto option = [&parser](const char *name, const char *text, const char *value) {
        addNumberOption(parser, name, text, value);
    };
    option("seconds", "Seconds measured (default 90).", "90");
    option("devices", "Devices on the line, 1..31, the dead ones included (default 31).", "31");
    option("dead", "Devices that never answer, the highest addresses (default 0).", "0");
    option("baud", "Baud rate of the line (default 38400; the Quantrol joins at 19200 and below).", "38400");
    option("warmup", "Seconds after every live device is online before measuring (default 20).", "20");
    option("change-ms", "An alarm state is set on a device with nothing under way this often (default 600).", "600");
    option("hold-ms", "An alarm state is cleared after this long, seen or not (default 2000).", "2000");
    option("startup-runs", "Demo start-ups timed, the best one printed (default 3; 0: none).", "3");
    parser.addOption({QStringLiteral("platform"), QStringLiteral("Qt platform of the HMI (default offscreen)."),
                      QStringLiteral("name"), QStringLiteral("offscreen")});
    parser.addOption({QStringLiteral("hmi"), QStringLiteral("The jumo-hmi program."), QStringLiteral("path"),
                      QStringLiteral(JUMO_BIN_DIR "/jumo-hmi")});
    parser.addOption({QStringLiteral("trace"),
                      QStringLiteral("Write what the HMI reports on stderr to this file, each line after the "
                                     "benchmark's wall-clock ms."),
                      QStringLiteral("file")});
    parser.process(app);
    const int seconds = std::max(5, parser.value(QStringLiteral("seconds")).toInt());
    const int deviceCount = std::clamp(parser.value(QStringLiteral("devices")).toInt(), 1, 31);
    const int dead = std::clamp(parser.value(QStringLiteral("dead")).toInt(), 0, deviceCount - 1);
    const int baud = parser.value(QStringLiteral("baud")).toInt();
    const int warmupS = std::max(0, parser.value(QStringLiteral("warmup")).toInt());
    const int changeMs = std::max(10, parser.value(QStringLiteral("change-ms")).toInt());
    const int holdMs = std::max(100, parser.value(QStringLiteral("hold-ms")).toInt());
    const int startupRuns = std::max(0, parser.value(QStringLiteral("startup-runs")).toInt());
    const QString platform = parser.value(QStringLiteral("platform"));
    const QString hmiProgram = parser.value(QStringLiteral("hmi"));
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    const BenchLine setup = benchLine(registry, baud);
    if (setup.exitCode != 0)
        return setup.exitCode;
    const QStringList &families = setup.families;
    Home demoHome;   // the demo's own, so its journal is not the one read below
    Home home;
    if (!demoHome.make() || !home.make()) {
        std::fprintf(stderr, "no temporary home for the HMI\n");
        return 1;
    }
    const QProcessEnvironment env = home.environment(platform);
    std::printf("jumo-hmi benchmark (%s platform), load average at the start: %s\n", qPrintable(platform),
                qPrintable(loadAverage()));

    // 1. Start-up to the first live value, demo mode (best of the runs).
    qint64 best = -1;
    for (int run = 0; run < startupRuns; ++run) {
        QProcess hmi;
        hmi.setProcessEnvironment(demoHome.environment(platform));
        QElapsedTimer timer;
        timer.start();
        hmi.start(hmiProgram, {QStringLiteral("--demo"), QStringLiteral("--report-startup")});
        QByteArray seen;
        const bool ok = waitForOutput(hmi, "first live value", 30000, &seen);
        const qint64 elapsed = timer.elapsed();
        hmi.terminate();
        hmi.waitForFinished(5000);
        if (!ok) {
            std::printf("demo start-up: no live value within 30 s\n%s\n", seen.constData());
            return 1;
        }
        best = best < 0 ? elapsed : std::min(best, elapsed);
    }
    if (startupRuns > 0)
        std::printf("demo mode, start to first live value: %lld ms (best of %d; target < 1500 ms)\n", best, startupRuns);

    // 2. The line: a pty pair, the simulated devices in this process, every marker bit off.
    QTemporaryDir dir;
    PtyPair pty;
    bool ready = false;
    QObject::connect(&pty, &PtyPair::ready, [&ready] { ready = true; });
    pty.start(dir.path());
    if (!waitUntil([&] { return ready; }, 10000)) {
        std::fprintf(stderr, "no pty pair (is socat installed?)\n");
        return 1;
    }
    SimulatorLine sim;
    sim.setPacing(true);
    sim.setTickInterval(500);
    // A full-HD window: every faceplate of the line on screen, as in the control room.
    QStringList hmiArgs{QStringLiteral("-qwindowgeometry"), QStringLiteral("1920x1080+0+0"), QStringLiteral("--port"),
                        pty.masterEnd(), QStringLiteral("--baud"), QString::number(baud)};
    QHash<QString, SimulatedDevice *> live;   // "FAMILY@ADDRESS", as the journal names them
    for (int a = 1; a <= deviceCount; ++a) {
        const QString family = families.at((a - 1) % families.size());
        const QString name = QStringLiteral("%1@%2").arg(family).arg(a);
        SimulatedDevice *device = sim.addDevice(registry.family(family), quint8(a));
        setMarker(device, false);
        hmiArgs << QStringLiteral("--device") << name;
        if (a > deviceCount - dead)
            sim.setFault(quint8(a), Fault{FaultMode::Dead, -1, 0, 0});
        else
            live.insert(name, device);
    }
    if (!sim.open(pty.deviceEnd(), setup.format)) {
        std::fprintf(stderr, "the simulator cannot open %s\n", qPrintable(pty.deviceEnd()));
        return 1;
    }
    ReadAges readAges;
    readAges.watch(&sim, QStringLiteral("line"), live.values());
    // What the dead devices cost: every request to them waits out its timeout.
    int deadRequests = 0;
    bool countDead = false;
    QObject::connect(&sim, &SimulatorLine::requestReceived, [&](const QByteArray &frame) {
        if (countDead && !frame.isEmpty() && quint8(frame[0]) > deviceCount - dead)
            ++deadRequests;
    });
    std::printf("%d devices (%s in turn) at %d baud, %d of them dead, replies paced\n", deviceCount,
                qPrintable(families.join(QLatin1Char('/'))), baud, dead);
    std::printf("jumo-hmi %s --report-startup --report-faceplate-ages\n",
                qPrintable(hmiArgs.join(QLatin1Char(' ')).replace(pty.masterEnd(), QStringLiteral("PTY"))));

    // 3. The HMI; its faceplate report read line by line.
    QProcess hmi;
    hmi.setProcessEnvironment(env);
    hmi.setProcessChannelMode(QProcess::SeparateChannels);
    hmi.setStandardOutputFile(QProcess::nullDevice());
    struct FaceplateReport
    {
        int onScreen = 0;
        int tiles = 0;
        int online = 0;
        int neverRead = 0;
        QString oldest;
        QString unread;
        QList<double> ages;
    } latest;
    QString oldestName;              // of the oldest value sampled while measuring
    double oldestMs = -1;
    QList<double> ageSamples;        // every faceplate value, every second, while measuring
    QList<double> oldestPerSecond;   // the oldest of each second
    bool measuring = false;
    bool firstValue = false;
    QByteArray pendingErr;
    QByteArray otherOutput;
    QFile trace(parser.value(QStringLiteral("trace")));
    if (parser.isSet(QStringLiteral("trace")) && !trace.open(QIODevice::WriteOnly)) {
        std::fprintf(stderr, "cannot write %s\n", qPrintable(trace.fileName()));
        return 2;
    }
    QObject::connect(&hmi, &QProcess::readyReadStandardError, [&] {
        pendingErr += hmi.readAllStandardError();
        qsizetype end;
        while ((end = pendingErr.indexOf('\n')) >= 0) {
            const QByteArray line = pendingErr.left(end).trimmed();
            pendingErr.remove(0, end + 1);
            if (trace.isOpen())
                trace.write(QByteArray::number(wallMs()) + ' ' + line + '\n');
            if (line.startsWith("first live value")) {
                firstValue = true;
            } else if (line.startsWith("faceplate-ages ")) {
                const QList<QByteArray> f = line.split(' ');
                FaceplateReport r;
                r.onScreen = f.value(1).toInt();
                r.tiles = f.value(2).toInt();
                r.online = f.value(3).toInt();
                r.neverRead = f.value(4).toInt();
                r.oldest = QString::fromUtf8(f.value(5));
                r.unread = QString::fromUtf8(f.value(6));
                for (qsizetype i = 7; i < f.size(); ++i)
                    r.ages << f.at(i).toDouble();
                latest = r;
                if (measuring) {
                    ageSamples += r.ages;
                    oldestPerSecond << maximum(r.ages);
                    if (maximum(r.ages) > oldestMs) {
                        oldestMs = maximum(r.ages);
                        oldestName = r.oldest;
                    }
                }

            } else if (otherOutput.size() < 4096) {
                otherOutput += line + '\n';
            }
        }
    });
    // The HMI's alarm journal, read as it is written: the alarm states (from the
    // measurement on), and the communication records (a live device lost while measuring,
    // when each dead one was called not answering).
    AlarmChanges alarms(live, 1, changeMs, holdMs);
    // The journal records changes only: the clear of a set state the HMI never saw is none.
    alarms.setClearsAfterUnseenSet(false);
    JournalTail journal(home.journal());
    QList<double> latency;          // alarm change in the simulator -> the HMI's journal
    QList<double> setLatency;       // of the set states alone
    int lostCommunication = 0;      // a live device said not to answer meanwhile
    QHash<QString, qint64> deadOfflineMs;   // dead device -> when the HMI said it does not answer
    QTimer tail;
    QObject::connect(&tail, &QTimer::timeout, [&] {
        for (const QJsonObject &record : journal.take()) {
            const QString device = record.value(QLatin1String("device")).toString();
            const QString id = record.value(QLatin1String("id")).toString();
            const QString state = record.value(QLatin1String("state")).toString();
            const qint64 recordMs =
                    QDateTime::fromString(record.value(QLatin1String("time")).toString(), Qt::ISODateWithMs)
                            .toMSecsSinceEpoch();
            SimulatedDevice *simulated = live.value(device);
            if (!simulated) {
                if (id == QLatin1String("communication") && state.startsWith(QLatin1String("lost"))
                    && !deadOfflineMs.contains(device))
                    deadOfflineMs.insert(device, recordMs);
                continue;
            }
            if (id == QLatin1String("communication")) {
                lostCommunication += measuring && state.startsWith(QLatin1String("lost")) ? 1 : 0;
                continue;
            }
            if (id != markers().value(simulated->map().family).reference())
                continue;
            const bool on = state.startsWith(QLatin1String("set"));
            const std::optional<AlarmChanges::Change> change = alarms.observe(device, on, 0);
            if (!change || !measuring)
                continue;
            latency << double(recordMs - change->t0);
            if (on)
                setLatency << double(recordMs - change->t0);
        }
    });
    tail.start(20);
    const qint64 hmiStartMs = wallMs();
    hmi.start(hmiProgram, hmiArgs + QStringList{QStringLiteral("--report-startup"),
                                                QStringLiteral("--report-faceplate-ages")});
    if (!waitUntil([&] { return firstValue || hmi.state() == QProcess::NotRunning; }, 30000) || !firstValue) {
        std::printf("HMI did not show live values: %s\n", otherOutput.constData());
        return 1;
    }
    const int liveCount = int(live.size());
    QElapsedTimer startup;
    startup.start();
    if (!waitUntil([&] { return latest.online >= liveCount || hmi.state() == QProcess::NotRunning; }, 300000)
        || latest.online < liveCount) {
        std::printf("only %d of %d devices came online in the HMI: %s\n", latest.online, liveCount,
                    otherOutput.constData());
        return 1;
    }
    std::printf("every live device online in the HMI after %.1f s; faceplates on screen: %d of %d\n",
                double(startup.elapsed()) / 1000.0, latest.onScreen, latest.tiles);
    // A line with a dead device is measured once the HMI has given up on it (it is probed
    // with back-off from then on); how long that took is a figure of its own.
    if (!waitUntil([&] { return deadOfflineMs.size() >= dead || hmi.state() == QProcess::NotRunning; }, 600000)) {
        std::printf("the HMI never said the dead devices do not answer\n");
        return 1;
    }
    if (dead > 0 && !deadOfflineMs.isEmpty())
        std::printf("every dead device said not answering %.1f s after the HMI's start\n",
                    double(std::max_element(deadOfflineMs.cbegin(), deadOfflineMs.cend()).value() - hmiStartMs) / 1000.0);
    std::printf("warm-up %d s\n", warmupS);
    spin(warmupS * 1000);

    // 4. Measured: alarm states set, held, cleared; the journal says when the HMI saw each.
    const double cpuBefore = cpuSeconds(hmi.processId());
    const double simCpuBefore = cpuSeconds();
    const int requestsBefore = sim.requestsReceived();
    measuring = true;
    countDead = true;
    QElapsedTimer window;
    window.start();
    readAges.start();
    alarms.start();
    spin(seconds * 1000);
    alarms.stopChanging();
    const ReadAges::Longest unread = readAges.stop();
    const double wallSeconds = double(window.elapsed()) / 1000.0;
    const double cpu = cpuSeconds(hmi.processId()) - cpuBefore;
    const double simCpu = cpuSeconds() - simCpuBefore;
    const int requests = sim.requestsReceived() - requestsBefore;
    countDead = false;
    const QString loadAtEnd = loadAverage();
    const FaceplateReport last = latest;
    // The last states get their time to arrive.
    waitUntil([&] { return alarms.idle(); }, 30000 + holdMs);
    measuring = false;
    alarms.finish();
    alarms.giveUp();
    const double peak = statusKiB("VmHWM", hmi.processId()) / 1024.0;
    const double rss = statusKiB("VmRSS", hmi.processId()) / 1024.0;
    hmi.terminate();
    hmi.waitForFinished(10000);

    std::printf("\n| figure | measured |\n| --- | --- |\n");
    std::printf("| alarm change to the HMI (its alarm journal), median / p99 / max | %.0f ms / %.0f ms / %.0f ms "
                "(%lld changes: %lld set, %lld cleared) |\n",
                percentile(latency, 50), percentile(latency, 99), maximum(latency), qint64(latency.size()),
                qint64(setLatency.size()), qint64(latency.size() - setLatency.size()));
    std::printf("| of the set states alone, median / p99 / max | %.0f ms / %.0f ms / %.0f ms |\n",
                percentile(setLatency, 50), percentile(setLatency, 99), maximum(setLatency));
    std::printf("| alarm states held %d ms that ended unseen (missed) | %d of %d |\n", holdMs, alarms.missed(),
                alarms.setStates());
    std::printf("| changes never seen (30 s) | %d |\n", alarms.lost());
    std::printf("| faceplate value age, sampled every second, median / p99 / max | %.0f ms / %.0f ms / %.0f ms (%lld "
                "samples; the oldest of each second: p99 %.0f ms) |\n",
                percentile(ageSamples, 50), percentile(ageSamples, 99), maximum(ageSamples), qint64(ageSamples.size()),
                percentile(oldestPerSecond, 99));
    std::printf("| the oldest faceplate value sampled | %s |\n", qPrintable(oldestName));
    std::printf("| faceplates on screen | %d of %d (%d devices online, %d faceplate values never read) |\n",
                last.onScreen, last.tiles, last.online, last.neverRead);
    if (last.unread != QLatin1String("-"))
        std::printf("| faceplate values of devices online never read | %s |\n", qPrintable(last.unread));
    std::printf("| longest an entry of a live device went unread (requests at the simulator) | %.1f s (%s) |\n",
                double(unread.ms) / 1000.0, qPrintable(unread.where));
    std::printf("| live devices that stopped answering for a while | %d |\n", lostCommunication);
    for (int a = deviceCount - dead + 1; a <= deviceCount; ++a) {
        const QString name = QStringLiteral("%1@%2").arg(families.at((a - 1) % families.size())).arg(a);
        const auto offline = deadOfflineMs.constFind(name);
        if (offline == deadOfflineMs.cend())
            std::printf("| dead %s: said not answering | never |\n", qPrintable(name));
        else
            std::printf("| dead %s: said not answering after (from the HMI's start) | %.1f s |\n", qPrintable(name),
                        double(*offline - hmiStartMs) / 1000.0);
    }
    std::printf("| Modbus requests | %.0f /s (%d to the dead devices) |\n", double(requests) / wallSeconds, deadRequests);
    std::printf("| HMI CPU over %.0f s | %.2f s = %.1f %% of one core |\n", wallSeconds, cpu, 100.0 * cpu / wallSeconds);
    std::printf("| HMI memory (VmRSS / peak VmHWM) | %.1f MiB / %.1f MiB |\n", rss, peak);
    std::printf("| load average at the end of the measurement (1, 5, 15 min) | %s |\n", qPrintable(loadAtEnd));
    std::printf("(simulator and benchmark, not counted: %.2f s CPU)\n", simCpu);
    return 0;
}
