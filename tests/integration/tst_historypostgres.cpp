// The history in PostgreSQL: a real server (Debian's postgresql-15) started in a
// temporary folder as the postgres user, the same store, reader and jumoctl history as
// with SQLite, and the round trip through them.
#include "clirun.h"
#include "history/historyreader.h"
#include "history/sqlhistorystore.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

#include <pwd.h>
#include <unistd.h>

using namespace jumo;
using namespace jumo::test;

namespace {

const QString binDir = QStringLiteral("/usr/lib/postgresql/15/bin");

bool runAsPostgres(const QStringList &command, QString *output)
{
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.setWorkingDirectory(QDir::tempPath());
    p.start(QStringLiteral("runuser"), QStringList{QStringLiteral("-u"), QStringLiteral("postgres"), QStringLiteral("--")}
                                               + command);
    const bool ok = p.waitForFinished(60000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
    *output = QString::fromLocal8Bit(p.readAll());
    return ok;
}

} // namespace

class tst_HistoryPostgres : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void roundTrip();

private:
    QTemporaryDir m_dir;
    QString m_data;
    quint16 m_port = 0;
    bool m_started = false;
};

void tst_HistoryPostgres::initTestCase()
{
    const passwd *postgres = getpwnam("postgres");
    if (!QFileInfo::exists(binDir + "/initdb") || !postgres || geteuid() != 0)
        QSKIP("needs Debian's postgresql-15 and root (initdb runs as the postgres user)");
    QVERIFY(m_dir.isValid());
    QVERIFY(chown(qPrintable(m_dir.path()), postgres->pw_uid, postgres->pw_gid) == 0);
    m_data = m_dir.filePath("data");
    QTcpServer probe;
    QVERIFY(probe.listen(QHostAddress::LocalHost));
    m_port = probe.serverPort();
    probe.close();
    QString output;
    const bool made = runAsPostgres({binDir + "/initdb", "-D", m_data, "-A", "trust", "-U", "postgres", "--no-sync"},
                                    &output);
    // A machine where the postgres user may not run the server's programs (seen on a
    // fresh minimal chroot): nothing to test the store against here, and said so.
    if (!made && output.contains("failed to execute"))
        QSKIP(qPrintable("the postgres user cannot run initdb here: " + output.trimmed()));
    QVERIFY2(made, qPrintable(output));
    QVERIFY2(runAsPostgres({binDir + "/pg_ctl", "-D", m_data, "-w", "-l", m_dir.filePath("server.log"), "-o",
                            QString("-p %1 -k %2 -c listen_addresses=127.0.0.1 -c fsync=off").arg(m_port).arg(m_dir.path()),
                            "start"},
                           &output),
             qPrintable(output));
    m_started = true;
}

void tst_HistoryPostgres::cleanupTestCase()
{
    QString output;
    if (m_started)
        runAsPostgres({binDir + "/pg_ctl", "-D", m_data, "-m", "immediate", "stop"}, &output);
}

void tst_HistoryPostgres::roundTrip()
{
    QString error;
    const QString url = QString("postgresql://postgres@127.0.0.1:%1/postgres").arg(m_port);
    const std::optional<HistoryLocation> location = HistoryLocation::parse(url, &error);
    QVERIFY2(location, qPrintable(error));
    const HistoryKey key{"hall-3", "line1", "ipc300@1"};
    const qint64 t0 = (QDateTime::currentMSecsSinceEpoch() / 60000 - 30) * 60000;
    HistorySettings settings;
    settings.batchIntervalMs = 50;
    {
        SqlHistoryStore store(*location, key.station, settings);
        QSignalSpy written(&store, &SqlHistoryStore::written);
        QSignalSpy maintained(&store, &SqlHistoryStore::maintained);
        QSignalSpy stopped(&store, &HistoryStore::recordingStopped);
        store.start();
        const int voltage = store.series({key, "load_voltage", true, "V"});
        const int name = store.series({key, "device_name", false, QString()});
        auto sample = [](int series, qint64 t, SampleState state, double value) {
            HistorySample s;
            s.series = series;
            s.timeMs = t;
            s.state = state;
            s.value = value;
            return s;
        };
        store.record(sample(voltage, t0, SampleState::Ok, 230));
        store.record(sample(voltage, t0 + 60000, SampleState::Ok, 231));
        store.record(sample(voltage, t0 + 120000, SampleState::Offline, qQNaN()));
        store.record(sample(voltage, t0 + 180000, SampleState::Ok, 229));
        HistorySample text = sample(name, t0, SampleState::Ok, qQNaN());
        text.text = "IPC300";
        store.record(text);
        store.flush();
        QTRY_VERIFY_WITH_TIMEOUT(!written.isEmpty() || !stopped.isEmpty(), 20000);
        QVERIFY2(stopped.isEmpty(), qPrintable(stopped.value(0).value(0).toString()));
        store.maintainNow();
        QVERIFY(maintained.wait(20000));
        QVERIFY(maintained.last().at(0).toLongLong() >= t0 + 180000);

        QSignalSpy answered(&store, &HistorySource::samplesAnswered);
        store.requestSamples({key, "load_voltage", t0 - 60000, t0 + 10 * 60000, 1000});
        QVERIFY(answered.wait(20000));
        const HistoryTrace trace = answered.at(0).at(1).value<HistoryTrace>();
        QVERIFY2(trace.ok(), qPrintable(trace.error));
        QCOMPARE(trace.points.size(), 4);
        QCOMPARE(trace.points[1].value, 231.0);
        QCOMPARE(trace.gaps().size(), 1);
        QCOMPARE(trace.gaps()[0].state, SampleState::Offline);
    }
    // The same from the one-minute rows, and through jumoctl.
    HistoryReader reader(*location);
    const HistoryTrace minutes = reader.samples(key, "load_voltage", t0, t0 + 10 * 60000, 5);
    QVERIFY2(minutes.ok(), qPrintable(minutes.error));
    QCOMPARE(minutes.resolution, HistoryTrace::Resolution::Minute);
    QVERIFY(!minutes.points.isEmpty());
    QVERIFY(minutes.points.size() >= 4);
    QCOMPARE(minutes.points[0].timeMs, t0);
    QCOMPARE(minutes.points[1].maximum, 231.0);
    QCOMPARE(minutes.points[2].state, SampleState::Offline);
    const QString iso = QDateTime::fromMSecsSinceEpoch(t0, Qt::UTC).toString(Qt::ISODateWithMs);
    const Run r = run({"history", "--db", url, "ipc300@1", "device_name", "--from", iso, "--to",
                       QDateTime::fromMSecsSinceEpoch(t0 + 1000, Qt::UTC).toString(Qt::ISODateWithMs), "--csv"});
    QCOMPARE(r.err, QString());
    QCOMPARE(r.code, 0);
    QCOMPARE(r.out.split('\n').value(1), iso + ",hall-3/line1/ipc300@1,device_name,IPC300,,ok,current,raw,,,");
}

QTEST_GUILESS_MAIN(tst_HistoryPostgres)
#include "tst_historypostgres.moc"
