// A write changes only what the operator asked, over a pty line: bit changes through
// jumoctl (ENTRY.BIT=0|1) and through Bus::writeBits as the HMI makes them keep the other
// bits (IPC 300 0x00F1 composed from 0x00EF; dTRON 300 0x0027 read and rewritten), a
// command whose every answer is lost goes out once and ends "unknown", and the system's
// read-only setting keeps every write frame off the line.
#include "bus/bus.h"
#include "clirun.h"
#include "testpeers.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

namespace {

constexpr quint16 ipcStatusWord = 0x00EF;       // binary_signal_1: reports the bits of 0x00F1
constexpr quint16 ipcSwitchWord = 0x00F1;       // binary_signal_write (write-only)
constexpr quint16 inhibitReported = 1u << 9;    // 0x00EF bit 9: external inhibit input
constexpr quint16 outputReported = 1u << 10;    // 0x00EF bit 10: digital output
constexpr quint16 dtronControlWord = 0x0027;    // binary_output_control, activation bit 15
constexpr quint16 dtronOutputs = 0x0021;        // binary_outputs: what the outputs do

// The words of the write requests (0x06 and 0x10) to one register, in order.
QList<quint16> writtenWords(const QList<QByteArray> &frames, quint8 slave, quint16 address)
{
    QList<quint16> words;
    for (const QByteArray &f : frames) {
        if (f.size() < 8 || quint8(f[0]) != slave || quint16(quint8(f[2]) << 8 | quint8(f[3])) != address)
            continue;
        if (quint8(f[1]) == 0x06)
            words << quint16(quint8(f[4]) << 8 | quint8(f[5]));
        else if (quint8(f[1]) == 0x10 && f.size() >= 11)
            words << quint16(quint8(f[7]) << 8 | quint8(f[8]));
    }
    return words;
}

} // namespace

class tst_BitWrites : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cliDigitalOutputKeepsExternalInhibit();
    void cliBitsOfOneEntryGoInOneWrite();
    void cliBadBitAssignmentSendsNothing_data();
    void cliBadBitAssignmentSendsNothing();
    void busDigitalOutputKeepsExternalInhibit();
    void cliDtronK1KeepsK2();
    void busDtronK1KeepsK2();
    void libmodbusKeepsOtherBitsOfHoldingRegister();
    void libmodbusComposesWriteOnlyWordFromStatus();
    void commandWithEveryAnswerLostGoesOutOnce_data();
    void commandWithEveryAnswerLostGoesOutOnce();
    void systemReadOnlyKeepsWritesOffTheLine();
    void systemReadOnlyFailsClosed_data();
    void systemReadOnlyFailsClosed();

private:
    QStringList port(const TestLine &line) const { return {"--port", line.masterEnd(), "--baud", "19200"}; }
    QStringList port() const { return port(m_line); }
    QJsonObject lastAudit() const;
    bool openBus(Bus &bus, const TestLine &line) const;
    SimulatedDevice *ipc() { return m_sim.line().device(1); }
    SimulatedDevice *dtron() { return m_sim.line().device(4); }

    QTemporaryDir m_logs;
    TestLine m_line;
    SimulatorPeer m_sim;
    QList<QByteArray> m_frames;   // every request the simulator received
};

void tst_BitWrites::initTestCase()
{
    qputenv("JUMO_MAP_PATH", "");
    qputenv("XDG_DATA_HOME", QByteArray(QDir::tempPath().toUtf8() + "/jumo-test-no-maps"));
    qputenv("JUMO_LOG_DIR", m_logs.path().toUtf8());
    QVERIFY(m_line.start());
    m_sim.line().addDevice(families().family("ipc300"), 1);
    m_sim.line().addDevice(families().family("dtron300"), 4);
    QVERIFY(m_sim.start(m_line.deviceEnd(), {}));
    connect(&m_sim.line(), &SimulatorLine::requestReceived, this, [this](const QByteArray &f) { m_frames << f; });
}

