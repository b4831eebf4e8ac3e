// What the benchmark programs share: waiting on the event loop, a process's CPU time and
// memory from /proc, percentiles, and for the alarm benchmarks (station, HMI) the alarm
// or warning bit each family's simulated devices set and clear, the changes made of them,
// and how long every entry of the simulated devices went unread.
#pragma once

#include "protocol/familyregistry.h"
#include "protocol/lineformat.h"
#include "sim/simulatorline.h"

#include <QByteArray>
#include <QCommandLineParser>
#include <QDateTime>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QHash>
#include <QList>
#include <QRandomGenerator>
#include <QSet>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <optional>
#include <unistd.h>

namespace jumo::bench {

// Figures of an unoptimised build (.ci/build's Check type, made for the tests) are not the
// product's: said on stderr before anything is measured.
inline void warnIfUnoptimised()
{
#ifndef __OPTIMIZE__
    std::fputs("warning: this benchmark was built without optimisation (build type Check?); for figures, build "
               "RelWithDebInfo or Release\n",
               stderr);
#endif
}

// Runs the event loop for this long.
inline void spin(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

// Runs the event loop until the condition holds (true) or the time is up (false).
inline bool waitUntil(const std::function<bool()> &condition, int timeoutMs)
{
    QElapsedTimer timer;
    timer.start();
    while (!condition()) {
        if (timer.elapsed() > timeoutMs)
            return false;
        spin(5);
    }
    return true;
}

// User and system CPU seconds of a process (0: this one); -1 when it is gone.
inline double cpuSeconds(qint64 pid = 0)
{
    QFile stat(pid > 0 ? QStringLiteral("/proc/%1/stat").arg(pid) : QStringLiteral("/proc/self/stat"));
    if (!stat.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray line = stat.readAll();
    // Fields after the name: the state is index 0, utime 11, stime 12.
    const QList<QByteArray> fields = line.mid(line.lastIndexOf(')') + 2).split(' ');
    return (fields.value(11).toDouble() + fields.value(12).toDouble()) / double(sysconf(_SC_CLK_TCK));
}

// A memory field of /proc/PID/status in KiB ("VmRSS", "VmHWM"; pid 0: this process);
// -1 when it is gone.
inline double statusKiB(const QByteArray &field, qint64 pid = 0)
{
    QFile status(pid > 0 ? QStringLiteral("/proc/%1/status").arg(pid) : QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith(field + ':'))
            return line.mid(field.size() + 1).trimmed().split(' ').first().toDouble();
    }
    return -1;
}

// The load average of the machine, "0.52 0.31 0.20" (1, 5 and 15 minutes).
inline QString loadAverage()
{
    QFile file(QStringLiteral("/proc/loadavg"));
    if (!file.open(QIODevice::ReadOnly))
        return QStringLiteral("unknown");
    return QString::fromLatin1(file.readAll().split(' ').mid(0, 3).join(' '));
}

// The machine's wall clock in ms: every process of a benchmark shares it.
inline qint64 wallMs()
{
    return QDateTime::currentMSecsSinceEpoch();
}

// The p-th percentile (0..100) of the values; -1 without any.
inline double percentile(QList<double> values, double p)
{
    if (values.isEmpty())
        return -1;
    std::sort(values.begin(), values.end());
    const qsizetype index = std::min<qsizetype>(values.size() - 1, qsizetype(p / 100.0 * double(values.size())));
    return values.at(index);
}

inline double maximum(const QList<double> &values)
{
    return values.isEmpty() ? -1 : *std::max_element(values.begin(), values.end());
}

// "median 523 ms, p99 1060 ms, max 1120 ms (300 samples)"
inline QString figures(const QList<double> &values)
{
    if (values.isEmpty())
        return QStringLiteral("no samples");
    return QStringLiteral("median %1 ms, p99 %2 ms, max %3 ms (%4 samples)")
        .arg(percentile(values, 50), 0, 'f', 0)
        .arg(percentile(values, 99), 0, 'f', 0)
        .arg(maximum(values), 0, 'f', 0)
        .arg(values.size());
}

// ---- the alarm benchmarks ------------------------------------------------------------

// The families a line at this baud rate has, in the order its addresses take them (the
// Quantrol runs at 9600 and 19200 baud only).
inline QStringList familiesAt(const FamilyRegistry &registry, int baud)
{
    QStringList families;
    for (const QString &family : {QStringLiteral("ipc300"), QStringLiteral("tya200"), QStringLiteral("dtron300"),
                                  QStringLiteral("quantrol")}) {
        if (registry.family(family) && registry.family(family)->protocol.baudRates.contains(baud))
            families << family;
    }
    return families;
}

// A numeric option ("--seconds <n>") with its default.
inline void addNumberOption(QCommandLineParser &parser, const char *name, const char *text, const char *value)
{
    parser.addOption({QString::fromLatin1(name), QString::fromLatin1(text), QStringLiteral("n"), QString::fromLatin1(value)});
}

// A benchmark's line: its format at this baud rate and the families that run at it (the
// Quantrol tops out at 19200), their marker bits checked. exitCode is not 0 when the
// benchmark cannot run; why is printed.
struct BenchLine
{
    LineFormat format;
    QStringList families;
    int exitCode = 0;
};

// The alarm or warning bit each family's devices set and clear (never an input bit). The
// Quantrol's alarm bits follow its limit monitors, so its threshold is moved with the bit
// (the simulation would otherwise put the bit back at its next tick).
struct Marker
{
    QString entry;
    QString bit;
    QString threshold;

    QString reference() const { return entry + QLatin1Char('.') + bit; }
};

inline const QHash<QString, Marker> &markers()
{
    static const QHash<QString, Marker> m{
        {QStringLiteral("ipc300"), {QStringLiteral("malfunction_signal_2"), QStringLiteral("inhibit_peak_current"), {}}},
        {QStringLiteral("tya200"), {QStringLiteral("malfunction_signals_3"), QStringLiteral("wiring_error"), {}}},
        {QStringLiteral("dtron300"), {QStringLiteral("program_status"), QStringLiteral("tolerance_limit"), {}}},
        {QStringLiteral("quantrol"),
         {QStringLiteral("limit_value_monitoring"), QStringLiteral("limit_value_monitoring_2"),
          QStringLiteral("limit_2_alarm_value")}},
    };
    return m;
}

// Empty when every family's marker is an alarm or warning bit of an alarm word (read in
// the alarm class); else what is wrong, for the benchmark to refuse to run.
inline QString checkMarkers(const FamilyRegistry &registry, const QStringList &families)
{
    for (const QString &family : families) {
        const auto map = registry.family(family);
        const auto marker = markers().constFind(family);
        if (!map || marker == markers().cend())
            return QStringLiteral("%1: no marker bit").arg(family);
        const RegisterEntry *entry = map->entry(marker->entry);
        const BitDefinition *bit = entry ? entry->bitById(marker->bit) : nullptr;
        if (!bit)
            return QStringLiteral("%1: %2 is no bit of the map").arg(family, marker->reference());
        if (bit->kind != BitKind::Alarm && bit->kind != BitKind::Warning)
            return QStringLiteral("%1: %2 is a %3 bit, not an alarm or warning bit")
                .arg(family, marker->reference(), bitKindName(bit->kind));
        if (entry->pollClass != PollClass::Alarm)
            return QStringLiteral("%1: %2 is not read as an alarm word (class %3)")
                .arg(family, marker->entry, pollClassName(entry->pollClass));
    }
    return {};
}

inline BenchLine benchLine(const FamilyRegistry &registry, int baud)
{
    BenchLine line;
    const std::optional<LineFormat> format = LineFormat::parse(baud, QStringLiteral("8N1"));
    if (!format) {
        std::fprintf(stderr, "baud %d is not a line speed\n", baud);
        line.exitCode = 2;
        return line;
    }
    line.format = *format;
    line.families = familiesAt(registry, baud);
    if (line.families.isEmpty()) {
        std::fprintf(stderr, "no family runs at %d baud\n", baud);
        line.exitCode = 2;
    } else if (const QString wrong = checkMarkers(registry, line.families); !wrong.isEmpty()) {
        std::fprintf(stderr, "marker bits: %s\n", qPrintable(wrong));
        line.exitCode = 1;
    }
    return line;
}

inline void setMarker(SimulatedDevice *device, bool on)
{
    const Marker &marker = markers().value(device->map().family);
    if (!marker.threshold.isEmpty())
        device->setNumber(marker.threshold, on ? -1.0e6 : 1.0e6);
    device->setFlag(marker.reference(), on);
}

// Alarm states made in the simulator, one device at a time, and who has seen each. Every
// changeMs a device with nothing under way is picked at random: with a hold time its
// marker bit is set, held that long and cleared, and the device rests as long again; a
// set state that ended before every observer saw it counts as missed. Without a hold time
// the bit is toggled, and toggled back only once every observer saw the change. A change
// not seen by every observer within 30 s counts as lost.
class AlarmChanges
{
public:
    struct Change
    {
        qint64 t0 = 0;   // wallMs() when it was made
        bool state = false;
        QSet<int> seenBy;
    };

    // devices: "KEY" -> the simulated device, for the keys observers report.
    AlarmChanges(QHash<QString, SimulatedDevice *> devices, int observers, int changeMs, int holdMs)
        : m_devices(std::move(devices)), m_keys(m_devices.keys()), m_observers(observers), m_holdMs(holdMs)
    {
        std::sort(m_keys.begin(), m_keys.end());
        m_timer.setInterval(changeMs);
        QObject::connect(&m_timer, &QTimer::timeout, [this] { changeOne(); });
    }

    // What a cleared state is worth after a set state nobody saw: a viewer that shows
    // every reading sees it (true, the default); a journal of changes has nothing to say,
    // the bit was never seen set (false: the clear is not measured).
    void setClearsAfterUnseenSet(bool measured) { m_clearsAfterUnseen = measured; }

    void start()
    {
        m_measuring = true;
        m_timer.start();
    }
    // No new changes; those held are still cleared and their clears measured.
    void stopChanging() { m_timer.stop(); }
    // Nothing is measured any more (the bits are still cleared after their hold).
    void finish()
    {
        m_timer.stop();
        m_measuring = false;
    }

    // An observer saw the device's marker bit in this state at receivedMs: the change
    // it completes (null when nothing under way is seen by it so: old news, or seen by it
    // before). The change is forgotten once every observer saw it; copy what is needed.
    std::optional<Change> observe(const QString &key, bool state, int observer)
    {
        const auto change = m_changes.find(key);
        if (change == m_changes.end() || change->state != state || change->seenBy.contains(observer))
            return std::nullopt;
        change->seenBy.insert(observer);
        const Change seen = *change;
        if (change->seenBy.size() >= m_observers)
            m_changes.erase(change);
        return seen;
    }

    // Nothing under way and nothing held.
    bool idle() const { return m_changes.isEmpty() && m_held == 0; }
    // Those not seen by every observer so far: lost.
    void giveUp() { m_lost += int(m_changes.size()); m_changes.clear(); }

    int made() const { return m_made; }
    int setStates() const { return m_setStates; }   // alarm states set (with a hold time)
    int missed() const { return m_missed; }
    int lost() const { return m_lost; }

private:
    void changeOne()
    {
        const qint64 now = wallMs();
        for (auto it = m_changes.begin(); it != m_changes.end();) {
            if (now - it->t0 > 30000) {
                ++m_lost;
                it = m_changes.erase(it);
            } else {
                ++it;
            }
        }
        for (int attempt = 0; attempt < 20; ++attempt) {
            const QString key = m_keys.at(int(m_random.bounded(qint64(m_keys.size()))));
            if (m_changes.contains(key) || m_restUntil.value(key) > now)
                continue;
            SimulatedDevice *device = m_devices.value(key);
            Change change;
            change.state = m_holdMs > 0 || !device->flag(markers().value(device->map().family).reference());
            change.t0 = wallMs();
            setMarker(device, change.state);
            m_changes.insert(key, change);
            ++m_made;
            if (m_holdMs > 0) {
                ++m_setStates;
                m_restUntil.insert(key, change.t0 + 2 * qint64(m_holdMs));
                ++m_held;
                QTimer::singleShot(m_holdMs, device, [this, key, device, t0 = change.t0] { clear(key, device, t0); });
            }
            return;
        }
    }

    void clear(const QString &key, SimulatedDevice *device, qint64 setAt)
    {
        --m_held;
        bool unseen = false;
        const auto held = m_changes.find(key);
        if (held != m_changes.end() && held->t0 == setAt) {
            unseen = held->seenBy.isEmpty();
            m_missed += held->seenBy.size() < m_observers ? 1 : 0;
            m_changes.erase(held);
        }
        setMarker(device, false);
        if (!m_measuring || (unseen && !m_clearsAfterUnseen))
            return;
        Change back;
        back.state = false;
        back.t0 = wallMs();
        m_changes.insert(key, back);
        ++m_made;
    }

    QHash<QString, SimulatedDevice *> m_devices;
    QStringList m_keys;
    int m_observers = 1;
    int m_holdMs = 0;
    bool m_clearsAfterUnseen = true;
    bool m_measuring = false;
    QTimer m_timer;
    QRandomGenerator m_random{20261202};
    QHash<QString, Change> m_changes;   // key -> the change under way
    QHash<QString, qint64> m_restUntil;   // key -> no new change before then
    int m_held = 0;   // set states whose clear is to come
    int m_made = 0;
    int m_setStates = 0;
    int m_missed = 0;
    int m_lost = 0;
};

// How long each readable entry of the simulated devices went unread, as the requests
// arrive at the simulator: the longest gap between two reads of an entry (a read request
// that spans it whole) while measuring, the time since its last read at the end included.
// What the station or HMI has read, seen from the other end of the line, at no cost to it.
class ReadAges
{
public:
    struct Longest
    {
        qint64 ms = -1;
        QString where;   // "line1 ipc300@3 setpoint_1"
    };

    ReadAges() { m_clock.start(); }

    // The devices of a line whose entries are watched (not a dead one: nobody reads it).
    void watch(SimulatorLine *line, const QString &lineName, const QList<SimulatedDevice *> &devices)
    {
        for (SimulatedDevice *device : devices) {
            Device &d = m_devices[qMakePair(line, device->address())];
            d.name = QStringLiteral("%1 %2@%3").arg(lineName, device->map().family).arg(device->address());
            for (const RegisterEntry &e : device->map().entries()) {
                if (e.isReadable() && e.alias.isEmpty())
                    d.entries.append({&e, -1, 0});
            }
        }
        QObject::connect(line, &SimulatorLine::requestReceived, [this, line](const QByteArray &frame) {
            onRequest(line, frame);
        });
    }

    // From now on (the entries' last reads before count as made now).
    void start()
    {
        const qint64 now = m_clock.elapsed();
        m_measuring = true;
        for (Device &d : m_devices) {
            for (Entry &e : d.entries) {
                e.lastMs = now;
                e.longestMs = 0;
            }
        }
    }
    // The longest gap of any entry up to now.
    Longest stop()
    {
        m_measuring = false;
        const qint64 now = m_clock.elapsed();
        Longest longest;
        for (const Device &d : std::as_const(m_devices)) {
            for (const Entry &e : d.entries) {
                const qint64 gap = std::max(e.longestMs, now - e.lastMs);
                if (gap > longest.ms)
                    longest = {gap, d.name + QLatin1Char(' ') + e.entry->id};
            }
        }
        return longest;
    }

private:
    struct Entry
    {
        const RegisterEntry *entry;
        qint64 lastMs;
        qint64 longestMs;
    };
    struct Device
    {
        QString name;
        QList<Entry> entries;
    };

    void onRequest(SimulatorLine *line, const QByteArray &frame)
    {
        // A read request: address, 0x03 or 0x04, start, count, CRC.
        if (!m_measuring || frame.size() != 8 || (frame[1] != 0x03 && frame[1] != 0x04))
            return;
        const auto d = m_devices.find(qMakePair(line, quint8(frame[0])));
        if (d == m_devices.end())
            return;
        const int start = (quint8(frame[2]) << 8) | quint8(frame[3]);
        const int count = (quint8(frame[4]) << 8) | quint8(frame[5]);
        const qint64 now = m_clock.elapsed();
        for (Entry &e : d->entries) {
            if (e.entry->address >= start && e.entry->lastAddress() < start + count) {
                e.longestMs = std::max(e.longestMs, now - e.lastMs);
                e.lastMs = now;
            }
        }
    }

    QHash<QPair<SimulatorLine *, quint8>, Device> m_devices;
    QElapsedTimer m_clock;
    bool m_measuring = false;
};

} // namespace jumo::bench
