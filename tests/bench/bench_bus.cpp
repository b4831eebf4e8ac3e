// Bus benchmark (a program, not a test): full-refresh cycle time of 1 and 31 simulated
// devices at 9600 and 38400 baud with replies paced at the baud rate, against the
// theoretical wire-time limit of the same requests, and the cost of one dead device
// once the bus has backed off from it.
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
    double cycleMs = 0;    // full-refresh time: mean period between a live device's cycles
    double theoryMs = 0;   // wire-time limit of the same requests
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
    for (int a = 1; a <= scenario.devices; ++a) {
        const DeviceId id = bus.addDevice(map, quint8(a));
        if (scenario.oneDead && a == scenario.devices)
            dead = id;
        else
            live << id;
    }
    for (DeviceId id : std::as_const(live)) {
        for (const ReadBlock &b : bus.plan(id)->blocks)
            result.theoryMs += LineTiming::transactionMs(format, LineTiming::readRequestBytes,
                                                         LineTiming::readReplyBytes(b.count), processingMs,
                                                         map->protocol.turnaroundMs);
    }
    QHash<DeviceId, int> done;
    QHash<DeviceId, QList<qint64>> finishedAt;   // while measuring
    bool measuring = false;
    QElapsedTimer clock;
    clock.start();
    QObject::connect(&bus, &Bus::pollCycleFinished, [&](DeviceId id, double) {
        if (id == dead)
            return;
        ++done[id];
        if (measuring)
            finishedAt[id] << clock.elapsed();
    });
    const int oneCycleBudget = int(result.theoryMs * 3) + 20000;
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
    double sum = 0;
    for (DeviceId d : std::as_const(live)) {
        const QList<qint64> &t = finishedAt.value(d);
        sum += double(t.last() - t.first()) / double(t.size() - 1);
    }
    result.cycleMs = sum / double(live.size());
    result.ok = true;
    return result;
}

} // namespace

int main(int argc, char *argv[])
{
    jumo::bench::warnIfUnoptimised();
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Bus benchmark: cycle time against the wire-time limit."));
    parser.addHelpOption();
    parser.addOption({QStringLiteral("family"), QStringLiteral("Device family (default ipc300)."), QStringLiteral("id"),
                      QStringLiteral("ipc300")});
    parser.addOption({QStringLiteral("processing"), QStringLiteral("Simulated processing time in ms (default 3)."),
                      QStringLiteral("ms"), QStringLiteral("3")});
    parser.addOption({QStringLiteral("cycles"), QStringLiteral("Measured cycles per scenario (default 3)."),
                      QStringLiteral("n"), QStringLiteral("3")});
    parser.addOption({QStringLiteral("devices"), QStringLiteral("Devices of the large line (default 31)."),
                      QStringLiteral("n"), QStringLiteral("31")});
    parser.process(app);
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    const QString family = parser.value(QStringLiteral("family"));
    if (!registry.family(family)) {
        std::fprintf(stderr, "unknown family %s\n", qPrintable(family));
        return 2;
    }
    const int processing = parser.value(QStringLiteral("processing")).toInt();
    const int cycles = std::max(1, parser.value(QStringLiteral("cycles")).toInt());
    const int many = std::clamp(parser.value(QStringLiteral("devices")).toInt(), 2, 247);

    std::printf("family %s, processing %d ms, replies paced at the baud rate, %d measured cycles\n\n",
                qPrintable(family), processing, cycles);
    std::printf("%-6s %-8s %-9s %12s %12s %7s\n", "baud", "devices", "dead", "cycle ms", "limit ms", "ratio");
    bool failed = false;
    for (int baud : {9600, 38400}) {
        double liveMany = 0;
        for (int devices : {1, many - 1, many}) {
            const Result r = measure(registry, family, {baud, devices, false}, processing, cycles);
            if (!r.ok) {
                std::printf("%-6d %-8d %-9s %12s\n", baud, devices, "none", "failed");
                failed = true;
                continue;
            }
            if (devices == many - 1)
                liveMany = r.cycleMs;
            std::printf("%-6d %-8d %-9s %12.1f %12.1f %7.3f\n", baud, devices, "none", r.cycleMs, r.theoryMs,
                        r.cycleMs / r.theoryMs);
            std::fflush(stdout);
        }
        const Result d = measure(registry, family, {baud, many, true}, processing, cycles);
        if (!d.ok) {
            std::printf("%-6d %-8d %-9s %12s\n", baud, many, "1", "failed");
            failed = true;
            continue;
        }
        std::printf("%-6d %-8d %-9s %12.1f %12.1f %7.3f   (%+.1f %% against %d live devices alone)\n", baud, many,
                    "1", d.cycleMs, d.theoryMs, d.cycleMs / d.theoryMs, 100.0 * (d.cycleMs / liveMany - 1.0), many - 1);
        std::fflush(stdout);
    }
    return failed ? 1 : 0;
}
