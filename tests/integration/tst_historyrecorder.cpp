// The recorder on a real Bus polling the simulator over a socat pty pair: the values
// from the first poll, a change as a step at its time, a steady value again every
// heartbeat, a silent device as a gap with its reason, all read back from the SQLite file.
#include "bus/bus.h"
#include "history/historyreader.h"
#include "history/historyrecorder.h"
#include "history/sqlhistorystore.h"
#include "testpeers.h"

#include <QDateTime>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

class tst_HistoryRecorder : public QObject
{
    Q_OBJECT

private slots:
    void recordsStepsAndGapsFromTheBus();
};

void tst_HistoryRecorder::recordsStepsAndGapsFromTheBus()
{
    TestLine line;
    QVERIFY(line.start());
    SimulatorPeer sim;
    const auto map = families().family(QStringLiteral("ipc300"));
    const RegisterEntry *voltage = map->entry(QStringLiteral("load_voltage"));
    QVERIFY(sim.start(line.deviceEnd(), {1}));
    QVERIFY(sim.setWords(1, voltage->address, ValueCodec::encodeFloat(231.5f, map->protocol.floatWordOrder)));

    QTemporaryDir dir;
    const HistoryLocation location = HistoryLocation::file(HistoryLocation::defaultFile(dir.path(), "hall-3"));
    const HistoryKey key{QStringLiteral("hall-3"), QStringLiteral("line1"), QStringLiteral("ipc300@1")};
    const qint64 startMs = QDateTime::currentMSecsSinceEpoch();
    qint64 changedMs = 0;
    qint64 silentMs = 0;
    qint64 backMs = 0;
    {
        Bus bus;
        BusSettings settings;
        settings.portName = line.masterEnd();
        settings.format = testFormat();
        settings.timeoutMs = 300;
        settings.reconnectIntervalMs = 200;
        bus.setSettings(settings);
        const DeviceId id = bus.addDevice(map, 1);
        bus.setPollEntries(id, {voltage->id, QStringLiteral("device_name")});

        HistorySettings historySettings;
        historySettings.heartbeatMs = 2000;
        historySettings.batchIntervalMs = 100;
        SqlHistoryStore store(location, key.station, historySettings);
        QSignalSpy stopped(&store, &HistoryStore::recordingStopped);
        store.start();
        HistoryRecorder recorder(&store);
        recorder.addSource(&bus, key.line);
        QVERIFY(bus.open());

        auto voltageNow = [&] {
            const EntryState *state = bus.entryState(id, voltage->id);
            return state && state->isCurrent() ? state->value.value.toDouble() : qQNaN();
        };
        QTRY_COMPARE_WITH_TIMEOUT(voltageNow(), 231.5, 10000);
        // A steady value is recorded again after a heartbeat.
        QTRY_VERIFY_WITH_TIMEOUT(recorder.samplesRecorded() >= 4, 10000);

        changedMs = QDateTime::currentMSecsSinceEpoch();
        QVERIFY(sim.setWords(1, voltage->address, ValueCodec::encodeFloat(187.5f, map->protocol.floatWordOrder)));
        QTRY_COMPARE_WITH_TIMEOUT(voltageNow(), 187.5, 10000);

        silentMs = QDateTime::currentMSecsSinceEpoch();
        QVERIFY(sim.setFault(1, "dead", -1, 0));
        QTRY_VERIFY_WITH_TIMEOUT(bus.entryState(id, voltage->id)->validity == Validity::Unknown, 15000);
        backMs = QDateTime::currentMSecsSinceEpoch();
        QVERIFY(sim.setFault(1, "none", -1, 0));
        QTRY_COMPARE_WITH_TIMEOUT(voltageNow(), 187.5, 30000);
        bus.close();
        QVERIFY2(stopped.isEmpty(), qPrintable(stopped.value(0).value(0).toString()));
    }
    const qint64 endMs = QDateTime::currentMSecsSinceEpoch();

    HistoryReader reader(location);
    QString error;
    QVERIFY2(reader.open(&error), qPrintable(error));
    QList<HistoryPoint> raw;
    QVERIFY2(reader.records(key, voltage->id, startMs - 1000, endMs + 1000,
                            [&raw](const HistoryRecord &r) {
                                raw.append(r.point);
                                return true;
                            },
                            &error),
             qPrintable(error));
    QVERIFY(raw.size() >= 5);
    // From the first poll: the first sample is the value the device held.
    QCOMPARE(raw.first().state, SampleState::Ok);
    QCOMPARE(raw.first().value, 231.5);
    // Again after the heartbeat, before the change.
    QVERIFY(raw[1].value == 231.5 && raw[1].timeMs - raw[0].timeMs >= 2000);

    HistoryTrace trace = reader.samples(key, voltage->id, startMs - 1000, endMs + 1000, 1000);
    QVERIFY2(trace.ok(), qPrintable(trace.error));
    QList<HistoryPoint> &p = trace.points;
    // Steps: 231.5, then 187.5 from the change on, a gap while the device was silent,
    // 187.5 again, and the end of recording.
    QVERIFY(p.size() >= 5);
    QCOMPARE(p[0].value, 231.5);
    QCOMPARE(p[1].value, 187.5);
    QVERIFY(p[1].timeMs >= changedMs && p[1].timeMs < silentMs + 1000);
    const QList<HistoryGap> gaps = trace.gaps();
    QCOMPARE(gaps.size(), 2);
    QVERIFY(gaps[0].startMs >= silentMs && gaps[0].endMs >= backMs);
    QVERIFY2(gaps[0].state == SampleState::Timeout || gaps[0].state == SampleState::Offline,
             qPrintable(sampleStateName(gaps[0].state)));
    QCOMPARE(gaps[1].state, SampleState::Disconnected);   // the bus closed

    // Text entries are recorded as text.
    const HistoryTrace name = reader.samples(key, QStringLiteral("device_name"), startMs - 1000, endMs + 1000, 1000);
    QVERIFY(!name.points.isEmpty());
    QCOMPARE(name.points.first().text.trimmed(), QString("IPC300"));
    const auto series = reader.series(key.station, &error);
    QVERIFY(series);
    QCOMPARE(series->size(), 2);
    QCOMPARE(series->at(0).numeric, false);   // device_name
    QCOMPARE(series->at(1).unit, QString("V"));
}

QTEST_GUILESS_MAIN(tst_HistoryRecorder)
#include "tst_historyrecorder.moc"
