// Soak benchmark (a program, not a test): 31 simulated devices of all four families on
// one pty line at 38400 baud for an hour (or --minutes N), with faults of every kind on
// about 1 % of the requests (lost, late, garbled, stray byte, exception) and a device
// going dead now and then, while the HMI's models, the alarm journal and the data logger
// are attached. Every value the bus calls current is checked against the simulator's
// registers. Prints cycles, values checked, wrong values (must be 0), recoveries, memory
// after warm-up and at the end, and CPU.
#include "benchsupport.h"
#include "bus/bus.h"
#include "logs/alarmjournal.h"
#include "logs/datalogger.h"
#include "logs/eventlog.h"
#include "models/alarmbitsmodel.h"
#include "models/livevaluesmodel.h"
#include "protocol/familyregistry.h"
#include "sim/ptypair.h"
#include "sim/simulatorline.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QLoggingCategory>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>
#include <cstring>
#include <unistd.h>

using namespace jumo;
using namespace jumo::bench;

namespace {

// The truth of one varied entry: what the simulator holds now and held before, so a read
// that crossed a change is right with either.
struct Varied
{
    quint16 address = 0;
    QList<quint16> now;
    QList<quint16> before;
};

} // namespace

int main(int argc, char **argv)
{
    jumo::bench::warnIfUnoptimised();
    QCoreApplication app(argc, argv);
    // Faults on purpose: Qt's complaints about them are not news.
    QLoggingCategory::setFilterRules(QStringLiteral("qt.modbus*=false\njumo.bus*=false"));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Soak benchmark: hours of faults against the bus and the HMI's models."));
    parser.addHelpOption();
    parser.addOption({QStringLiteral("minutes"), QStringLiteral("Duration in minutes (default 60)."), QStringLiteral("n"),
                      QStringLiteral("60")});
    parser.addOption({QStringLiteral("warmup"), QStringLiteral("Minutes before the first memory figure (default 5)."),
                      QStringLiteral("n"), QStringLiteral("5")});
    parser.addOption({QStringLiteral("faults"), QStringLiteral("Share of requests with a fault, percent (default 1)."),
                      QStringLiteral("p"), QStringLiteral("1")});
    parser.process(app);
    const double minutes = parser.value(QStringLiteral("minutes")).toDouble();
    const double warmupMinutes = std::min(parser.value(QStringLiteral("warmup")).toDouble(), minutes / 2);
    const double faultShare = parser.value(QStringLiteral("faults")).toDouble() / 100.0;

    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    const QStringList families{QStringLiteral("ipc300"), QStringLiteral("tya200"), QStringLiteral("quantrol"),
                               QStringLiteral("dtron300")};
    const LineFormat format = *LineFormat::parse(38400, QStringLiteral("8N1"));

    QTemporaryDir dir;
    PtyPair pty;
    bool ready = false;
    QObject::connect(&pty, &PtyPair::ready, [&ready] { ready = true; });
    pty.start(dir.filePath(QStringLiteral("line")));
    if (!waitUntil([&] { return ready; }, 10000)) {
        std::fprintf(stderr, "no pty pair (is socat installed?)\n");
        return 1;
    }
    SimulatorLine sim;
    sim.setPacing(true);
    sim.setTickInterval(0);   // the truth changes only where this program changes it
    for (int a = 1; a <= 31; ++a)
        sim.addDevice(registry.family(families.at((a - 1) % families.size())), quint8(a));
    if (!sim.open(pty.deviceEnd(), format))
        return 1;

    Bus bus;
    BusSettings settings;
    settings.portName = pty.masterEnd();
    settings.format = format;
    bus.setSettings(settings);
    if (!bus.open()) {
        std::fprintf(stderr, "cannot open %s\n", qPrintable(pty.masterEnd()));
        return 1;
    }

    // What the HMI attaches to every device: its models, the journal, a data logger.
    EventLog journalLog(dir.filePath(QStringLiteral("alarm-journal.jsonl")));
    AlarmJournal journal(&bus, &journalLog);
    int journalRecords = 0;
    QObject::connect(&journalLog, &EventLog::appended, [&journalRecords] { ++journalRecords; });
    QList<QObject *> models;
    QHash<DeviceId, SimulatedDevice *> simOf;
    QHash<DeviceId, Varied> varied;
    DataLogger::Settings logging;
    logging.folder = dir.filePath(QStringLiteral("log"));
    logging.maxFileBytes = 4 * 1024 * 1024;
    for (SimulatedDevice *d : sim.devices()) {
        const DeviceId id = bus.addDevice(d->mapPointer(), d->address());
        simOf.insert(id, d);
        models << new LiveValuesModel(&bus, id) << new AlarmBitsModel(&bus, id);
        for (const QString &entry : d->map().overview)
            logging.entries << qMakePair(id, entry);
        // One float per device whose value this program changes now and then.
        for (const RegisterEntry &e : d->map().entries()) {
            if (e.isReadable() && e.type == ValueType::Float && e.alias.isEmpty()) {
                Varied v;
                v.address = e.address;
                for (int i = 0; i < e.wordCount(); ++i)
                    v.now << d->word(quint16(e.address + i));
                v.before = v.now;
                varied.insert(id, v);
                break;
            }
        }
    }
    DataLogger logger(&bus);
    QString error;
    if (!logger.start(logging, &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }

    // Faults: about this share of the requests gets one, of a kind drawn at random.
    QRandomGenerator random(20261201);
    QHash<FaultMode, int> injected;
    QObject::connect(&sim, &SimulatorLine::requestReceived, [&](const QByteArray &frame) {
        if (frame.isEmpty() || frame.at(0) == 0 || random.generateDouble() >= faultShare)
            return;
        static const QList<FaultMode> kinds{FaultMode::Drop, FaultMode::Late, FaultMode::StrayByte, FaultMode::BadCrc,
                                            FaultMode::Exception};
        Fault fault;
        fault.mode = kinds.at(int(random.bounded(kinds.size())));
        fault.remaining = 1;
        fault.lateMs = 400;              // after the bus has given up on it
        fault.exceptionCode = 4;         // slave device failure
        sim.setFault(quint8(frame.at(0)), fault);
        ++injected[fault.mode];
    });
    // Every 2 minutes one device goes dead for 20 s; every 30 s the varied values change.
    int deadSpells = 0;
    QTimer deadTimer;
    QObject::connect(&deadTimer, &QTimer::timeout, [&] {
        const quint8 address = quint8(1 + random.bounded(31));
        sim.setFault(address, Fault{FaultMode::Dead, -1, 0, 0});
        ++deadSpells;
        QTimer::singleShot(20000, &sim, [&sim, address] { sim.setFault(address, Fault{}); });
    });
    deadTimer.start(120000);
    QTimer changeTimer;
    QObject::connect(&changeTimer, &QTimer::timeout, [&] {
        for (auto it = varied.begin(); it != varied.end(); ++it) {
            Varied &v = it.value();
            v.before = v.now;
            const float value = float(random.bounded(1000.0));
            quint32 bits = 0;
            std::memcpy(&bits, &value, sizeof bits);
            v.now = {quint16(bits >> 16), quint16(bits & 0xFFFF)};
            simOf.value(it.key())->setWords(v.address, v.now);
            // Read back what the simulator holds (its word order), as the truth.
            v.now = {simOf.value(it.key())->word(v.address), simOf.value(it.key())->word(quint16(v.address + 1))};
        }
    });
    changeTimer.start(30000);

    // Every current value against the simulator's registers.
    qint64 checked = 0;
    qint64 wrong = 0;
    qint64 cycles = 0;
    int recoveries = 0;
    QObject::connect(&bus, &Bus::entriesUpdated, [&](DeviceId id, const QStringList &ids) {
        SimulatedDevice *d = simOf.value(id);
        const auto map = bus.deviceMap(id);
        if (!d || !map)
            return;
        for (const QString &entryId : ids) {
            const EntryState *s = bus.entryState(id, entryId);
            const RegisterEntry *e = map->entry(entryId);
            if (!s || !e || !s->isCurrent())
                continue;
            QList<quint16> truth;
            for (int i = 0; i < s->words.size(); ++i)
                truth << d->word(quint16(e->address + i));
            ++checked;
            const Varied v = varied.value(id);
            const bool right = s->words == truth || (e->address == v.address && s->words == v.before);
            if (!right) {
                ++wrong;
                const auto hex = [](const QList<quint16> &words) {
                    QStringList out;
                    for (quint16 w : words)
                        out << QStringLiteral("%1").arg(w, 4, 16, QLatin1Char('0'));
                    return out.join(QLatin1Char(' '));
                };
                std::fprintf(stderr, "WRONG %s %s: read %s, simulator %s\n", qPrintable(bus.deviceName(id)),
                             qPrintable(entryId), qPrintable(hex(s->words)), qPrintable(hex(truth)));
            }
        }
    });
    QObject::connect(&bus, &Bus::pollCycleFinished, [&](DeviceId, double) { ++cycles; });
    QObject::connect(&bus, &Bus::onlineChanged, [&](DeviceId, bool online) { recoveries += online; });

    const double cpuStart = cpuSeconds();
    QElapsedTimer clock;
    clock.start();
    double warmRss = -1;
    QTimer warm;
    warm.setSingleShot(true);
    QObject::connect(&warm, &QTimer::timeout, [&] { warmRss = statusKiB("VmRSS"); });
    warm.start(int(warmupMinutes * 60000));
    QTimer progress;
    QObject::connect(&progress, &QTimer::timeout, [&] {
        std::fprintf(stderr, "%5.1f min: %lld cycles, %lld values checked, %lld wrong, %d recoveries, RSS %.0f KiB\n",
                     clock.elapsed() / 60000.0, cycles, checked, wrong, recoveries, statusKiB("VmRSS"));
    });
    progress.start(60000);
    waitUntil([&] { return clock.elapsed() >= qint64(minutes * 60000); }, int(minutes * 60000) + 60000);
    const double seconds = clock.elapsed() / 1000.0;
    const double cpu = cpuSeconds() - cpuStart;
    const double endRss = statusKiB("VmRSS");
    logger.stop();
    bus.close();

    qint64 faults = 0;
    for (int n : std::as_const(injected))
        faults += n;
    std::printf("soak: 31 devices (4 families), 38400 baud, %.1f min, faults on %.1f %% of requests\n", seconds / 60,
                faultShare * 100);
    std::printf("requests received by the simulator: %d; faults injected: %lld (lost %d, late %d, stray byte %d, "
                "bad CRC %d, exception %d); dead spells: %d\n",
                sim.requestsReceived(), faults, injected.value(FaultMode::Drop), injected.value(FaultMode::Late),
                injected.value(FaultMode::StrayByte), injected.value(FaultMode::BadCrc),
                injected.value(FaultMode::Exception), deadSpells);
    std::printf("poll cycles: %lld; values checked against the simulator: %lld; wrong values: %lld; recoveries: %d\n",
                cycles, checked, wrong, recoveries);
    std::printf("data logger rows: %d; journal records: %d\n", logger.rowsWritten(), journalRecords);
    std::printf("memory (VmRSS): %.0f KiB after %.1f min warm-up, %.0f KiB at the end: %+.0f KiB\n", warmRss,
                warmupMinutes, endRss, endRss - warmRss);
    std::printf("CPU (bus, models, logger and the simulator in one process): %.1f s = %.1f %% of one core\n", cpu,
                100.0 * cpu / seconds);
    qDeleteAll(models);
    return wrong == 0 ? 0 : 1;
}
