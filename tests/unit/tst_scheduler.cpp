// The bus's rules, checked in simulated time: the scheduler with its value store and write
// transactions on a fake transport and a manual clock, the devices answered by the
// simulator's device model. Fairness, keepalive deadlines, quiet time after a timeout,
// no repeat of actions, read-modify-write, invalidation on loss, exception 02 isolation.
#include "bus/bus.h"
#include "bus/devicescanner.h"
#include "commissioning/parameterwritejob.h"
#include "fakeline.h"
#include "models/livevaluesmodel.h"
#include "protocol/familyregistry.h"
#include "sim/simulateddevice.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace jumo;
using namespace jumo::test;

namespace {

// The longest silence towards a slave between its first and last request.
qint64 longestGap(const FakeTransport &t, quint8 slave, qint64 fromMs, qint64 toMs)
{
    qint64 last = fromMs;
    qint64 longest = 0;
    for (const FakeTransport::Sent &s : t.sent) {
        if (s.atMs < fromMs || s.atMs > toMs)
            continue;
        if (s.request.slave == slave || s.request.isBroadcast()) {
            longest = std::max(longest, s.atMs - last);
            last = s.atMs;
        }
    }
    return std::max(longest, toMs - last);
}

// The longest time an entry went unread between fromMs and toMs.
qint64 longestUnread(const QList<qint64> &reads, qint64 fromMs, qint64 toMs)
{
    qint64 last = fromMs;
    qint64 longest = 0;
    for (qint64 t : reads) {
        if (t < fromMs || t > toMs)
            continue;
        longest = std::max(longest, t - last);
        last = t;
    }
    return std::max(longest, toMs - last);
}

// The age of an entry's value (the time since it was last read) sampled every second from
// fromMs to toMs, as the HMI benchmark samples its faceplates.
QList<qint64> sampledAges(const QList<qint64> &reads, qint64 fromMs, qint64 toMs)
{
    QList<qint64> ages;
    qsizetype next = 0;
    qint64 last = -1;
    for (qint64 t = fromMs; t <= toMs; t += 1000) {
        while (next < reads.size() && reads[next] <= t)
            last = reads[next++];
        ages << (last < 0 ? t : t - last);
    }
    return ages;
}

// The shortest time between two reads of an entry after fromMs.
qint64 shortestInterval(const QList<qint64> &reads, qint64 fromMs)
{
    qint64 shortest = std::numeric_limits<qint64>::max();
    for (qsizetype i = 1; i < reads.size(); ++i) {
        if (reads[i - 1] >= fromMs)
            shortest = std::min(shortest, reads[i] - reads[i - 1]);
    }
    return shortest;
}

// 31 devices of these families in turn, at addresses 1..31.
QList<QPair<QString, int>> fullLine(const QStringList &families)
{
    QList<QPair<QString, int>> devices;
    for (int a = 1; a <= 31; ++a)
        devices << qMakePair(families.at((a - 1) % families.size()), a);
    return devices;
}

// Adds the devices, every faceplate shown by the view as on the HMI's overview.
QList<DeviceId> addShowingFaceplates(Line &line, const QList<QPair<QString, int>> &devices, QObject &view)
{
    QList<DeviceId> ids;
    for (const auto &[family, address] : devices) {
        ids << line.bus->addDevice(families().family(family), quint8(address));
        line.bus->shownEntries()->setShown(&view, ids.last(), line.bus->deviceMap(ids.last())->faceplateEntries(false));
    }
    return ids;
}

} // namespace

class tst_Scheduler : public QObject
{
    Q_OBJECT

private slots:
    void classDeadlinesHoldOnAFullLine_data();
    void classDeadlinesHoldOnAFullLine();
    void keepaliveAndPollsHoldDuringScanAndRestore();
    void jobsTakeOnlyTheirShareOfLineTime();
    void shownEntryMovesUpAClassAndBack();
    void settingsAreReadAtOnceAfterAWrite();
    void settingsAreReadSoonAfterAWriteOnAFullLine();
    void actionIsSentOnceAndEndsUnknown();
    void valueIsRepeatedAfterALostAnswer();
    void answerThatDoesNotFitIsNoConfirmation();
    void quietTimeAfterATimeout();
    void operatorWriteGoesNext();
    void jobsAndPollsTakeTurns();
    void lineLossMakesEverythingUnknownAtOnce();
    void valuesTurnStaleWhenNotRead();
    void shownValuesTurnStaleSoonOnAFullLine();
    void offlineDeviceIsUnknownAndComesBack();
    void deviceThatNeverAnswersIsOfflineAfterItsRetries();
    void aCycleReadsEveryBlock();
    void aLostAnswerDoesNotHoldUpTheAlarmWords();
    void earlySettingsKeepThePollInterval();
    void bitChangeKeepsTheOtherBits_data();
    void bitChangeKeepsTheOtherBits();
    void bitChangeRefusedWhereStateIsUnreported();
    void exception02IsolatesTheMissingEntry();
    void broadcastNeverReadsBackFromAddressZero();
    void keepaliveHoldsWhileBitChangesAreRepeated_data();
    void keepaliveHoldsWhileBitChangesAreRepeated();
    void writeUnderWayWhenTheLineReopensIsUnknown_data();
    void writeUnderWayWhenTheLineReopensIsUnknown();
    void broadcastWhoseOnlyReaderGoesIsNotConfirmed();
};

void tst_Scheduler::classDeadlinesHoldOnAFullLine_data()
{
    QTest::addColumn<int>("baud");
    QTest::addColumn<QStringList>("families");
    QTest::addColumn<int>("alarmMs");       // the longest an alarm word may go unread
    QTest::addColumn<bool>("faceplates");   // every faceplate shown, as on the HMI's overview
    QTest::addColumn<int>("faceplateMs");   // the longest a faceplate value may go unread
    QTest::addColumn<int>("faceplateP99Ms"); // its age, sampled every second, at the 99th percentile (-1: not checked)
    QTest::addColumn<bool>("everyMinute");  // every readable entry read at least every minute
    const QStringList three{"ipc300", "tya200", "dtron300"};
    const QStringList four{"ipc300", "tya200", "dtron300", "quantrol"};
    QTest::newRow("38400, IPC 300, TYA 200, dTRON 300") << 38400 << three << 1500 << false << 60000 << -1 << true;
    QTest::newRow("19200, all four families") << 19200 << four << 2500 << false << 60000 << -1 << true;
    // Every faceplate shown: its setpoints are read as live values, and its live values
    // at a target of their own (3 s), after the alarm words and, with settings and
    // whatever reached the ceiling, the most overdue first. Alarm words and faceplates
    // overfill a line of 31 devices at 38400 (about 60 % of the line for the alarm words
    // every second, 62 faceplate blocks): the faceplates get what the alarm words and the
    // settings leave. These are the longest times, not percentiles (before the faceplates
    // had a target of their own: alarm 2.3 s and faceplate 23 s at 38400).
    QTest::newRow("38400, faceplates shown") << 38400 << three << 1500 << true << 10000 << 3000 << true;
    QTest::newRow("19200, all four families, faceplates shown") << 19200 << four << 2500 << true << 45000 << -1 << false;
}

