// History benchmark (a program, not a test). Recording: one station of 8 lines with 31
// simulated devices each (248; IPC 300, TYA 200 and dTRON 300 in turn) on socat pty
// pairs at 38400 baud, replies paced at the baud rate, values moving, every device read
// whole by a Bus per line; the process's CPU is measured without and then with the
// HistoryRecorder and its SQLite store, and the store's file gives the bytes per sample.
// Query: a store holding 24 hours of 20 entries (a sample every 5 s each), rolled up;
// the time of a trend's 24-hour query of one entry and of reading its every sample.
#include "benchsupport.h"
#include "bus/bus.h"
#include "history/historyreader.h"
#include "history/historyrecorder.h"
#include "history/sqlhistorystore.h"
#include "protocol/familyregistry.h"
#include "sim/ptypair.h"
#include "sim/simulatorline.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QSqlQuery>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

using namespace jumo;
using namespace jumo::bench;

namespace {

// CPU seconds of this process's threads whose name starts with prefix.
double threadCpuSeconds(const QByteArray &prefix)
{
    double total = 0;
    const QDir tasks(QStringLiteral("/proc/self/task"));
    for (const QString &tid : tasks.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        QFile comm(tasks.filePath(tid + QStringLiteral("/comm")));
        if (!comm.open(QIODevice::ReadOnly) || !comm.readAll().startsWith(prefix))
            continue;
        QFile stat(tasks.filePath(tid + QStringLiteral("/stat")));
        if (!stat.open(QIODevice::ReadOnly))
            continue;
        const QByteArray line = stat.readAll();
        const QList<QByteArray> fields = line.mid(line.lastIndexOf(')') + 2).split(' ');
        total += (fields.value(11).toDouble() + fields.value(12).toDouble()) / double(sysconf(_SC_CLK_TCK));
    }
    return total;
}

qint64 fileBytes(const QString &path)
{
    qint64 bytes = 0;
    for (const char *suffix : {"", "-wal", "-shm"})
        bytes += QFileInfo(path + QLatin1String(suffix)).size();
    return bytes;
}

struct TableSize
{
    qint64 rows = -1;
    qint64 bytes = -1;   // its pages, from SQLite's dbstat (Debian's SQLite has it)
};

TableSize tableSize(const QString &path, const QString &table)
{
    TableSize size;
    HistoryDatabase db(HistoryLocation::file(path));
    QString error;
    if (!db.open(false, &error))
        return size;
    QSqlQuery q = db.query();
    if (q.exec(QStringLiteral("SELECT COUNT(*) FROM %1").arg(table)) && q.next())
        size.rows = q.value(0).toLongLong();
    QSqlQuery pages = db.query();
    if (pages.exec(QStringLiteral("SELECT SUM(pgsize) FROM dbstat WHERE name = '%1'").arg(table)) && pages.next())
        size.bytes = pages.value(0).toLongLong();
    return size;
}

int recording(int lineCount, int devicesPerLine, int seconds)
{
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    const QStringList families{QStringLiteral("ipc300"), QStringLiteral("tya200"), QStringLiteral("dtron300")};
    const LineFormat format = *LineFormat::parse(38400, QStringLiteral("8N1"));
    QTemporaryDir dir;
    std::vector<std::unique_ptr<PtyPair>> ptys;
    std::vector<std::unique_ptr<SimulatorLine>> sims;
    std::vector<std::unique_ptr<Bus>> buses;
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
        auto bus = std::make_unique<Bus>();
        BusSettings settings;
        settings.portName = pty->masterEnd();
        settings.format = format;
        bus->setSettings(settings);
        for (int a = 1; a <= devicesPerLine; ++a) {
            const auto map = registry.family(families.at((a + l - 1) % families.size()));
            sim->addDevice(map, quint8(a));
            bus->addDevice(map, quint8(a));
        }
        if (!sim->open(pty->deviceEnd(), format) || !bus->open()) {
            std::fprintf(stderr, "a line did not open\n");
            return 1;
        }
        ptys.push_back(std::move(pty));
        sims.push_back(std::move(sim));
        buses.push_back(std::move(bus));
    }
    std::printf("%d lines, %d devices, 38400 baud, every device read whole\n", lineCount, lineCount * devicesPerLine);
    std::fflush(stdout);
    spin(20000);   // every device found and confirmed

