// Bus benchmark (a program, not a test): full-refresh cycle time of 1 and 31 simulated
// devices at 9600 and 38400 baud with replies paced at the baud rate, every readable
// entry read every cycle, against the theoretical wire-time limit of the same requests,
// and the cost of one dead device once the bus has backed off from it (--runs N: N
// times, each run against the live devices alone measured right before it).
#include "benchsupport.h"
#include "bus/bus.h"
#include "protocol/familyregistry.h"
#include "bus/linetiming.h"
#include "sim/ptypair.h"
#include "sim/simulatorline.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>

using namespace jumo;
using namespace jumo::bench;

namespace {

struct Result
{
    double cycleMs = 0;    // full-refresh time: mean period between two reads of a live device's block
    double busCycleMs = 0; // the bus's own word for it: mean period between a live device's cycles
    double theoryMs = 0;   // wire-time limit of the same requests
    double windowS = 0;    // how long it was measured
    int probes = 0;        // of the dead device, in that time
    bool ok = false;
};

struct Scenario
{
    int baud = 9600;
    int devices = 1;
    bool oneDead = false;
};

Result measure(const FamilyRegistry &registry, const QString &family, const Scenario &scenario, int processingMs,
               int cycles)
{
    Result result;
    QTemporaryDir dir;
    PtyPair pty;
    bool ready = false;
    QObject::connect(&pty, &PtyPair::ready, [&ready] { ready = true; });
    pty.start(dir.path());
    if (!waitUntil([&] { return ready; }, 10000))
        return result;
    const auto map = registry.family(family);
    const LineFormat format = *LineFormat::parse(scenario.baud, QStringLiteral("8N1"));
    SimulatorLine sim;
    sim.setPacing(true);
    sim.setProcessingDelayMs(processingMs);
    for (int a = 1; a <= scenario.devices; ++a)
        sim.addDevice(map, quint8(a));
    if (scenario.oneDead)
        sim.setFault(quint8(scenario.devices), Fault{FaultMode::Dead, -1, 0, 0});
    if (!sim.open(pty.deviceEnd(), format))
        return result;

    Bus bus;
    BusSettings settings;
    settings.portName = pty.masterEnd();
    settings.format = format;
    bus.setSettings(settings);
    if (!bus.open())
        return result;
    QList<DeviceId> live;
    DeviceId dead = -1;
    // A full refresh reads the whole map every cycle: every readable entry named, one
    // class (by default alarm words, live values and settings each have their own age).
    QStringList everything;
    for (const RegisterEntry &e : map->entries()) {
        if (e.isReadable() && e.alias.isEmpty())
            everything << e.id;
    }
    for (int a = 1; a <= scenario.devices; ++a) {
        const DeviceId id = bus.addDevice(map, quint8(a));
        bus.setPollEntries(id, everything);
        if (scenario.oneDead && a == scenario.devices)
            dead = id;
        else
            live << id;
    }
    // The line's full refresh as the simulator sees it: how often each block of the live
    // devices is read. The bus's own cycles are printed beside it: each of them after the
    // first ends one block early (the block that ended a cycle counts for the next one).
    QHash<quint32, QList<qint64>> readAt;   // slave << 16 | start -> times, while measuring
    QHash<DeviceId, int> done;
    QHash<DeviceId, QList<qint64>> finishedAt;   // while measuring
    bool measuring = false;
    QElapsedTimer clock;
    clock.start();
    const quint8 deadAddress = scenario.oneDead ? quint8(scenario.devices) : 0;
    QObject::connect(&sim, &SimulatorLine::requestReceived, [&](const QByteArray &frame) {
        if (!measuring || frame.size() != 8 || frame[1] != 0x03 || quint8(frame[0]) == deadAddress)
            return;
        readAt[(quint32(quint8(frame[0])) << 16) | (quint32(quint8(frame[2])) << 8) | quint8(frame[3])]
                << clock.elapsed();
    });
    QObject::connect(&bus, &Bus::pollCycleFinished, [&](DeviceId id, double) {
        if (id == dead) {
            // Each probe that finds nobody ends one of its cycles.
            result.probes += measuring ? 1 : 0;
            return;
        }
        ++done[id];
        if (measuring)
            finishedAt[id] << clock.elapsed();
    });
    double plannedMs = 0;   // the plans at the start, for the time allowed
    for (DeviceId id : std::as_const(live)) {
        for (const ReadBlock &b : bus.plan(id)->blocks)
            plannedMs += LineTiming::transactionMs(format, LineTiming::readRequestBytes,
                                                   LineTiming::readReplyBytes(b.count), processingMs,
                                                   map->protocol.turnaroundMs);
    }
    const int oneCycleBudget = int(plannedMs * 3) + 20000;
    // Warm up: every device once; with a dead one, until the bus probes it only rarely.
    if (!waitUntil([&] { return std::all_of(live.cbegin(), live.cend(), [&](DeviceId d) { return done.value(d) >= 1; }); },
                   oneCycleBudget))
        return result;
    if (scenario.oneDead && !waitUntil([&] { return bus.backoffMs(dead) >= 16000; }, 120000 + oneCycleBudget * 4))
        return result;
    // The period between two cycle ends of a device is the full refresh of the line.
    // With a dead device, measure over at least a minute so its rare probes are counted
    // at their real rate.
    measuring = true;
    const qint64 measureStart = clock.elapsed();
    const int minimumMs = scenario.oneDead ? 60000 : 0;
    if (!waitUntil([&] {
            return clock.elapsed() - measureStart >= minimumMs
                    && std::all_of(live.cbegin(), live.cend(),
                                   [&](DeviceId d) { return finishedAt.value(d).size() >= cycles + 1; });
        },
                   oneCycleBudget * (cycles + 2) + minimumMs))
        return result;
    result.windowS = double(clock.elapsed() - measureStart) / 1000.0;
    // The plans as they were read while measuring (an entry the device answered with
    // exception 02 has left its plan by then).
    for (DeviceId id : std::as_const(live)) {
        for (const ReadBlock &b : bus.plan(id)->blocks)
            result.theoryMs += LineTiming::transactionMs(format, LineTiming::readRequestBytes,
                                                         LineTiming::readReplyBytes(b.count), processingMs,
                                                         map->protocol.turnaroundMs);
    }
    double sum = 0;
    for (DeviceId d : std::as_const(live)) {
        const QList<qint64> &t = finishedAt.value(d);
        sum += double(t.last() - t.first()) / double(t.size() - 1);
    }
    result.busCycleMs = sum / double(live.size());
    sum = 0;
    int blocks = 0;
    for (const QList<qint64> &t : std::as_const(readAt)) {
        if (t.size() < 2)
            continue;
        sum += double(t.last() - t.first()) / double(t.size() - 1);
        ++blocks;
    }
    if (blocks == 0)
        return result;
    result.cycleMs = sum / double(blocks);
    result.ok = true;
    return result;
}

// "9600,38400" -> {9600, 38400}; empty when a part is no number in the range.
QList<int> numbers(const QString &text, int low, int high)
{
    QList<int> out;
    for (const QString &part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        const int n = part.trimmed().toInt(&ok);
        if (!ok || n < low || n > high)
            return {};
        out << n;
    }
    return out;
}

} // namespace