void tst_Scheduler::classDeadlinesHoldOnAFullLine()
{
    // Whole maps of 31 devices, no selection: alarm words are read every round, settings
    // once a minute, live values in between, and every value stays current.
    QFETCH(int, baud);
    QFETCH(QStringList, families);
    QFETCH(int, alarmMs);
    QFETCH(bool, faceplates);
    QFETCH(int, faceplateMs);
    QFETCH(int, faceplateP99Ms);
    QFETCH(bool, everyMinute);
    const QList<QPair<QString, int>> devices = fullLine(families);
    Line line(devices, baud);
    QVERIFY(line.bus->open());
    QList<DeviceId> ids;
    QObject overview;
    for (const auto &[family, address] : devices) {
        ids << line.bus->addDevice(jumo::test::families().family(family), quint8(address));
        if (faceplates)
            line.bus->shownEntries()->setShown(&overview, ids.last(), line.bus->deviceMap(ids.last())->faceplateEntries(false));
    }
    // When each value was stored as read: what the views and the publisher get.
    QHash<QString, QList<qint64>> reads;
    QObject::connect(line.bus.get(), &Bus::entriesUpdated, line.bus.get(), [&](DeviceId id, const QStringList &entries) {
        for (const QString &e : entries) {
            const EntryState *s = line.bus->entryState(id, e);
            if (s && s->validity == Validity::Current && s->goodMs == line.clock.nowMs())
                reads[QStringLiteral("%1@%2").arg(e).arg(line.bus->deviceAddress(id))] << s->goodMs;
        }
    });
    const qint64 from = 70000;   // after the first reads of everything and a minute more
    const qint64 to = 200000;
    line.run(to);

    QHash<PollClass, qint64> longest;
    QHash<PollClass, qint64> shortest;
    qint64 longestFaceplate = 0;
    QList<qint64> faceplateAges;
    QStringList failures;   // (checked after the figures are printed)
    const auto check = [&failures](bool ok, const QString &what) {
        if (!ok)
            failures << what;
    };
    for (int i = 0; i < ids.size(); ++i) {
        const auto map = line.bus->deviceMap(ids[i]);
        for (const RegisterEntry &e : map->entries()) {
            if (!e.isReadable() || !e.alias.isEmpty())
                continue;
            const QList<qint64> times = reads.value(QStringLiteral("%1@%2").arg(e.id).arg(devices[i].second));
            const qint64 unread = longestUnread(times, from, to);
            const QString where = QStringLiteral("%1@%2 %3 (%4)").arg(map->family).arg(devices[i].second).arg(e.id, pollClassName(e.pollClass));
            // Every readable entry at least every minute.
            if (everyMinute)
                check(unread <= 60000, QStringLiteral("%1 unread for %2 ms").arg(where).arg(unread));
            if (e.pollClass == PollClass::Alarm)
                check(unread <= alarmMs, QStringLiteral("%1 unread for %2 ms").arg(where).arg(unread));
            if (map->faceplateEntries(false).contains(e.id)) {
                check(unread <= faceplateMs, QStringLiteral("%1 (faceplate) unread for %2 ms").arg(where).arg(unread));
                longestFaceplate = std::max(longestFaceplate, unread);
                faceplateAges += sampledAges(times, from, to);
            }
            longest[e.pollClass] = std::max(longest.value(e.pollClass), unread);
            // (A shown setting is read as a live value: not counted as a setting.)
            if (!faceplates || !map->faceplateEntries(false).contains(e.id))
                shortest[e.pollClass] = std::min(shortest.value(e.pollClass, std::numeric_limits<qint64>::max()),
                                                 shortestInterval(times, from));

            // Validity follows the class: nothing went stale on the way.
            const EntryState *s = line.bus->entryState(ids[i], e.id);
            if (everyMinute)
                check(s && s->validity == Validity::Current, where + QStringLiteral(" is not current"));
        }
    }
    // Settings are not read more often than their class allows (the line time goes to the
    // rest): early only where the line had time.
    check(shortest.value(PollClass::Setting) >= DevicePoll::settingEarlyMs,
          QStringLiteral("a setting read again after %1 ms").arg(shortest.value(PollClass::Setting)));
    // The power units kept their keepalive.
    for (int i = 0; i < devices.size(); ++i) {
        if (devices[i].first == "ipc300" || devices[i].first == "tya200") {
            const qint64 gap = longestGap(*line.transport, quint8(devices[i].second), from, to);
            check(gap < 4000, QStringLiteral("%1 ms between two requests to %2").arg(gap).arg(devices[i].second));
        }
    }
    // What the line's time went to, by the class each request read.
    QMap<QString, double> share;
    {
        const auto &sent = line.transport->sent;
        for (qsizetype k = 1; k < sent.size(); ++k) {
            if (sent[k - 1].atMs < from)
                continue;
            const ModbusRequest &r = sent[k - 1].request;
            const int dev = r.slave - 1;
            QString c = QStringLiteral("other");
            if (dev >= 0 && dev < ids.size()) {
                const auto map = line.bus->deviceMap(ids[dev]);
                if (const RegisterEntry *e = map->entryAt(r.start)) {
                    const PollClass pc = line.bus->pollClass(ids[dev], e->id);
                    c = pollClassName(pc) + (pc == PollClass::Live && map->faceplateEntries(false).contains(e->id) ? QStringLiteral(" (faceplates)") : QString());
                }
            }
            share[c] += sent[k].atMs - sent[k - 1].atMs;
        }
    }
    QStringList shares;
    for (auto it = share.cbegin(); it != share.cend(); ++it)
        shares << QStringLiteral("%1 %2 %").arg(it.key()).arg(100.0 * it.value() / double(to - from), 0, 'f', 1);
    std::sort(faceplateAges.begin(), faceplateAges.end());
    const qint64 faceplateP99 = faceplateAges.isEmpty() ? 0 : faceplateAges.at(faceplateAges.size() * 99 / 100);
    qInfo("longest unread: alarm %lld ms, faceplate %lld ms (sampled age p99 %lld ms), live %lld ms, setting %lld ms; "
          "%lld requests in %lld s; line time: %s",
          longest.value(PollClass::Alarm), longestFaceplate, faceplateP99, longest.value(PollClass::Live),
          longest.value(PollClass::Setting), qint64(line.transport->sent.size()), to / 1000,
          qPrintable(shares.join(QStringLiteral(", "))));
    check(faceplateP99Ms < 0 || faceplateP99 <= faceplateP99Ms, QStringLiteral("faceplate age p99 %1 ms").arg(faceplateP99));
    QVERIFY2(failures.isEmpty(), qPrintable(QStringLiteral("%1 (%2 in all)").arg(failures.mid(0, 5).join(QStringLiteral("; "))).arg(failures.size())));
}

