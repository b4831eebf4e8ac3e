// Log benchmark (a program, not a test): what a large alarm journal and write audit log
// (10^6 records each by default) cost the HMI. In this process, the journal table over
// the file: the newest rows, paging back to the oldest, filters; then start to the first
// live value (demo mode) and peak memory of jumo-hmi with and without the logs.
#include "logs/eventlog.h"
#include "models/eventlogmodel.h"

#include "benchsupport.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>
#include <functional>

namespace {

void spin(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

// A line of /proc/PID/status ("VmHWM", "VmRSS") in MiB.
double statusMiB(qint64 pid, const QByteArray &key)
{
    QFile status(pid ? QStringLiteral("/proc/%1/status").arg(pid) : QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith(key + ':'))
            return line.mid(key.size() + 1).trimmed().split(' ').first().toDouble() / 1024.0;
    }
    return -1;
}

// Records as the HMI writes them: one alarm bit of one of 31 devices a second (the
// journal), or one write (the audit log), oldest first.
bool writeLog(const QString &path, int records, bool audit)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return false;
    const QDateTime start = QDateTime::currentDateTimeUtc().addSecs(-records);
    QByteArray chunk;
    for (int n = 0; n < records; ++n) {
        const QByteArray time = start.addSecs(n).toString(Qt::ISODateWithMs).toLatin1();
        const QByteArray device = QByteArray("ipc300@") + QByteArray::number(n % 31 + 1);
        if (audit) {
            chunk += "{\"device\":\"" + device + "\",\"entry\":\"input_setpoint\",\"message\":\"\",\"new\":\""
                   + QByteArray::number(n % 1000 / 10.0) + "\",\"old\":\"" + QByteArray::number(n % 997 / 10.0)
                   + "\",\"result\":\"confirmed\",\"time\":\"" + time + "\"}\n";
        } else {
            chunk += "{\"bit\":7,\"device\":\"" + device
                   + "\",\"id\":\"malfunction_signal_1.fuse_failure\",\"kind\":\"alarm\",\"label\":\"Fuse failure\","
                     "\"register\":\"0x00ED\",\"state\":\""
                   + (n % 2 ? "cleared" : "set") + "\",\"time\":\"" + time + "\"}\n";
        }
        if (chunk.size() > (1 << 20)) {
            if (file.write(chunk) != chunk.size())
                return false;
            chunk.clear();
        }
    }
    return file.write(chunk) == chunk.size();
}

struct StartUp
{
    qint64 bestMs = -1;
    double peakMiB = -1;
};

// Best of three starts to the first live value; peak memory a few seconds later, when
// the log pages have read what they read at start.
StartUp measureStartUp(const QString &hmi, const QString &logDir, const QString &home, int settleMs)
{
    StartUp result;
    for (int run = 0; run < 3; ++run) {
        QProcess process;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        env.insert(QStringLiteral("JUMO_LOG_DIR"), logDir);
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), home);
        process.setProcessEnvironment(env);
        QElapsedTimer timer;
        timer.start();
        process.start(hmi, {QStringLiteral("--demo"), QStringLiteral("--report-startup")});
        QByteArray seen;
        qint64 elapsed = -1;
        while (timer.elapsed() < 120000 && process.state() != QProcess::NotRunning) {
            seen += process.readAllStandardError();
            if (seen.contains("first live value")) {
                elapsed = timer.elapsed();
                break;
            }
            spin(2);
        }
        if (elapsed >= 0) {
            spin(settleMs);
            result.peakMiB = std::max(result.peakMiB, statusMiB(process.processId(), "VmHWM"));
            result.bestMs = result.bestMs < 0 ? elapsed : std::min(result.bestMs, elapsed);
        } else {
            std::printf("no live value within 120 s: %s\n", seen.constData());
        }
        process.terminate();
        if (!process.waitForFinished(10000)) {   // busy outside its event loop
            process.kill();
            process.waitForFinished(10000);
        }
    }
    return result;
}

bool waitUntil(const std::function<bool()> &done, int timeoutMs = 600000)
{
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > timeoutMs)
            return false;
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    }
    return true;
}

} // namespace