    double cpu0 = cpuSeconds();
    QElapsedTimer clock;
    clock.start();
    spin(seconds * 1000);
    const double withoutCpu = cpuSeconds() - cpu0;
    const double withoutS = clock.elapsed() / 1000.0;
    std::printf("without recording: %.1f s CPU in %.0f s = %.1f %% of one core (buses and simulators)\n", withoutCpu,
                withoutS, 100 * withoutCpu / withoutS);

    const QString path = HistoryLocation::defaultFile(dir.path(), QStringLiteral("bench"));
    qint64 series = 0;
    qint64 rows = 0;
    double perSecond = 0;
    {
        SqlHistoryStore store(HistoryLocation::file(path), QStringLiteral("bench"));
        store.start();
        HistoryRecorder recorder(&store);
        for (int l = 0; l < lineCount; ++l)
            recorder.addSource(buses[size_t(l)].get(), QStringLiteral("line%1").arg(l + 1));
        spin(10000);   // the first samples of every value
        const int recorded0 = recorder.samplesRecorded();
        const double writer0 = threadCpuSeconds("jumo-history");
        cpu0 = cpuSeconds();
        clock.restart();
        spin(seconds * 1000);
        const double withCpu = cpuSeconds() - cpu0;
        const double withS = clock.elapsed() / 1000.0;
        const double writerCpu = threadCpuSeconds("jumo-history") - writer0;
        const int samples = recorder.samplesRecorded() - recorded0;
        std::printf("with recording:    %.1f s CPU in %.0f s = %.1f %% of one core; recording: %.1f %% "
                    "(of which the writer thread %.1f %%)\n",
                    withCpu, withS, 100 * withCpu / withS, 100 * (withCpu / withS - withoutCpu / withoutS),
                    100 * writerCpu / withS);
        std::printf("samples: %.0f/s (changes and gaps; %d in all since the first poll)\n", samples / withS,
                    recorder.samplesRecorded());
        for (const auto &bus : buses) {
            for (DeviceId id : bus->devices())
                series += bus->deviceMap(id)->entries().size();
        }
        // Heartbeats: every value that stays is recorded again every 5 minutes.
        std::printf("series: %lld (a heartbeat each adds %.1f samples/s)\n", series, series / 300.0);
        perSecond = samples / withS + series / 300.0;
        std::fflush(stdout);
        for (auto &bus : buses)
            bus->close();
        spin(500);
    }
    const TableSize raw = tableSize(path, QStringLiteral("history_raw"));
    const TableSize named = tableSize(path, QStringLiteral("history_series"));
    rows = raw.rows;
    const double perSample = rows > 0 ? double(raw.bytes) / double(rows) : 0;
    std::printf("store: %lld bytes in all; samples: %lld in %lld bytes = %.1f bytes per sample; the %lld series' "
                "names: %lld bytes\n",
                fileBytes(path), rows, raw.bytes, perSample, named.rows, named.bytes);
    std::printf("a day at this rate, heartbeats included: %.0f samples/s = %.0f MiB of raw samples\n", perSecond,
                perSecond * 86400 * perSample / 1048576.0);
    return 0;
}