int main(int argc, char *argv[])
{
    jumo::bench::warnIfUnoptimised();
    QCoreApplication app(argc, argv);
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Bus benchmark: cycle time against the wire-time limit."));
    parser.addHelpOption();
    parser.addOption({QStringLiteral("family"), QStringLiteral("Device family (default ipc300)."), QStringLiteral("id"),
                      QStringLiteral("ipc300")});
    parser.addOption({QStringLiteral("processing"), QStringLiteral("Simulated processing time in ms (default 3)."),
                      QStringLiteral("ms"), QStringLiteral("3")});
    parser.addOption({QStringLiteral("cycles"), QStringLiteral("Measured cycles per scenario (default 3)."),
                      QStringLiteral("n"), QStringLiteral("3")});
    parser.addOption({QStringLiteral("devices"),
                      QStringLiteral("Devices of the large line, the dead one included; several comma-separated "
                                     "(default 31)."),
                      QStringLiteral("n[,n...]"), QStringLiteral("31")});
    parser.addOption({QStringLiteral("baud"), QStringLiteral("Baud rates, comma-separated (default 9600,38400)."),
                      QStringLiteral("rate[,rate...]"), QStringLiteral("9600,38400")});
    parser.addOption({QStringLiteral("runs"),
                      QStringLiteral("Runs of the dead-device scenario per baud rate and line, each with the live "
                                     "devices alone measured right before it (default 1)."),
                      QStringLiteral("n"), QStringLiteral("1")});
    parser.addOption({QStringLiteral("dead-only"),
                      QStringLiteral("Only the dead-device runs and their live-alone references.")});
    parser.process(app);
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    const QString family = parser.value(QStringLiteral("family"));
    if (!registry.family(family)) {
        std::fprintf(stderr, "unknown family %s\n", qPrintable(family));
        return 2;
    }
    const int processing = parser.value(QStringLiteral("processing")).toInt();
    const int cycles = std::max(1, parser.value(QStringLiteral("cycles")).toInt());
    const QList<int> lines = numbers(parser.value(QStringLiteral("devices")), 2, 247);
    const QList<int> bauds = numbers(parser.value(QStringLiteral("baud")), 1200, 115200);
    const int runs = std::max(1, parser.value(QStringLiteral("runs")).toInt());
    const bool deadOnly = parser.isSet(QStringLiteral("dead-only"));
    if (lines.isEmpty() || bauds.isEmpty()) {
        std::fprintf(stderr, "--devices takes 2..247, --baud baud rates, comma-separated\n");
        return 2;
    }

    std::printf("family %s, processing %d ms, replies paced at the baud rate, %d measured cycles; load average %s\n\n",
                qPrintable(family), processing, cycles, qPrintable(loadAverage()));
    // cycle ms: how often each block of a live device is read, at the simulator; bus cycle
    // ms: the period of the bus's pollCycleFinished, for comparison.
    std::printf("%-6s %-8s %-9s %12s %12s %7s %14s\n", "baud", "devices", "dead", "cycle ms", "limit ms", "ratio",
                "bus cycle ms");
    bool failed = false;
    const auto row = [&](int baud, int devices, const char *dead, const Result &r) {
        if (!r.ok) {
            std::printf("%-6d %-8d %-9s %12s\n", baud, devices, dead, "failed");
            failed = true;
            return false;
        }
        std::printf("%-6d %-8d %-9s %12.1f %12.1f %7.3f %14.1f", baud, devices, dead, r.cycleMs, r.theoryMs,
                    r.cycleMs / r.theoryMs, r.busCycleMs);
        return true;
    };
    for (int baud : bauds) {
        for (int many : lines) {
            if (!deadOnly) {
                for (int devices : {1, many}) {
                    if (row(baud, devices, "none", measure(registry, family, {baud, devices, false}, processing, cycles)))
                        std::printf("\n");
                }
            }
            QList<double> costs;
            QList<double> ratios;
            for (int run = 1; run <= runs; ++run) {
                // The live devices alone, then the same line with one more that never answers.
                const Result alone = measure(registry, family, {baud, many - 1, false}, processing, cycles);
                if (row(baud, many - 1, "none", alone))
                    std::printf("   (run %d: the live devices alone)\n", run);
                const Result d = measure(registry, family, {baud, many, true}, processing, cycles);
                if (!alone.ok || !row(baud, many, "1", d))
                    continue;
                const double cost = 100.0 * (d.cycleMs / alone.cycleMs - 1.0);
                costs << cost;
                ratios << d.cycleMs / d.theoryMs;
                std::printf("   (run %d: %+.1f %% against the %d live devices alone; probes of the dead one in "
                            "the %.0f s: %d; load %s)\n",
                            run, cost, many - 1, d.windowS, d.probes, qPrintable(loadAverage()));
            }
            if (runs > 1 && !costs.isEmpty())
                std::printf("%d runs at %d baud, %d devices, one dead: cost %+.1f %% .. %+.1f %%, ratio %.3f .. %.3f\n",
                            int(costs.size()), baud, many, *std::min_element(costs.begin(), costs.end()),
                            *std::max_element(costs.begin(), costs.end()),
                            *std::min_element(ratios.begin(), ratios.end()),
                            *std::max_element(ratios.begin(), ratios.end()));
        }
    }
    return failed ? 1 : 0;
}