void tst_Scheduler::keepaliveAndPollsHoldDuringScanAndRestore()
{
    Line line({{"ipc300", 1}, {"tya200", 2}, {"dtron300", 4}});
    QVERIFY(line.bus->open());
    const DeviceId ipc = line.bus->addDevice(families().family("ipc300"), 1);
    const DeviceId tya = line.bus->addDevice(families().family("tya200"), 2);
    const DeviceId dtron = line.bus->addDevice(families().family("dtron300"), 4);
    line.bus->setPollEntries(dtron, {"filtered_process_value"});
    // The IPC 300 is polled only every 20 s: its keepalive must come from the scheduler.
    line.bus->setPollInterval(ipc, 20000);
    QHash<DeviceId, QList<qint64>> cycles;
    QObject::connect(line.bus.get(), &Bus::pollCycleFinished, line.bus.get(),
                     [&](DeviceId id, double) { cycles[id] << line.clock.nowMs(); });
    line.run(3000);

    // 76 parameters of the dTRON restored (each written and read back) and the whole
    // address range scanned, both at once, while the IPC 300 and the TYA 200 are monitored.
    const auto map = families().family("dtron300");
    QList<ParameterDifference> differences;
    for (const QString &id : ParameterSet::parameterIds(*map)) {
        const RegisterEntry *e = map->entry(id);
        QList<quint16> words;
        for (int i = 0; i < e->wordCount(); ++i)
            words << line.sim(4)->word(quint16(e->address + i));
        differences << ParameterDifference{id, e->label, e->unit, {}, ValueCodec::exactText(*e, *map, words), {}, {}};
    }
    QCOMPARE(differences.size(), 76);
    ParameterWriteJob restore(line.bus.get(), dtron);
    DeviceScanner scan(*line.bus, families().families());
    QList<int> found;
    connect(&scan, &DeviceScanner::found, this, [&](int address) { found << address; });
    const qint64 start = line.clock.nowMs();
    restore.start(differences);
    scan.start(1, 247);
    QVERIFY(line.runUntil([&] { return !restore.isRunning() && !scan.isRunning(); }, 3600 * 1000));
    const qint64 end = line.clock.nowMs();
    QCOMPARE(restore.result(), Job::Result::Succeeded);
    QCOMPARE(restore.succeeded(), 76);
    QCOMPARE(scan.result(), Job::Result::Succeeded);
    QCOMPARE(found, QList<int>({1, 2, 4}));
    QVERIFY2(end - start > 60 * 1000, "the jobs ran for minutes of line time");
    qInfo("scan and restore: %lld s of line time, %lld requests", (end - start) / 1000, qint64(line.transport->sent.size()));

    // Neither power unit was left without a telegram for 5 s, and their polls went on.
    for (quint8 slave : {quint8(1), quint8(2)}) {
        const qint64 gap = longestGap(*line.transport, slave, start, end);
        QVERIFY2(gap < 5000, qPrintable(QStringLiteral("slave %1 silent for %2 ms").arg(slave).arg(gap)));
    }
    for (DeviceId id : {ipc, tya}) {
        qint64 last = start;
        for (qint64 t : cycles.value(id)) {
            if (t < start)
                continue;
            QVERIFY2(t - last < 25000, qPrintable(QStringLiteral("no poll cycle of device %1 for %2 ms").arg(id).arg(t - last)));
            last = t;
        }
        QVERIFY(end - last < 25000);
    }
}

void tst_Scheduler::jobsTakeOnlyTheirShareOfLineTime()
{
    // A probe of a silent address costs its timeout and as long again in quiet; a poll a
    // few ms. Taking turns by request would leave the polls a fraction of the line.
    Line line({{"ipc300", 1}});
    QVERIFY(line.bus->open());
    line.bus->addDevice(families().family("ipc300"), 1);
    line.run(2000);
    for (int i = 0; i < 40; ++i)
        line.bus->probe(quint8(100 + i), 0x0000, 1, families().family("dtron300")->protocol);
    const qsizetype first = line.transport->sent.size();
    const qint64 start = line.clock.nowMs();
    line.run(10000);
    const QList<FakeTransport::Sent> &sent = line.transport->sent;
    qint64 pollMs = 0;
    qint64 jobMs = 0;
    for (qsizetype i = first; i + 1 < sent.size(); ++i)
        (sent[i].request.slave >= 100 ? jobMs : pollMs) += sent[i + 1].atMs - sent[i].atMs;
    QVERIFY2(jobMs > 0 && pollMs >= jobMs * 8 / 10,
             qPrintable(QStringLiteral("polls %1 ms, jobs %2 ms of %3 ms").arg(pollMs).arg(jobMs).arg(line.clock.nowMs() - start)));
}

void tst_Scheduler::shownEntryMovesUpAClassAndBack()
{
    // A view shows a setting and a live value through the model it uses: while shown the
    // setting is read as a live value, and the live value stays one (read ahead of the
    // others at a target of its own: classDeadlinesHoldOnAFullLine); hidden, they are what
    // their map says again. A view that goes shows nothing any more.
    Line line({{"ipc300", 1}});
    QVERIFY(line.bus->open());
    const DeviceId id = line.bus->addDevice(families().family("ipc300"), 1);
    LiveValuesModel values(line.bus.get(), id);
    QHash<QString, int> reads;
    QObject::connect(line.bus.get(), &Bus::entriesUpdated, line.bus.get(), [&](DeviceId, const QStringList &entries) {
        for (const QString &e : entries) {
            if (line.bus->entryState(id, e)->goodMs == line.clock.nowMs())
                ++reads[e];
        }
    });
    line.run(3000);
    QCOMPARE(line.bus->pollClass(id, "load_voltage_limit"), PollClass::Setting);
    QCOMPARE(line.bus->pollClass(id, "load_voltage"), PollClass::Live);

    QObject view;
    values.setShown(&view, true, {"load_voltage_limit", "load_voltage"});
    QCOMPARE(line.bus->pollClass(id, "load_voltage_limit"), PollClass::Live);
    QCOMPARE(line.bus->pollClass(id, "load_voltage"), PollClass::Live);
    reads.clear();
    line.run(5000);
    QVERIFY2(reads.value("load_voltage_limit") >= 5, qPrintable(QString::number(reads.value("load_voltage_limit"))));
    QVERIFY2(reads.value("load_voltage") >= 5, qPrintable(QString::number(reads.value("load_voltage"))));

    values.setShown(&view, false);
    QCOMPARE(line.bus->pollClass(id, "load_voltage_limit"), PollClass::Setting);
    QCOMPARE(line.bus->pollClass(id, "load_voltage"), PollClass::Live);
    reads.clear();
    line.run(10000);   // (the setting block, read at the start, is read early from 20 s of age)
    QCOMPARE(reads.value("load_voltage_limit"), 0);
    QVERIFY(reads.value("load_voltage") > 10);
    // Moved back, the setting is as current as a setting read then.
    QCOMPARE(line.bus->entryState(id, "load_voltage_limit")->validity, Validity::Current);

    {
        QObject shortLived;
        values.setShown(&shortLived, true, {"load_voltage_limit"});
        QCOMPARE(line.bus->pollClass(id, "load_voltage_limit"), PollClass::Live);
    }
    QCOMPARE(line.bus->pollClass(id, "load_voltage_limit"), PollClass::Setting);
}