void tst_BitWrites::init()
{
    // Every test starts from signals off.
    for (const char *bit : {"binary_signal_1.external_inhibit_input", "binary_signal_1.digital_output",
                            "binary_signal_1.external_digital_input_1", "binary_signal_1.external_digital_input_2"})
        QVERIFY(ipc()->setFlag(bit, false));
    QVERIFY(dtron()->setWords(dtronControlWord, {0}));
    QVERIFY(dtron()->setWords(dtronOutputs, {0}));
    m_sim.setFault(1, "none", -1, 0);
    m_sim.setFault(4, "none", -1, 0);
    m_frames.clear();
}

QJsonObject tst_BitWrites::lastAudit() const
{
    QFile file(m_logs.filePath("write-audit.jsonl"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
    return QJsonDocument::fromJson(lines.last()).object();
}

bool tst_BitWrites::openBus(Bus &bus, const TestLine &line) const
{
    BusSettings settings;
    settings.portName = line.masterEnd();
    settings.format = testFormat();
    bus.setSettings(settings);
    bus.setPolling(false);
    return bus.open();
}

void tst_BitWrites::cliDigitalOutputKeepsExternalInhibit()
{
    Run r = run(QStringList{"write"} + port() + QStringList{"ipc300@1", "external_inhibit_input=1"});
    QCOMPARE(r.code, 0);
    QVERIFY(ipc()->word(ipcStatusWord) & inhibitReported);

    r = run(QStringList{"write"} + port() + QStringList{"ipc300@1", "binary_signal_write.digital_output=1"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains("binary_signal_write: confirmed by read-back: digital_output=1"), qPrintable(r.out));
    // The device's status word proves it: the output is on and the inhibit still is.
    QCOMPARE(ipc()->word(ipcStatusWord) & (inhibitReported | outputReported), inhibitReported | outputReported);
    QCOMPARE(writtenWords(m_frames, 1, ipcSwitchWord), QList<quint16>{0x0009});   // inhibit (bit 0) + output (bit 3)
    r = run(QStringList{"read"} + port() + QStringList{"ipc300@1", "binary_signal_1"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("(external_inhibit_input+digital_output)  [ok]"), qPrintable(r.out));

    r = run(QStringList{"write"} + port() + QStringList{"ipc300@1", "binary_signal_write.digital_output=off"});
    QCOMPARE(r.code, 0);
    QCOMPARE(ipc()->word(ipcStatusWord) & (inhibitReported | outputReported), inhibitReported);
    QCOMPARE(writtenWords(m_frames, 1, ipcSwitchWord), (QList<quint16>{0x0009, 0x0001}));
    const QJsonObject audit = lastAudit();
    QCOMPARE(audit.value("entry").toString(), QString("binary_signal_write"));
    QCOMPARE(audit.value("new").toString(), QString("binary_signal_write.digital_output=0"));
    QCOMPARE(audit.value("result").toString(), QString("confirmed"));
}

void tst_BitWrites::cliBitsOfOneEntryGoInOneWrite()
{
    QVERIFY(ipc()->setFlag("binary_signal_1.external_inhibit_input", true));
    const Run r = run(QStringList{"write"} + port()
                      + QStringList{"ipc300@1", "binary_signal_write.digital_output=1",
                                    "binary_signal_write.external_digital_input_2=true"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains("confirmed by read-back: external_digital_input_2=1, digital_output=1"), qPrintable(r.out));
    QCOMPARE(writtenWords(m_frames, 1, ipcSwitchWord), QList<quint16>{0x000D});   // one frame: bits 0, 2, 3
    QVERIFY(ipc()->flag("binary_signal_1.external_inhibit_input"));
    QVERIFY(ipc()->flag("binary_signal_1.external_digital_input_2"));
    QVERIFY(ipc()->flag("binary_signal_1.digital_output"));
    QVERIFY(!ipc()->flag("binary_signal_1.external_digital_input_1"));
}

void tst_BitWrites::cliBadBitAssignmentSendsNothing_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown bit") << QStringList{"ipc300@1", "binary_signal_write.digital_outptu=1"}
                                 << "'digital_outptu' is not a bit of 'binary_signal_write'";
    QTest::newRow("reserved bit") << QStringList{"ipc300@1", "binary_signal_write.reserve_bit4=1"}
                                  << "'reserve_bit4' is not a bit of 'binary_signal_write'";
    QTest::newRow("bad state") << QStringList{"ipc300@1", "binary_signal_write.digital_output=2"}
                               << "'2' is not a bit state for 'binary_signal_write.digital_output': give 0, 1, on, "
                                  "off, true or false";
    QTest::newRow("bad state after a good one")
            << QStringList{"ipc300@1", "binary_signal_write.digital_output=1", "binary_signal_write.external_inhibit_input=yes"}
            << "'yes' is not a bit state";
    QTest::newRow("unknown entry") << QStringList{"ipc300@1", "output_control.digital_output=1"}
                                   << "'output_control' is not an entry of ipc300";
    QTest::newRow("read-only word") << QStringList{"ipc300@1", "binary_signal_1.digital_output=1"}
                                    << "'binary_signal_1' is not a writable bit field";
    QTest::newRow("not a bit field") << QStringList{"ipc300@1", "input_setpoint.x=1"}
                                     << "'input_setpoint' is not a writable bit field";
    QTest::newRow("on and off") << QStringList{"ipc300@1", "binary_signal_write.digital_output=1", "binary_signal_write.digital_output=0"}
                                << "'binary_signal_write.digital_output' is given twice, on and off";
    QTest::newRow("whole and bits") << QStringList{"ipc300@1", "binary_signal_write=0", "binary_signal_write.digital_output=1"}
                                    << "'binary_signal_write' is given both whole and by bits";
    QTest::newRow("command word") << QStringList{"dtron300@4", "program_controller_functions.segment_change=1"}
                                  << "send a command as program_controller_functions=BIT";
    QTest::newRow("activation bit") << QStringList{"dtron300@4", "binary_output_control.activation=1"}
                                    << "is the activation bit, which every write sets";
    QTest::newRow("unreported bits") << QStringList{"dtron300@4", "logic_1_2.logic_1=1"}
                                     << "the device does not report the state of logic_2";
    QTest::newRow("broadcast") << QStringList{"ipc300@0", "binary_signal_write.digital_output=1", "--verify", "1"}
                               << "a broadcast is not answered";
}

void tst_BitWrites::cliBadBitAssignmentSendsNothing()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const int requestsBefore = m_sim.line().requestsReceived();
    const Run r = run(QStringList{"write"} + port() + args);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QCOMPARE(m_sim.line().requestsReceived(), requestsBefore);   // not even a read
}

void tst_BitWrites::busDigitalOutputKeepsExternalInhibit()
{
    QVERIFY(ipc()->setFlag("binary_signal_1.external_inhibit_input", true));
    Bus bus;
    QVERIFY(openBus(bus, m_line));
    const DeviceId id = bus.addDevice(families().family("ipc300"), 1);
    QSignalSpy finished(&bus, &Bus::writeFinished);

    bus.writeBits(id, "binary_signal_write", {{"digital_output", true}});
    QVERIFY(finished.wait(20000));
    WriteOutcome outcome = finished.takeFirst().at(1).value<WriteOutcome>();
    QVERIFY2(outcome.result == WriteOutcome::Result::Confirmed, qPrintable(outcome.message));
    QCOMPARE(ipc()->word(ipcStatusWord) & (inhibitReported | outputReported), inhibitReported | outputReported);

    bus.writeBits(id, "binary_signal_write", {{"digital_output", false}});
    QVERIFY(finished.wait(20000));
    outcome = finished.takeFirst().at(1).value<WriteOutcome>();
    QVERIFY2(outcome.result == WriteOutcome::Result::Confirmed, qPrintable(outcome.message));
    QCOMPARE(ipc()->word(ipcStatusWord) & (inhibitReported | outputReported), inhibitReported);
    QCOMPARE(writtenWords(m_frames, 1, ipcSwitchWord), (QList<quint16>{0x0009, 0x0001}));
    bus.close();
}

void tst_BitWrites::cliDtronK1KeepsK2()
{
    // K2 on, as someone switched it earlier with the whole word.
    Run r = run(QStringList{"write"} + port() + QStringList{"dtron300@4", "binary_output_control=0x8002"});
    QCOMPARE(r.code, 0);
    QCOMPARE(dtron()->word(dtronOutputs), quint16(0x0002));

    r = run(QStringList{"write"} + port() + QStringList{"dtron300@4", "binary_output_control.output_1=1"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains("binary_output_control: confirmed by read-back: output_1=1 (was 0x8002"), qPrintable(r.out));
    QCOMPARE(dtron()->word(dtronOutputs), quint16(0x0003));   // K1 and K2
    QCOMPARE(dtron()->word(dtronControlWord), quint16(0x8003));

    r = run(QStringList{"write"} + port() + QStringList{"dtron300@4", "binary_output_control.output_1=0"});
    QCOMPARE(r.code, 0);
    QCOMPARE(dtron()->word(dtronOutputs), quint16(0x0002));   // K2 still on
    QCOMPARE(writtenWords(m_frames, 4, dtronControlWord), (QList<quint16>{0x8002, 0x8003, 0x8002}));
}

void tst_BitWrites::busDtronK1KeepsK2()
{
    Bus bus;
    QVERIFY(openBus(bus, m_line));
    const DeviceId id = bus.addDevice(families().family("dtron300"), 4);
    QSignalSpy finished(&bus, &Bus::writeFinished);
    bus.write(id, "binary_output_control", "output_2+activation");
    QVERIFY(finished.wait(20000));
    QCOMPARE(dtron()->word(dtronOutputs), quint16(0x0002));

    bus.writeBits(id, "binary_output_control", {{"output_1", true}});
    QVERIFY(finished.wait(20000));
    QCOMPARE(finished.at(1).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Confirmed);
    QCOMPARE(dtron()->word(dtronOutputs), quint16(0x0003));

    bus.writeBits(id, "binary_output_control", {{"output_1", false}});
    QVERIFY(finished.wait(20000));
    QCOMPARE(finished.at(2).at(1).value<WriteOutcome>().result, WriteOutcome::Result::Confirmed);
    QCOMPARE(dtron()->word(dtronOutputs), quint16(0x0002));
    bus.close();
}

void tst_BitWrites::libmodbusKeepsOtherBitsOfHoldingRegister()
{
    TestLine line;
    QVERIFY(line.start());
    LibmodbusPeer peer;
    QVERIFY(peer.start(line.deviceEnd(), {4}));
    QVERIFY(peer.setWords(4, dtronControlWord, {0x8202}));   // outputs 2 and 10 on
    QVERIFY(peer.setWords(4, 0x4009, {0x0001}));   // the device format, which names a dTRON

    Run r = run(QStringList{"write"} + port(line) + QStringList{"dtron300@4", "binary_output_control.output_1=1"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QCOMPARE(peer.words(4, dtronControlWord, 1), QList<quint16>{0x8203});
    r = run(QStringList{"write"} + port(line) + QStringList{"dtron300@4", "binary_output_control.output_10=off",
                                                            "binary_output_control.output_1=off"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QCOMPARE(peer.words(4, dtronControlWord, 1), QList<quint16>{0x8002});
    QCOMPARE(peer.writeFrames(), 2);
}

void tst_BitWrites::libmodbusComposesWriteOnlyWordFromStatus()
{
    // The independent peer only stores words: it does not report 0x00F1 in 0x00EF as a
    // device does. The frame it received shows the composition all the same.
    TestLine line;
    QVERIFY(line.start());
    LibmodbusPeer peer;
    QVERIFY(peer.start(line.deviceEnd(), {1}));
    QVERIFY(peer.setWords(1, ipcStatusWord, {inhibitReported | (1u << 8)}));   // inhibit, external input 2
    QVERIFY(peer.setWords(1, 0x000E, {0x4950, 0x4333, 0x3030}));   // the device name "IPC300", which names it
    const Run r = run(QStringList{"write"} + port(line) + QStringList{"ipc300@1", "binary_signal_write.digital_output=1"});
    QCOMPARE(peer.writeFrames(), 1);
    QCOMPARE(peer.words(1, ipcSwitchWord, 1), QList<quint16>{0x000D});   // bits 0, 2 kept, bit 3 set
    // ... and, as the peer's 0x00EF does not follow, the read-back says so.
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("written, but the device does not report digital_output=1"), qPrintable(r.err));
}

void tst_BitWrites::commandWithEveryAnswerLostGoesOutOnce_data()
{
    QTest::addColumn<QString>("peer");
    QTest::newRow("simulator") << "simulator";
    QTest::newRow("libmodbus") << "libmodbus";
}

void tst_BitWrites::commandWithEveryAnswerLostGoesOutOnce()
{
    QFETCH(QString, peer);
    TestLine ownLine;
    LibmodbusPeer libmodbus;
    Peer *far = &m_sim;
    const TestLine *line = &m_line;
    if (peer == "libmodbus") {
        QVERIFY(ownLine.start());
        QVERIFY(libmodbus.start(ownLine.deviceEnd(), {4}));
        far = &libmodbus;
        line = &ownLine;
    }
    QVERIFY(far->setFault(4, "dead"));
    const int writesBefore = far->writeFrames();
    // The device is dead: its identity cannot be read, and the test is about the write.
    const Run r = run(QStringList{"write", "--no-identify"} + port(*line)
                      + QStringList{"dtron300@4", "program_controller_functions=segment_change"});
    far->setFault(4, "none");
    QCOMPARE(far->writeFrames() - writesBefore, 1);   // never sent again, whatever the retries
    QCOMPARE(r.code, 3);
    QVERIFY2(r.err.contains("program_controller_functions: unknown, check the device: no answer: the command may or "
                            "may not have been carried out; it is not sent again"),
             qPrintable(r.err));
    const QJsonObject audit = lastAudit();
    QCOMPARE(audit.value("entry").toString(), QString("program_controller_functions"));
    QCOMPARE(audit.value("result").toString(), QString("unknown"));
}

void tst_BitWrites::systemReadOnlyKeepsWritesOffTheLine()
{
    QTemporaryDir config;
    QVERIFY(QDir(config.path()).mkpath("jumo"));
    QFile conf(config.filePath("jumo/jumo-hmi.conf"));
    QVERIFY(conf.open(QIODevice::WriteOnly));
    conf.write("[General]\nreadOnly=true\n");
    conf.close();
    QVERIFY(ipc()->setFlag("binary_signal_1.external_inhibit_input", true));
    const QList<quint16> setpoint = m_sim.words(1, 0x00D5, 2);
    const int writesBefore = m_sim.writeFrames();

    // The real executable: QSettings reads the system folders once per process.
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("XDG_CONFIG_DIRS", config.path());
    auto jumoctl = [&env](const QStringList &args) {
        auto p = std::make_unique<QProcess>();
        p->setProcessEnvironment(env);
        p->start(QStringLiteral(JUMOCTL_PATH), args);
        return p;
    };
    const auto write = jumoctl(QStringList{"write"} + port()
                               + QStringList{"ipc300@1", "input_setpoint=10", "binary_signal_write.digital_output=1"});
    // The simulator lives in this process: keep its event loop running meanwhile.
    QTRY_VERIFY_WITH_TIMEOUT(write->state() == QProcess::NotRunning, 60000);
    const QString err = QString::fromUtf8(write->readAllStandardError());
    QCOMPARE(write->exitCode(), 1);
    QVERIFY2(err.contains("read-only mode is set by the system configuration (" + config.filePath("jumo/jumo-hmi.conf")),
             qPrintable(err));
    QVERIFY2(err.contains("binary_signal_write: read-only mode: binary_signal_write was not written"), qPrintable(err));
    // Whatever is asked: a whole word, a broadcast.
    for (const QStringList &args : {QStringList{"ipc300@1", "binary_signal_write=0"},
                                    QStringList{"ipc300@0", "input_setpoint=10", "--verify", "1", "--line-has-only",
                                                "ipc300"}}) {
        const auto other = jumoctl(QStringList{"write"} + port() + args);
        QTRY_VERIFY_WITH_TIMEOUT(other->state() == QProcess::NotRunning, 60000);
        QCOMPARE(other->exitCode(), 1);
        QVERIFY(other->readAllStandardError().contains("read-only mode is set by the system configuration"));
    }

    QCOMPARE(m_sim.writeFrames(), writesBefore);
    QCOMPARE(m_sim.words(1, 0x00D5, 2), setpoint);
    QVERIFY(ipc()->flag("binary_signal_1.external_inhibit_input"));
    QCOMPARE(lastAudit().value("result").toString(), QString("read_only"));
}

void tst_BitWrites::systemReadOnlyFailsClosed_data()
{
    QTest::addColumn<QByteArray>("conf");      // jumo/jumo-hmi.conf; empty: a folder there
    QTest::addColumn<QString>("warning");
    QTest::newRow("lower case key") << QByteArray("[General]\nreadonly=true\n") << "'readonly' is taken as readOnly";
    QTest::newRow("capitalised key") << QByteArray("[General]\nReadOnly=true\n") << "'ReadOnly' is taken as readOnly";
    QTest::newRow("the file is a folder") << QByteArray() << "cannot be read (it is a folder)";
}

void tst_BitWrites::systemReadOnlyFailsClosed()
{
    // A slip of the administrator's must not let writes through without a word.
    QFETCH(QByteArray, conf);
    QFETCH(QString, warning);
    QTemporaryDir config;
    const QString path = config.filePath("jumo/jumo-hmi.conf");
    if (conf.isEmpty()) {
        QVERIFY(QDir().mkpath(path));
    } else {
        QVERIFY(QDir(config.path()).mkpath("jumo"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(conf);
    }
    const QList<quint16> setpoint = m_sim.words(1, 0x00D5, 2);
    const int writesBefore = m_sim.writeFrames();
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("XDG_CONFIG_DIRS", config.path());
    QProcess write;
    write.setProcessEnvironment(env);
    write.start(QStringLiteral(JUMOCTL_PATH), QStringList{"write"} + port() + QStringList{"ipc300@1", "input_setpoint=10"});
    // The simulator lives in this process: keep its event loop running meanwhile.
    QTRY_VERIFY_WITH_TIMEOUT(write.state() == QProcess::NotRunning, 60000);
    const QString err = QString::fromUtf8(write.readAllStandardError());
    QCOMPARE(write.exitCode(), 1);
    QVERIFY2(err.contains("warning: " + path) && err.contains(warning), qPrintable(err));
    QVERIFY2(err.contains("read-only mode is set by the system configuration (" + path), qPrintable(err));
    QCOMPARE(m_sim.writeFrames(), writesBefore);
    QCOMPARE(m_sim.words(1, 0x00D5, 2), setpoint);
    QCOMPARE(lastAudit().value("result").toString(), QString("read_only"));
}

QTEST_GUILESS_MAIN(tst_BitWrites)
#include "tst_bitwrites.moc"