int main(int argc, char *argv[])
{
    jumo::bench::warnIfUnoptimised();
    QCoreApplication app(argc, argv);
    std::setvbuf(stdout, nullptr, _IOLBF, 0);   // each figure as soon as it is measured
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Log benchmark: jumo-hmi with a large alarm journal and audit log."));
    parser.addHelpOption();
    parser.addOption({QStringLiteral("records"), QStringLiteral("Records in each log (default 1000000)."),
                      QStringLiteral("n"), QStringLiteral("1000000")});
    parser.addOption({QStringLiteral("hmi"), QStringLiteral("The jumo-hmi to measure (default: this build's)."),
                      QStringLiteral("path"), QStringLiteral(JUMO_BIN_DIR "/jumo-hmi")});
    parser.addOption({QStringLiteral("settle"), QStringLiteral("Wait after the first live value before the peak memory is read, ms (default 3000)."),
                      QStringLiteral("ms"), QStringLiteral("3000")});
    parser.process(app);
    const int records = parser.value(QStringLiteral("records")).toInt();
    const QString hmi = parser.value(QStringLiteral("hmi"));
    const int settleMs = parser.value(QStringLiteral("settle")).toInt();

    QTemporaryDir dir;
    const QString empty = dir.filePath(QStringLiteral("no-logs"));
    const QString large = dir.filePath(QStringLiteral("large-logs"));
    const QString home = dir.filePath(QStringLiteral("home"));
    QDir().mkpath(empty);
    QDir().mkpath(large);
    QDir().mkpath(home);
    const QString journalPath = large + QStringLiteral("/alarm-journal.jsonl");
    QElapsedTimer timer;
    timer.start();
    if (!writeLog(journalPath, records, false) || !writeLog(large + QStringLiteral("/write-audit.jsonl"), records, true)) {
        std::printf("cannot write the logs in %s\n", qPrintable(large));
        return 1;
    }
    std::printf("jumo-hmi log benchmark: %s\n", qPrintable(hmi));
    std::printf("logs of %d records each: journal %.1f MiB, audit log %.1f MiB (written in %.1f s)\n", records,
                QFileInfo(journalPath).size() / 1048576.0,
                QFileInfo(large + QStringLiteral("/write-audit.jsonl")).size() / 1048576.0, timer.elapsed() / 1000.0);

    // The journal table in this process, over the same file.
    const double rssBefore = statusMiB(0, "VmRSS");
    jumo::EventLog journal(journalPath);
    const QStringList columns{"time", "device", "register", "bit", "id", "label", "kind", "state"};
    timer.restart();
    jumo::EventLogModel model(&journal, columns, columns);
    if (!waitUntil([&] { return !model.isLoading(); }))
        return 1;
    std::printf("journal table: newest %d rows after %lld ms\n", model.rowCount(), timer.elapsed());
    timer.restart();
    int fetches = 0;
    while (model.canFetchMore({})) {
        model.fetchMore({});
        ++fetches;
        if (!waitUntil([&] { return !model.isLoading(); }))
            return 1;
    }
    std::printf("  paged back to the oldest of %d rows in %d steps: %lld ms; memory +%.1f MiB\n", model.rowCount(),
                fetches, timer.elapsed(), statusMiB(0, "VmRSS") - rssBefore);
    timer.restart();
    for (int row = 0; row < model.rowCount(); row += model.rowCount() / 1000)
        (void)model.index(row, 4).data();
    std::printf("  1000 rows across the table read and shown: %lld ms\n", timer.elapsed());
    struct Filter
    {
        const char *text;
        const char *what;
    };
    for (const Filter &f : {Filter{"ipc300@17", "a device (every 31st record)"},
                            Filter{"ipc300@17 nowhere", "a text in no record (the whole log searched)"},
                            Filter{"device", "a key in every line, a value in none"}}) {
        timer.restart();
        model.setFilter(QString::fromUtf8(f.text));
        if (!waitUntil([&] { return model.rowCount() > 0 || !model.isLoading(); }))
            return 1;
        const qint64 first = timer.elapsed();
        while (model.canFetchMore({})) {
            model.fetchMore({});
            if (!waitUntil([&] { return !model.isLoading(); }))
                return 1;
        }
        std::printf("  filter \"%s\", %s: first %s after %lld ms, all %d after %lld ms\n", f.text, f.what,
                    model.rowCount() ? "rows" : "answer", first, model.rowCount(), timer.elapsed());
    }
    std::printf("  peak memory of this process: %.1f MiB\n", statusMiB(0, "VmHWM"));

    // The HMI, started with and without the logs (its demo adds a few records to them).
    const StartUp without = measureStartUp(hmi, empty, home, settleMs);
    const StartUp with = measureStartUp(hmi, large, home, settleMs);
    std::printf("demo mode, start to first live value (best of 3): %lld ms without logs, %lld ms with them\n",
                without.bestMs, with.bestMs);
    std::printf("HMI peak memory (VmHWM, %d ms after it): %.1f MiB without logs, %.1f MiB with them (target < 150 MB)\n",
                settleMs, without.peakMiB, with.peakMiB);

    return 0;
}