void tst_Scheduler::settingsAreReadAtOnceAfterAWrite()
{
    // A write may change more than its own word: the device's settings are read at once,
    // not when their minute is over.
    Line line({{"ipc300", 1}});
    QVERIFY(line.bus->open());
    const DeviceId id = line.bus->addDevice(families().family("ipc300"), 1);
    line.run(5000);
    const qint64 readBefore = line.bus->entryState(id, "load_voltage_limit")->goodMs;
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    line.bus->write(id, "input_setpoint", "12");
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 10000));
    const qint64 written = line.clock.nowMs();
    line.run(1000);
    QVERIFY(readBefore < written - 3000);
    QVERIFY2(line.bus->entryState(id, "load_voltage_limit")->goodMs > written - 100,
             qPrintable(QString::number(line.bus->entryState(id, "load_voltage_limit")->goodMs - written)));
}

void tst_Scheduler::settingsAreReadSoonAfterAWriteOnAFullLine()
{
    // Every faceplate of 31 devices shown, so the shown values are always late: the
    // settings asked for after a write still go ahead of them.
    const QList<QPair<QString, int>> devices = fullLine({"ipc300", "tya200", "dtron300"});
    Line line(devices, 38400);
    QVERIFY(line.bus->open());
    QObject overview;
    const DeviceId ipc = addShowingFaceplates(line, devices, overview).constFirst();   // ipc300@1
    line.run(70000);
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    line.bus->write(ipc, "input_setpoint", "12");
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 10000));
    const qint64 written = line.clock.nowMs();
    QVERIFY(line.runUntil([&] { return line.bus->entryState(ipc, "load_voltage_limit")->goodMs > written; }, 60000));
    QVERIFY2(line.clock.nowMs() - written <= 1500, qPrintable(QString::number(line.clock.nowMs() - written)));
}

void tst_Scheduler::actionIsSentOnceAndEndsUnknown()
{
    Line line({{"dtron300", 4}});
    QVERIFY(line.bus->open());
    line.bus->setPolling(false);
    const DeviceId id = line.bus->addDevice(families().family("dtron300"), 4);
    line.transport->drop = [](const ModbusRequest &r) { return r.isWrite(); };
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    line.bus->write(id, "program_controller_functions", "segment_change");
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 60000));
    line.run(5000);
    // The device may well have changed the segment: never a second frame.
    QCOMPARE(line.transport->count(4, 0x06, 0x006F), 1);
    const auto outcome = finished.at(0).at(1).value<WriteOutcome>();
    QCOMPARE(outcome.result, WriteOutcome::Result::Unknown);
    QVERIFY2(outcome.message.contains("not sent again"), qPrintable(outcome.message));
}

void tst_Scheduler::valueIsRepeatedAfterALostAnswer()
{
    Line line({{"dtron300", 4}});
    QVERIFY(line.bus->open());
    line.bus->setPolling(false);
    const DeviceId id = line.bus->addDevice(families().family("dtron300"), 4);
    int dropped = 0;
    line.transport->drop = [&dropped](const ModbusRequest &r) { return r.isWrite() && dropped++ == 0; };
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    line.bus->write(id, "setpoint", "42.5");
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 60000));
    QCOMPARE(finished.at(0).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Confirmed);
    QCOMPARE(line.transport->count(4, 0x10, 0x0047), 2);

    // Every answer lost: repeated up to the retries, then unknown, never "failed".
    line.transport->drop = [](const ModbusRequest &r) { return r.isWrite(); };
    line.bus->write(id, "setpoint", "43");
    QVERIFY(line.runUntil([&] { return finished.count() == 2; }, 60000));
    QCOMPARE(finished.at(1).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Unknown);
    QCOMPARE(line.transport->count(4, 0x10, 0x0047), 2 + 1 + line.bus->settings().retries);
}

void tst_Scheduler::answerThatDoesNotFitIsNoConfirmation()
{
    // An echo of something else (RtuTransport's BadReply) came back: the device may have
    // carried the write out. An action goes out once; a value is repeated like after a
    // lost answer; either ends unknown, and the message says what came back, not that
    // nothing did.
    Line line({{"dtron300", 4}});
    QVERIFY(line.bus->open());
    line.bus->setPolling(false);
    const DeviceId id = line.bus->addDevice(families().family("dtron300"), 4);
    line.transport->misfit = [](const ModbusRequest &r) { return r.isWrite(); };
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    line.bus->write(id, "program_controller_functions", "segment_change");
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 60000));
    line.run(5000);
    QCOMPARE(line.transport->count(4, 0x06, 0x006F), 1);
    auto outcome = finished.at(0).at(1).value<WriteOutcome>();
    QCOMPARE(outcome.result, WriteOutcome::Result::Unknown);
    QVERIFY2(outcome.message.contains("not sent again"), qPrintable(outcome.message));
    QVERIFY2(!outcome.message.startsWith("no answer"), qPrintable(outcome.message));
    QVERIFY2(outcome.message.contains("write reply names 1 word(s) at 7"), qPrintable(outcome.message));

    line.bus->write(id, "setpoint", "43");
    QVERIFY(line.runUntil([&] { return finished.count() == 2; }, 60000));
    outcome = finished.at(1).at(1).value<WriteOutcome>();
    QCOMPARE(outcome.result, WriteOutcome::Result::Unknown);
    QCOMPARE(line.transport->count(4, 0x10, 0x0047), 1 + line.bus->settings().retries);
    QVERIFY2(!outcome.message.startsWith("no answer"), qPrintable(outcome.message));
    QVERIFY2(outcome.message.contains("write reply names 1 word(s) at 7"), qPrintable(outcome.message));
}