int query(int entries)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.sqlite"));
    const qint64 dayMs = 24LL * 3600 * 1000;
    const qint64 endMs = (QDateTime::currentMSecsSinceEpoch() / 60000 - 5) * 60000;
    const qint64 startMs = endMs - dayMs;
    const HistoryKey key{QStringLiteral("bench"), QStringLiteral("line1"), QStringLiteral("ipc300@1")};
    QElapsedTimer clock;
    clock.start();
    {
        SqlHistoryStore store(HistoryLocation::file(path), key.station);
        qint64 done = 0;
        bool maintained = false;
        QObject::connect(&store, &SqlHistoryStore::written, [&done](int n) { done += n; });
        QObject::connect(&store, &SqlHistoryStore::maintained, [&maintained] { maintained = true; });
        store.start();
        QList<int> handles;
        for (int e = 0; e < entries; ++e)
            handles << store.series({key, QStringLiteral("entry%1").arg(e), true, QStringLiteral("V")});
        qint64 total = 0;
        for (qint64 t = startMs; t < endMs; t += 5000) {
            for (int e = 0; e < entries; ++e) {
                HistorySample s;
                s.series = handles[e];
                s.timeMs = t + e;
                s.state = SampleState::Ok;
                s.value = double((t / 5000 + e) % 97);
                store.record(s);
                ++total;
            }
        }
        store.flush();
        waitUntil([&] { return done >= total; }, 600000);
        std::printf("24 hours of %d entries written: %lld samples in %.1f s\n", entries, done, clock.elapsed() / 1000.0);
        clock.restart();
        store.maintainNow();
        waitUntil([&] { return maintained; }, 600000);
        std::printf("rolled up to one-minute rows in %.1f s; file %.1f MiB\n", clock.elapsed() / 1000.0,
                    fileBytes(path) / 1048576.0);
    }
    HistoryReader reader(HistoryLocation::file(path));
    QString error;
    if (!reader.open(&error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    auto timed = [&](const std::function<int()> &run, const char *what) {
        QList<double> ms;
        int points = 0;
        for (int i = 0; i < 5; ++i) {
            QElapsedTimer t;
            t.start();
            points = run();
            ms << t.nsecsElapsed() / 1e6;
        }
        const double first = ms.first();
        std::sort(ms.begin(), ms.end());
        std::printf("%s: %d points, first %.1f ms, median of 5 %.1f ms\n", what, points, first, ms[2]);
    };
    timed([&] { return int(reader.samples(key, QStringLiteral("entry7"), startMs, endMs, 1000).points.size()); },
          "24-hour trend of one entry (1000 buckets, from the one-minute rows)");
    timed([&] { return int(reader.samples(key, QStringLiteral("entry7"), endMs - 3600000, endMs, 1000).points.size()); },
          "1-hour trend of one entry (raw samples)");
    timed(
            [&] {
                int n = 0;
                reader.records(key, QStringLiteral("entry7"), startMs, endMs, [&n](const HistoryRecord &) { return ++n, true; },
                               &error);
                return n;
            },
            "every sample of one entry over 24 hours (jumoctl history)");
    return 0;
}

} // namespace

int main(int argc, char *argv[])
{
    jumo::bench::warnIfUnoptimised();
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("History benchmark: recording cost, bytes per sample, query time."));
    parser.addHelpOption();
    parser.addOption({QStringLiteral("lines"), QStringLiteral("Lines (default 8)."), QStringLiteral("N"), QStringLiteral("8")});
    parser.addOption({QStringLiteral("devices"), QStringLiteral("Devices per line (default 31)."), QStringLiteral("N"),
                      QStringLiteral("31")});
    parser.addOption({QStringLiteral("seconds"), QStringLiteral("Seconds measured each way (default 60)."),
                      QStringLiteral("N"), QStringLiteral("60")});
    parser.addOption({QStringLiteral("entries"), QStringLiteral("Entries in the 24-hour store (default 20)."),
                      QStringLiteral("N"), QStringLiteral("20")});
    parser.addOption({QStringLiteral("query-only"), QStringLiteral("Only the query figures.")});
    parser.process(app);
    if (!parser.isSet(QStringLiteral("query-only"))) {
        if (const int code = recording(parser.value(QStringLiteral("lines")).toInt(),
                                       parser.value(QStringLiteral("devices")).toInt(),
                                       parser.value(QStringLiteral("seconds")).toInt()))
            return code;
    }
    return query(parser.value(QStringLiteral("entries")).toInt());
}
