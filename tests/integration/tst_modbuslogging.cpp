// Qt's own Modbus log lines ("Discarding response with wrong CRC") are --verbose output
// of jumoctl and jumo-hmi, not noise on stderr: the real executables against the
// simulator over a pty, which answers the first request with a bad CRC.
#include "testpeers.h"

#include <QProcess>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

class tst_ModbusLogging : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void jumoctl_data();
    void jumoctl();
    void hmi_data();
    void hmi();

private:
    // Starts a tool with the test's environment; the caller waits for it.
    std::unique_ptr<QProcess> start(const QString &program, const QStringList &args);

    QTemporaryDir m_home;
    TestLine m_line;
    SimulatorPeer m_sim;
};

void tst_ModbusLogging::initTestCase()
{
    QVERIFY(m_home.isValid());
    QVERIFY(m_line.start());
    QVERIFY(m_sim.start(m_line.deviceEnd(), {1}));
}

std::unique_ptr<QProcess> tst_ModbusLogging::start(const QString &program, const QStringList &args)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("QT_LOGGING_RULES");   // it would override the tool's own rules
    env.insert("QT_QPA_PLATFORM", "offscreen");
    env.insert("XDG_CONFIG_HOME", m_home.filePath("config"));
    env.insert("XDG_DATA_HOME", m_home.filePath("data"));
    env.insert("JUMO_LOG_DIR", m_home.filePath("logs"));
    auto p = std::make_unique<QProcess>();
    p->setProcessEnvironment(env);
    p->start(program, args);
    return p;
}

void tst_ModbusLogging::jumoctl_data()
{
    QTest::addColumn<bool>("verbose");
    QTest::newRow("default: silent") << false;
    QTest::newRow("--verbose") << true;
}

void tst_ModbusLogging::jumoctl()
{
    QFETCH(bool, verbose);
    m_sim.setFault(1, "badcrc", 1, 0);
    const int requestsBefore = m_sim.line().requestsReceived();
    QStringList args{"read", "--port", m_line.masterEnd(), "--baud", "19200", "ipc300@1", "load_current"};
    if (verbose)
        args << "--verbose";
    const auto p = start(QStringLiteral(JUMOCTL_PATH), args);
    // The simulator lives in this process: keep its event loop running meanwhile.
    QTRY_VERIFY_WITH_TIMEOUT(p->state() == QProcess::NotRunning, 60000);
    const QString err = QString::fromUtf8(p->readAllStandardError());
    QCOMPARE(p->exitCode(), 0);   // the retry got the value
    QVERIFY(p->readAllStandardOutput().contains("load_current = "));
    QVERIFY(m_sim.line().requestsReceived() - requestsBefore >= 2);   // the bad reply was there
    QCOMPARE(err.contains("Discarding response with wrong CRC"), verbose);
    QCOMPARE(err.contains("qt.modbus"), verbose);
}

void tst_ModbusLogging::hmi_data()
{
    jumoctl_data();
}

void tst_ModbusLogging::hmi()
{
    QFETCH(bool, verbose);
    m_sim.setFault(1, "badcrc", 1, 0);
    const int requestsBefore = m_sim.line().requestsReceived();
    QStringList args{"--port", m_line.masterEnd(), "--baud", "19200", "--device", "ipc300@1", "--report-startup"};
    if (verbose)
        args << "--verbose";
    const auto p = start(QStringLiteral(JUMO_HMI_PATH), args);
    QString err;
    // Live values arrived, and the HMI has sent two requests after the one with the bad
    // answer: it has long read that answer.
    QTRY_VERIFY_WITH_TIMEOUT((err += QString::fromUtf8(p->readAllStandardError())).contains("first live value")
                                     && m_sim.line().requestsReceived() - requestsBefore >= 3,
                             60000);
    p->terminate();   // the HMI quits cleanly on SIGTERM
    QTRY_VERIFY_WITH_TIMEOUT(p->state() == QProcess::NotRunning, 60000);
    err += QString::fromUtf8(p->readAllStandardError());
    QCOMPARE(err.contains("Discarding response with wrong CRC"), verbose);
    QCOMPARE(err.contains("qt.modbus"), verbose);
}

QTEST_GUILESS_MAIN(tst_ModbusLogging)
#include "tst_modbuslogging.moc"