void tst_Scheduler::quietTimeAfterATimeout()
{
    Line line({{"ipc300", 1}});
    QVERIFY(line.bus->open());
    const DeviceId id = line.bus->addDevice(families().family("ipc300"), 1);
    line.bus->setPollEntries(id, {"load_current"});
    int reads = 0;
    line.transport->drop = [&reads](const ModbusRequest &r) { return !r.isWrite() && ++reads == 3; };
    line.run(5000);
    const QList<FakeTransport::Sent> &sent = line.transport->sent;
    QVERIFY(sent.size() > 5);
    // The third read got no answer: nothing goes out for its timeout, then as long again,
    // so a late answer cannot be taken for the next request's.
    const qint64 timeout = sent[2].request.timeoutMs;
    QVERIFY(sent[3].atMs - sent[2].atMs >= 2 * timeout);
    QVERIFY(sent[1].atMs - sent[0].atMs < timeout);
    QCOMPARE(line.bus->entryState(id, "load_current")->validity, Validity::Current);
}

void tst_Scheduler::operatorWriteGoesNext()
{
    Line line({{"ipc300", 1}});
    QVERIFY(line.bus->open());
    const DeviceId id = line.bus->addDevice(families().family("ipc300"), 1);
    line.run(2000);
    for (int i = 0; i < 20; ++i)
        line.bus->probe(quint8(20 + i), 0x0000, 1, families().family("ipc300")->protocol);
    line.run(1000);
    const qsizetype before = line.transport->sent.size();
    line.bus->write(id, "input_setpoint", "12");
    line.run(2000);
    // At most the request under way goes before it.
    bool nextOrSecond = false;
    for (qsizetype i = before; i < std::min(before + 2, line.transport->sent.size()); ++i)
        nextOrSecond = nextOrSecond || line.transport->sent[i].request.isWrite();
    QVERIFY(nextOrSecond);
}

void tst_Scheduler::jobsAndPollsTakeTurns()
{
    Line line({{"ipc300", 1}});
    QVERIFY(line.bus->open());
    line.bus->addDevice(families().family("ipc300"), 1);
    line.run(2000);
    for (int i = 0; i < 30; ++i)
        line.bus->probe(quint8(100 + i), 0x0000, 1, families().family("ipc300")->protocol);
    const qsizetype first = line.transport->sent.size();
    line.run(20000);
    // Between two job requests there is always a poll while the device is monitored.
    int jobsInARow = 0;
    int jobs = 0;
    for (qsizetype i = first; i < line.transport->sent.size(); ++i) {
        const bool job = line.transport->sent[i].request.slave >= 100;
        if (job && ++jobsInARow > 2)   // a probe and its repeat after a lost answer
            QFAIL("the job lane took more than its turns");
        if (!job)
            jobsInARow = 0;
        jobs += job;
    }
    QVERIFY(jobs >= 10);
}

void tst_Scheduler::lineLossMakesEverythingUnknownAtOnce()
{
    Line line({{"ipc300", 1}, {"dtron300", 4}});
    QVERIFY(line.bus->open());
    const DeviceId ipc = line.bus->addDevice(families().family("ipc300"), 1);
    const DeviceId dtron = line.bus->addDevice(families().family("dtron300"), 4);
    line.run(5000);
    QCOMPARE(line.bus->entryState(ipc, "load_voltage")->validity, Validity::Current);
    QCOMPARE(line.bus->entryState(dtron, "setpoint")->validity, Validity::Current);
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    QSignalSpy conditions(line.bus.get(), &Bus::conditionChanged);
    line.transport->drop = [](const ModbusRequest &r) { return r.isWrite(); };
    line.bus->write(ipc, "input_setpoint", "30");
    line.bus->write(dtron, "setpoint", "30");
    line.runUntil([&] { return line.transport->count(1, 0x10) >= 1; }, 5000);

    line.transport->pull();
    // At the same moment: every value unknown, both devices "line lost".
    for (DeviceId id : {ipc, dtron}) {
        const auto map = line.bus->deviceMap(id);
        for (const RegisterEntry &e : map->entries()) {
            if (const EntryState *s = line.bus->entryState(id, e.id)) {
                QVERIFY2(s->validity == Validity::Unknown, qPrintable(e.id));
                QVERIFY(s->error == ReadError::LineLost || s->error == ReadError::NotAvailable);
            }
        }
        QCOMPARE(line.bus->condition(id).state, DeviceCondition::State::LineLost);
    }
    QVERIFY(conditions.count() >= 2);
    line.run(100);
    QCOMPARE(finished.count(), 2);
    // The write under way may have been taken; the queued one never went out.
    QCOMPARE(finished.at(0).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Unknown);
    QCOMPARE(finished.at(1).at(1).value<WriteOutcome>().result, WriteOutcome::Result::NotSent);

    // The port comes back: values turn current again, nothing asked before is replayed.
    line.transport->drop = nullptr;
    const int writes = line.transport->count(4, 0x10);
    line.run(3000);
    QCOMPARE(line.bus->state(), LineState::Connected);
    QTRY_COMPARE_WITH_TIMEOUT(line.bus->entryState(ipc, "load_voltage")->validity, Validity::Current, 1);
    // Settings too: a reconnect reads everything at once.
    QCOMPARE(line.bus->entryState(ipc, "load_voltage_limit")->validity, Validity::Current);
    QCOMPARE(line.bus->entryState(dtron, "ps1_pb1")->validity, Validity::Current);
    QCOMPARE(line.transport->count(4, 0x10), writes);
}

void tst_Scheduler::valuesTurnStaleWhenNotRead()
{
    // Validity follows the class: a live value is stale seconds after its reads stop, a
    // setting (read once a minute) only after about two minutes.
    Line line({{"quantrol", 3}});
    QVERIFY(line.bus->open());
    const DeviceId id = line.bus->addDevice(families().family("quantrol"), 3);
    line.run(3000);
    QCOMPARE(line.bus->entryState(id, "actual_value_filtered")->validity, Validity::Current);
    QCOMPARE(line.bus->entryState(id, "controller_setpoint")->validity, Validity::Current);
    line.bus->setPolling(false);
    line.run(1000);
    QCOMPARE(line.bus->entryState(id, "actual_value_filtered")->validity, Validity::Current);
    line.run(10000);
    QCOMPARE(line.bus->entryState(id, "actual_value_filtered")->validity, Validity::Stale);
    QCOMPARE(line.bus->entryState(id, "actual_value_filtered")->statusName(), QString("stale"));
    QCOMPARE(line.bus->entryState(id, "controller_setpoint")->validity, Validity::Current);
    line.run(2 * DevicePoll::settingTargetMs);
    QCOMPARE(line.bus->entryState(id, "controller_setpoint")->validity, Validity::Stale);
}

