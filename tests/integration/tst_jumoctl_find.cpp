// jumoctl find as a user runs it: the jumo-sim program on a pty pair, started at settings
// nobody told jumoctl, and the jumoctl program searching every setting the families support.
// The simulator watches the client's end of the pair and answers only at its own baud rate
// and format (a pty carries the baud rate, the stop bits and odd parity; not even parity).
#include <QDir>
#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

class tst_JumoctlFind : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void findsDevicesAtTheirOwnSettings();
    void simulatorAnswersOnlyAtItsSettings();
    void networkLinesAndBadListsAreRefused_data();
    void networkLinesAndBadListsAreRefused();
    void interruptSaysWhatWasFound();
    void lateAnswerIsNotTakenAtTheNextSetting();

private:
    struct Sim
    {
        QTemporaryDir dir;
        QProcess process;
        QString master() const { return QDir(dir.path()).filePath(QStringLiteral("master")); }
    };
    static bool startSim(Sim &sim, const QStringList &args);
    static QProcess *startJumoctl(const QStringList &args, QObject *parent);

    Sim m_tya;     // tya200@4 at 19200 8E1
    Sim m_dtron;   // dtron300@7 at 9600 8N2
};

bool tst_JumoctlFind::startSim(Sim &sim, const QStringList &args)
{
    sim.process.setProcessChannelMode(QProcess::MergedChannels);
    sim.process.start(QStringLiteral(JUMO_SIM_PATH), QStringList{"--pty", sim.dir.path(), "--pace"} + args);
    QByteArray seen;
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < 10000 && !seen.contains("connect to")) {
        sim.process.waitForReadyRead(100);
        seen += sim.process.readAll();
    }
    // The simulator must be watching the client's end, or it answers at any setting.
    if (seen.contains("warning"))
        qWarning("%s", seen.constData());
    return seen.contains("connect to") && !seen.contains("warning");
}

QProcess *tst_JumoctlFind::startJumoctl(const QStringList &args, QObject *parent)
{
    auto *p = new QProcess(parent);
    p->start(QStringLiteral(JUMOCTL_PATH), args);
    return p;
}

void tst_JumoctlFind::initTestCase()
{
    qputenv("JUMO_MAP_PATH", "");
    QVERIFY(startSim(m_tya, {"--baud", "19200", "--format", "8E1", "tya200@4"}));
    QVERIFY(startSim(m_dtron, {"--baud", "9600", "--format", "8N2", "dtron300@7"}));
}

void tst_JumoctlFind::cleanupTestCase()
{
    for (Sim *sim : {&m_tya, &m_dtron}) {
        sim->process.terminate();
        sim->process.waitForFinished(5000);
    }
}

void tst_JumoctlFind::findsDevicesAtTheirOwnSettings()
{
    // Both lines searched at once, the whole default search of every setting, addresses 1..10.
    QObject owner;
    QProcess *tya = startJumoctl({"find", "--port", m_tya.master(), "--to", "10"}, &owner);
    QProcess *dtron = startJumoctl({"find", "--port", m_dtron.master(), "--to", "10"}, &owner);
    for (QProcess *p : {tya, dtron}) {
        QVERIFY(p->waitForFinished(240000));
        QCOMPARE(p->exitStatus(), QProcess::NormalExit);
    }
    const QString tyaOut = QString::fromUtf8(tya->readAllStandardOutput());
    const QString tyaErr = QString::fromUtf8(tya->readAllStandardError());
    const QString dtronOut = QString::fromUtf8(dtron->readAllStandardOutput());
    const QString dtronErr = QString::fromUtf8(dtron->readAllStandardError());
    QCOMPARE(tya->exitCode(), 0);
    QCOMPARE(dtron->exitCode(), 0);

    // The search says what it tries before it starts.
    QVERIFY2(tyaErr.contains("searching 16 setting(s) (9600, 19200, 38400, 4800 baud; 8N1 8E1 8O1 8N2) for addresses "
                             "1..10 and 255"),
             qPrintable(tyaErr));
    // The TYA 200 at its own setting; a pty cannot tell 8N1 from 8E1, so it answers there
    // too, and the search says why. Nowhere else.
    QVERIFY2(tyaOut.contains("at 19200 8E1: tya200 at address 4 (JUMO TYA 200"), qPrintable(tyaOut));
    for (const QString &line : tyaOut.split('\n', Qt::SkipEmptyParts))
        QVERIFY2(line.startsWith("at 19200 8E1: tya200 at address 4") || line.startsWith("at 19200 8N1: tya200 at address 4"),
                 qPrintable(tyaOut));
    QVERIFY2(tyaErr.contains("tya200 at address 4 answers at 19200 baud in 8N1, 8E1"), qPrintable(tyaErr));
    // The dTRON at its own setting only: two stop bits are seen on a pty.
    QCOMPARE(dtronOut.trimmed(), QStringLiteral("at 9600 8N2: dtron300 at address 7 (JUMO dTRON 304/308/316 (and plast) "
                                                "compact controllers)"));
    QVERIFY2(dtronErr.contains("the line's settings where the most answered: --baud 9600 --format 8N2"), qPrintable(dtronErr));
    // How long it took.
    static const QRegularExpression took("1 device\\(s\\) found in ([0-9.]+) s");
    for (const QString &err : {tyaErr, dtronErr}) {
        const QRegularExpressionMatch m = took.match(err);
        QVERIFY2(m.hasMatch(), qPrintable(err));
        qInfo("%s", qPrintable(m.captured(0)));
    }
}