void tst_Scheduler::shownValuesTurnStaleSoonOnAFullLine()
{
    // On a full line the live values nobody shows are read about once a minute and stay
    // current for two; a faceplate's live values are read every few seconds, and when
    // their reads stop they turn stale within seconds, not with the others.
    const QList<QPair<QString, int>> devices = fullLine({"ipc300", "tya200", "dtron300"});
    Line line(devices, 38400);
    QVERIFY(line.bus->open());
    QObject overview;
    const DeviceId ipc = addShowingFaceplates(line, devices, overview).constFirst();   // ipc300@1
    const QStringList faceplate = line.bus->deviceMap(ipc)->faceplateEntries(false);
    QVERIFY(faceplate.contains("load_voltage") && !faceplate.contains("controller_output_level"));
    QCOMPARE(line.bus->pollClass(ipc, "controller_output_level"), PollClass::Live);
    line.run(130000);
    QCOMPARE(line.bus->entryState(ipc, "load_voltage")->validity, Validity::Current);
    QCOMPARE(line.bus->entryState(ipc, "controller_output_level")->validity, Validity::Current);
    line.bus->setPolling(false);
    line.run(25000);
    QCOMPARE(line.bus->entryState(ipc, "load_voltage")->validity, Validity::Stale);
    QCOMPARE(line.bus->entryState(ipc, "controller_output_level")->validity, Validity::Current);
}

void tst_Scheduler::offlineDeviceIsUnknownAndComesBack()
{
    Line line({{"ipc300", 1}, {"quantrol", 3}});
    QVERIFY(line.bus->open());
    const DeviceId ipc = line.bus->addDevice(families().family("ipc300"), 1);
    const DeviceId quantrol = line.bus->addDevice(families().family("quantrol"), 3);
    line.run(3000);
    bool dead = true;
    line.transport->drop = [&dead](const ModbusRequest &r) { return dead && r.slave == 3; };
    line.runUntil([&] { return !line.bus->isOnline(quantrol); }, 30000);
    QCOMPARE(line.bus->condition(quantrol).state, DeviceCondition::State::Offline);
    QCOMPARE(line.bus->entryState(quantrol, "controller_setpoint")->validity, Validity::Unknown);
    QCOMPARE(line.bus->entryState(quantrol, "controller_setpoint")->error, ReadError::DeviceOffline);
    QCOMPARE(line.bus->entryState(ipc, "load_voltage")->validity, Validity::Current);
    // Probed with its shortest read: a probe of a silent device costs its timeout.
    const qsizetype offlineAt = line.transport->sent.size();
    line.run(20000);
    int probes = 0;
    for (qsizetype i = offlineAt; i < line.transport->sent.size(); ++i) {
        const ModbusRequest &r = line.transport->sent[i].request;
        if (r.slave == 3) {
            ++probes;
            QCOMPARE(r.count, quint16(1));
        }
    }
    QVERIFY(probes >= 2);
    dead = false;
    QVERIFY(line.runUntil([&] { return line.bus->isOnline(quantrol); }, 60000));
    line.run(3000);
    QCOMPARE(line.bus->entryState(quantrol, "controller_setpoint")->validity, Validity::Current);
}

void tst_Scheduler::deviceThatNeverAnswersIsOfflineAfterItsRetries()
{
    // A dTRON (16 blocks) that is not there from the start, identities checked: the block
    // whose answer was lost is asked again first, so the device is offline after two
    // blocks have failed with their retries, not once each of its blocks has timed out;
    // and a timeout is no reason to check what the device is.
    Line line({{"ipc300", 1}}, 19200);
    line.bus->setIdentityCheck({families().family("ipc300"), families().family("dtron300")});
    QVERIFY(line.bus->open());
    line.transport->drop = [](const ModbusRequest &r) { return r.slave == 7; };
    line.bus->addDevice(families().family("ipc300"), 1);
    const DeviceId dtron = line.bus->addDevice(families().family("dtron300"), 7);
    QVERIFY(line.runUntil([&] { return line.bus->condition(dtron).state == DeviceCondition::State::Offline; }, 120000));
    QList<quint16> asked;
    for (const auto &sent : line.transport->sent) {
        if (sent.request.slave == 7)
            asked << sent.request.start;
    }
    const int attempts = DevicePoll::failuresBeforeOffline * (BusSettings().retries + 1);
    QVERIFY2(asked.size() == attempts, qPrintable(QStringLiteral("%1 requests before offline after %2 ms")
                                                           .arg(asked.size())
                                                           .arg(line.clock.nowMs())));
    // Each block with its retries in a row.
    for (int i = 0; i < asked.size(); ++i)
        QCOMPARE(asked[i], asked[i - i % (BusSettings().retries + 1)]);
    QVERIFY2(line.clock.nowMs() < 15000, qPrintable(QString::number(line.clock.nowMs())));
}

void tst_Scheduler::aCycleReadsEveryBlock()
{
    // A selection in three blocks (jumoctl monitor): each cycle it reports is three reads,
    // the block that ended one cycle not counted for the next.
    Line line({{"ipc300", 1}}, 38400);
    QVERIFY(line.bus->open());
    const DeviceId id = line.bus->addDevice(families().family("ipc300"), 1);
    line.bus->setPollEntries(id, {"software_version", "load_voltage", "min_alarm"});
    QList<qsizetype> ends;
    QObject::connect(line.bus.get(), &Bus::pollCycleFinished, line.bus.get(),
                     [&] { ends << line.transport->sent.size(); });
    line.run(3000);
    QVERIFY(ends.size() >= 5);
    for (int i = 1; i < ends.size(); ++i)
        QCOMPARE(ends[i] - ends[i - 1], qsizetype(3));
}

void tst_Scheduler::aLostAnswerDoesNotHoldUpTheAlarmWords()
{
    // A full line, every faceplate shown: one answer of a dTRON's faceplate block is lost.
    // Its retry takes the device's most urgent place, so the device's alarm words keep
    // their deadline (the retry once waited in the tier of the live values, which a full
    // line does not serve: the device was not asked again for minutes).
    const QList<QPair<QString, int>> devices = fullLine({"ipc300", "tya200", "dtron300", "quantrol"});
    Line line(devices, 19200);
    QVERIFY(line.bus->open());
    QObject overview;
    const QList<DeviceId> ids = addShowingFaceplates(line, devices, overview);
    line.run(70000);
    const quint16 alarmWords = line.sim(3)->map().entry("program_status")->address;
    bool lost = false;
    line.transport->drop = [&lost, alarmWords](const ModbusRequest &r) {
        if (lost || r.slave != 3 || r.start == alarmWords)
            return false;
        lost = true;
        return true;
    };
    const qint64 from = line.clock.nowMs();
    line.run(30000);
    QVERIFY(lost);
    QVERIFY(line.bus->isOnline(ids.at(2)));
    const qint64 gap = longestGap(*line.transport, 3, from, line.clock.nowMs());
    QVERIFY2(gap < 3000, qPrintable(QStringLiteral("dtron300@3 not asked for %1 ms").arg(gap)));
    const EntryState *alarms = line.bus->entryState(ids.at(2), "program_status");
    QVERIFY(alarms && alarms->validity == Validity::Current);
}

void tst_Scheduler::earlySettingsKeepThePollInterval()
{
    // Settings are read early where the line has time, but never more often than the
    // device's poll interval (jumoctl monitor --interval).
    Line line({{"ipc300", 1}}, 38400);
    QVERIFY(line.bus->open());
    const DeviceId ipc = line.bus->addDevice(families().family("ipc300"), 1);
    line.bus->setPollInterval(ipc, 40000);
    QList<qint64> reads;
    QObject::connect(line.bus.get(), &Bus::entriesUpdated, line.bus.get(), [&](DeviceId, const QStringList &entries) {
        if (entries.contains("load_voltage_limit") && line.bus->entryState(ipc, "load_voltage_limit")->goodMs == line.clock.nowMs())
            reads << line.clock.nowMs();
    });
    line.run(130000);
    QVERIFY2(reads.size() >= 3, qPrintable(QString::number(reads.size())));
    QVERIFY2(shortestInterval(reads, 0) >= 40000, qPrintable(QString::number(shortestInterval(reads, 0))));
}

void tst_Scheduler::bitChangeKeepsTheOtherBits_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<int>("address");
    QTest::addColumn<QString>("entry");
    QTest::addColumn<QString>("before");   // "entry.bit" or bool entry set on the device first
    QTest::addColumn<QString>("bit");
    QTest::addColumn<QString>("mustStayOn");
    // IPC 300 0x00F1 is write-only: its bits are reported in 0x00EF.
    QTest::newRow("ipc300 0x00F1 from 0x00EF") << "ipc300" << 1 << "binary_signal_write" << "external_inhibit_input"
                                              << "digital_output" << "binary_signal_1.external_inhibit_input";
    // dTRON 0x0027 is read, changed and written back.
    QTest::newRow("dtron300 0x0027 itself") << "dtron300" << 4 << "binary_output_control"
                                            << "binary_output_control.output_2" << "output_1"
                                            << "binary_output_control.output_2";
    QTest::newRow("quantrol 0x0025 itself") << "quantrol" << 3 << "binary_output_control"
                                            << "binary_output_control.output_k2" << "output_k1"
                                            << "binary_output_control.output_k2";
}

void tst_Scheduler::bitChangeKeepsTheOtherBits()
{
    QFETCH(QString, family);
    QFETCH(int, address);
    QFETCH(QString, entry);
    QFETCH(QString, before);
    QFETCH(QString, bit);
    QFETCH(QString, mustStayOn);
    Line line({{family, address}});
    QVERIFY(line.bus->open());
    const DeviceId id = line.bus->addDevice(families().family(family), quint8(address));
    line.run(2000);
    SimulatedDevice *device = line.sim(quint8(address));
    QVERIFY(device->setFlag(before, true));
    if (const RegisterEntry *e = device->map().entry(entry); e->activationMask)
        QVERIFY(device->setWords(e->address, {quint16(device->word(e->address) | *e->activationMask)}));
    // A link is kept by the device itself.
    if (family == "ipc300")
        QVERIFY(device->setFlag("binary_signal_1.external_inhibit_input", true));

    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    const qsizetype first = line.transport->sent.size();
    line.bus->writeBits(id, entry, {{bit, true}});
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 30000));
    const auto outcome = finished.at(0).at(1).value<WriteOutcome>();
    QVERIFY2(outcome.result == WriteOutcome::Result::Confirmed, qPrintable(outcome.message));
    QVERIFY(device->flag(mustStayOn));
    QVERIFY(device->flag(entry + QLatin1Char('.') + bit));

    // The word was read right before the write: nothing in between.
    const RegisterEntry *target = device->map().entry(entry);
    qsizetype write = -1;
    for (qsizetype i = first; i < line.transport->sent.size(); ++i) {
        if (line.transport->sent[i].request.isWrite() && line.transport->sent[i].request.start == target->address)
            write = i;
    }
    QVERIFY(write > first);
    const ModbusRequest &preRead = line.transport->sent[write - 1].request;
    QVERIFY(!preRead.isWrite());
    QCOMPARE(preRead.slave, quint8(address));

    // And off again: only that bit.
    line.bus->writeBits(id, entry, {{bit, false}});
    QVERIFY(line.runUntil([&] { return finished.count() == 2; }, 30000));
    QCOMPARE(finished.at(1).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Confirmed);
    QVERIFY(device->flag(mustStayOn));
    QVERIFY(!device->flag(entry + QLatin1Char('.') + bit));
}

void tst_Scheduler::bitChangeRefusedWhereStateIsUnreported()
{
    Line line({{"quantrol", 3}});
    QVERIFY(line.bus->open());
    const DeviceId id = line.bus->addDevice(families().family("quantrol"), 3);
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    // 0x0048 is write-only and nothing reports its bits: one bit alone would set the others.
    line.bus->writeBits(id, "operation_functions", {{"keyboard_inhibit", true}});
    // An action word has no states to keep.
    line.bus->writeBits(id, "controller_functions", {{"manual_mode", true}});
    // Every bit given: the word is fully known and goes out.
    line.bus->writeBits(id, "operation_functions", {{"keyboard_inhibit", true}, {"level_inhibit", false}, {"display_off", false}});
    QVERIFY(line.runUntil([&] { return finished.count() == 3; }, 30000));
    QCOMPARE(finished.at(0).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Invalid);
    QVERIFY(finished.at(0).at(1).value<WriteOutcome>().message.contains("does not report"));
    QCOMPARE(finished.at(1).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Invalid);
    QCOMPARE(finished.at(2).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Accepted);
    QCOMPARE(line.sim(3)->word(0x0048), quint16(0x0001));
    QCOMPARE(line.transport->count(3, 0x06, 0x0048), 1);
}

void tst_Scheduler::exception02IsolatesTheMissingEntry()
{
    // A smaller model: the device lacks one address the family's map lists.
    const auto full = families().family("dtron300");
    auto smaller = std::make_shared<RegisterMap>(*full);
    QList<RegisterEntry> entries = full->entries();
    const QString missing = QStringLiteral("analog_input_2_mv");
    QVERIFY(full->entry(missing));
    entries.removeIf([&missing](const RegisterEntry &e) { return e.id == missing; });
    smaller->setEntries(entries);
    Line line({});
    line.add(smaller, 4);
    QVERIFY(line.bus->open());
    const DeviceId id = line.bus->addDevice(full, 4);
    QSignalSpy cycles(line.bus.get(), &Bus::pollCycleFinished);
    QVERIFY(line.runUntil([&] { return cycles.count() >= 2; }, 60000));
    QCOMPARE(line.bus->entryState(id, missing)->error, ReadError::NotAvailable);
    QCOMPARE(line.bus->entryState(id, missing)->statusName(), QString("unavailable"));
    int current = 0;
    for (const RegisterEntry &e : full->entries()) {
        const EntryState *s = line.bus->entryState(id, e.id);
        current += s && s->validity == Validity::Current;
    }
    QVERIFY2(current > 100, qPrintable(QString::number(current)));
    // Remembered for the session: later cycles ask no more questions.
    const int exceptions = line.bus->statistics(id)->exceptions.value(2);
    QVERIFY(exceptions > 0 && exceptions < 20);
    line.run(10000);
    QCOMPARE(line.bus->statistics(id)->exceptions.value(2), exceptions);
}