void tst_JumoctlFind::simulatorAnswersOnlyAtItsSettings()
{
    // The same simulated line, scanned at other settings, is silent; at its own it answers.
    const QList<QPair<QStringList, int>> cases{
            {{"--baud", "9600", "--format", "8E1"}, 1},
            {{"--baud", "19200", "--format", "8O1"}, 1},
            {{"--baud", "19200", "--format", "8N2"}, 1},
            {{"--baud", "19200", "--format", "8E1"}, 0},
    };
    for (const auto &[settings, code] : cases) {
        QProcess scan;
        scan.start(QStringLiteral(JUMOCTL_PATH), QStringList{"scan", "--port", m_tya.master(), "--from", "4", "--to", "4"} + settings);
        QVERIFY(scan.waitForFinished(60000));
        QVERIFY2(scan.exitCode() == code, qPrintable(settings.join(' ') + ": " + scan.readAllStandardError()));
    }
}

void tst_JumoctlFind::networkLinesAndBadListsAreRefused_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("gateway") << QStringList{"--port", "tcp://127.0.0.1:1502"} << "they are its own settings: set them there";
    QTest::newRow("device server") << QStringList{"--port", "rtu+tcp://127.0.0.1:4001"} << "set them there";
    QTest::newRow("no port") << QStringList{} << "give the serial port";
    QTest::newRow("bad baud") << QStringList{"--port", "/dev/null", "--baud", "9600,1234"} << "--baud takes rates";
    QTest::newRow("bad format") << QStringList{"--port", "/dev/null", "--format", "7E1"} << "--format takes 8N1";
    QTest::newRow("range") << QStringList{"--port", "/dev/null", "--from", "40", "--to", "3"} << "--from and --to";
    QTest::newRow("not a serial port") << QStringList{"--port", "/dev/null", "--baud", "4800", "--format", "8E1,8N1"}
                                       << QString();
}

void tst_JumoctlFind::networkLinesAndBadListsAreRefused()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    QProcess p;
    p.start(QStringLiteral(JUMOCTL_PATH), QStringList{"find"} + args);
    QVERIFY(p.waitForFinished(30000));
    const QString err = QString::fromUtf8(p.readAllStandardError());
    if (message.isEmpty()) {
        // Not refused: /dev/null is no serial port, which the search says.
        QCOMPARE(p.exitCode(), 1);
        QVERIFY2(err.contains("find: "), qPrintable(err));
        return;
    }
    QCOMPARE(p.exitCode(), 2);
    QVERIFY2(err.contains(message), qPrintable(err));
}

void tst_JumoctlFind::interruptSaysWhatWasFound()
{
    QProcess p;
    p.start(QStringLiteral(JUMOCTL_PATH), {"find", "--port", m_tya.master(), "--baud", "19200", "--format", "8N1,8E1",
                                           "--to", "31"});
    QVERIFY(p.waitForStarted());
    // Until the first setting's answer is out, then stopped.
    QByteArray out;
    QElapsedTimer timer;
    timer.start();
    while (!out.contains("tya200 at address 4") && timer.elapsed() < 60000) {
        p.waitForReadyRead(100);
        out += p.readAllStandardOutput();
    }
    QVERIFY2(out.contains("at 19200 8N1: tya200 at address 4"), out.constData());
    ::kill(pid_t(p.processId()), SIGINT);
    QVERIFY(p.waitForFinished(30000));
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QCOMPARE(p.exitCode(), 130);
    QVERIFY2(err.contains("interrupted: 1 device(s) found before the search stopped"), qPrintable(err));
}

void tst_JumoctlFind::lateAnswerIsNotTakenAtTheNextSetting()
{
    // A TYA 200 set to answer 150 ms late (its own processing is 6 ms at most), outside the
    // range: its late answer to a probe of 255 at 8N2 must not be read at 8N1, the next
    // setting, whose probe asks the same. It failed so before the wait after a lost hint.
    Sim late;
    QVERIFY(startSim(late, {"--baud", "9600", "--format", "8N2", "--min-response", "150", "tya200@100"}));
    QProcess p;
    p.start(QStringLiteral(JUMOCTL_PATH), {"find", "--port", late.master(), "--baud", "9600"});
    QVERIFY(p.waitForFinished(120000));
    const QString out = QString::fromUtf8(p.readAllStandardOutput());
    const QString err = QString::fromUtf8(p.readAllStandardError());
    late.process.terminate();
    late.process.waitForFinished(5000);
    QCOMPARE(p.exitCode(), 0);
    QCOMPARE(out.trimmed(), QStringLiteral("at 9600 8N2: address 255 answers as tya200, as every tya200 does whatever its "
                                           "own address; its own is outside 1..31 (--from and --to look further)"));
    QVERIFY2(err.contains("the line's settings where the most answered: --baud 9600 --format 8N2"), qPrintable(err));
}

QTEST_GUILESS_MAIN(tst_JumoctlFind)
#include "tst_jumoctl_find.moc"