void tst_Scheduler::broadcastNeverReadsBackFromAddressZero()
{
    Line line({{"ipc300", 1}, {"ipc300", 2}});
    QVERIFY(line.bus->open());
    line.bus->setPolling(false);
    line.bus->addDevice(families().family("ipc300"), 1);
    const DeviceId second = line.bus->addDevice(families().family("ipc300"), 2);
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    line.bus->writeBroadcast("ipc300", "input_setpoint", "25");
    line.bus->removeDevice(second);   // before its read-back
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 30000));
    QCOMPARE(finished.at(0).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Confirmed);
    QCOMPARE(line.transport->count(0, 0x10), 1);
    QCOMPARE(line.transport->count(0, 0x03), 0);
    QCOMPARE(line.transport->count(1, 0x03, 0x00D5), 1);
    QCOMPARE(line.transport->count(2, 0x03, 0x00D5), 0);
}

void tst_Scheduler::keepaliveHoldsWhileBitChangesAreRepeated_data()
{
    QTest::addColumn<int>("timeoutMs");
    QTest::addColumn<int>("baud");
    QTest::newRow("derived, 9600") << 0 << 9600;
    QTest::newRow("derived, 19200") << 0 << 19200;
    QTest::newRow("1000 ms, 9600") << 1000 << 9600;   // jumoctl --timeout
    QTest::newRow("2000 ms, 9600") << 2000 << 9600;
}

void tst_Scheduler::keepaliveHoldsWhileBitChangesAreRepeated()
{
    // A bit change holds the line from its pre-read to its write; the repeats of a write
    // whose answer was lost must not hold it too, or the IPC 300 goes without a telegram
    // for every attempt's timeout and quiet gap.
    QFETCH(int, timeoutMs);
    QFETCH(int, baud);
    Line line({{"ipc300", 1}, {"dtron300", 4}}, baud);
    BusSettings settings = line.bus->settings();
    settings.timeoutMs = timeoutMs;
    line.bus->setSettings(settings);
    QVERIFY(line.bus->open());
    const DeviceId ipc = line.bus->addDevice(families().family("ipc300"), 1);
    const DeviceId dtron = line.bus->addDevice(families().family("dtron300"), 4);
    line.bus->setPollInterval(ipc, 20000);   // its keepalive comes from the scheduler
    line.bus->setPollEntries(dtron, {"filtered_process_value"});
    line.run(3000);
    line.transport->drop = [](const ModbusRequest &r) { return r.isWrite() && r.slave == 4; };
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    const qint64 start = line.clock.nowMs();
    for (int i = 0; i < 6; ++i)
        line.bus->writeBits(dtron, "binary_output_control", {{"output_1", i % 2 == 0}});
    QVERIFY(line.runUntil([&] { return finished.count() == 6; }, 600000));
    const qint64 end = line.clock.nowMs();
    for (const QList<QVariant> &args : std::as_const(finished))
        QCOMPARE(args.at(1).value<WriteOutcome>().result, WriteOutcome::Result::Unknown);
    QCOMPARE(line.transport->count(4, 0x06, 0x0027), 6 * (1 + line.bus->settings().retries));
    const qint64 gap = longestGap(*line.transport, 1, start, end);
    QVERIFY2(gap < Scheduler::keepaliveMs(*families().family("ipc300")),
             qPrintable(QStringLiteral("slave 1 silent for %1 ms").arg(gap)));
}

void tst_Scheduler::writeUnderWayWhenTheLineReopensIsUnknown_data()
{
    QTest::addColumn<QString>("entry");
    QTest::addColumn<QString>("value");
    QTest::newRow("command") << "program_controller_functions" << "segment_change";
    QTest::newRow("value") << "setpoint" << "42";
}

void tst_Scheduler::writeUnderWayWhenTheLineReopensIsUnknown()
{
    // The port is opened again while a write frame is out and its answer not yet in. The
    // bus waited for that answer from the old transport forever (nothing was ever sent
    // again); and the frame may have been carried out: unknown, never "not written".
    QFETCH(QString, entry);
    QFETCH(QString, value);
    Line line({{"dtron300", 4}});
    QVERIFY(line.bus->open());
    line.bus->setPolling(false);
    const DeviceId id = line.bus->addDevice(families().family("dtron300"), 4);
    line.transport->drop = [](const ModbusRequest &r) { return r.isWrite(); };
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    line.bus->write(id, entry, value);
    QVERIFY(line.runUntil([&] { return line.transport->count(4, -1, -1) > 0 && line.transport->sent.last().request.isWrite(); },
                          10000));
    QVERIFY(line.bus->open());
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 60000));
    const WriteOutcome outcome = finished.at(0).at(1).value<WriteOutcome>();
    QVERIFY2(outcome.result == WriteOutcome::Result::Unknown, qPrintable(outcome.message));
    int writes = 0;
    for (const FakeTransport::Sent &s : std::as_const(line.transport->sent))
        writes += s.request.isWrite();
    QCOMPARE(writes, 0);   // the new transport sent nothing more: the write is over
}

void tst_Scheduler::broadcastWhoseOnlyReaderGoesIsNotConfirmed()
{
    // The one device to read the broadcast back from is removed while its read-back goes
    // unanswered: nobody confirmed it.
    Line line({{"ipc300", 1}});
    QVERIFY(line.bus->open());
    line.bus->setPolling(false);
    const DeviceId id = line.bus->addDevice(families().family("ipc300"), 1);
    line.transport->drop = [](const ModbusRequest &r) { return !r.isWrite(); };
    QSignalSpy finished(line.bus.get(), &Bus::writeFinished);
    line.bus->writeBroadcast("ipc300", "input_setpoint", "25");
    QVERIFY(line.runUntil([&] { return line.transport->count(1, 0x03, 0x00D5) == 1; }, 30000));
    line.bus->removeDevice(id);
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 30000));
    const WriteOutcome outcome = finished.at(0).at(1).value<WriteOutcome>();
    QVERIFY2(outcome.result == WriteOutcome::Result::Accepted, qPrintable(outcome.message));
    QCOMPARE(line.transport->count(0, 0x10), 1);
}

QTEST_GUILESS_MAIN(tst_Scheduler)
#include "tst_scheduler.moc"
