// jumo-publisher's command line, in-process: what it refuses, and that it says why.
#include "mqtt/publisherprogram.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace jumo;

class TstJumoPublisher : public QObject
{
    Q_OBJECT

private slots:
    void refused_data();
    void refused();
    void passwordFileMissing();
    void serviceIsNotRestartedWhenTheNameIsTaken();
};

void TstJumoPublisher::refused_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QStringList line{"--port", "/dev/null", "--device", "ipc300@1"};
    QTest::newRow("no broker") << line << "--broker is required";
    QTest::newRow("password in the url") << QStringList{"--broker", "mqtt://u:hunter2@host"} + line
                                         << "password file or JUMO_MQTT_PASSWORD";
    // An address Qt cannot parse is shown in the message: never with its password.
    QTest::newRow("password in a url with a bad port") << QStringList{"--broker", "mqtt://u:hunter2@host:99999"} + line
                                                       << "mqtt://u:***@host:99999";
    QTest::newRow("password in a url with a bad host") << QStringList{"--broker", "mqtt://u:hunter2@ho st"} + line
                                                       << "no broker address";
    QTest::newRow("password with a space in a url") << QStringList{"--broker", "mqtt://u:hun ter2@host"} + line
                                                    << "no broker address";
    QTest::newRow("password option does not exist") << QStringList{"--broker", "mqtt://host", "--password", "x"} + line
                                                    << "Unknown option 'password'";
    QTest::newRow("tls files without mqtts") << QStringList{"--broker", "mqtt://host", "--tls-ca", "/etc/hostname"} + line
                                             << "TLS files need an mqtts:// broker";
    QTest::newRow("station name with a slash") << QStringList{"--broker", "mqtt://host", "--name", "hall/3"} + line
                                               << "cannot be a station name";
    QTest::newRow("wildcard prefix") << QStringList{"--broker", "mqtt://host", "--prefix", "jumo/#"} + line
                                     << "cannot be a topic prefix";
    QTest::newRow("prefix with a line end") << QStringList{"--broker", "mqtt://host", "--prefix", "jumo\nplant"} + line
                                            << "'jumo\\x0aplant' cannot be a topic prefix";
    QTest::newRow("prefix in the broker's own topics") << QStringList{"--broker", "mqtt://host", "--prefix", "$SYS"} + line
                                                       << "'$SYS' cannot be a topic prefix";
    QTest::newRow("prefix starting with $") << QStringList{"--broker", "mqtt://host", "--prefix", "$jumo/a"} + line
                                            << "not starting with '$'";
    QTest::newRow("no lines") << QStringList{"--broker", "mqtt://host", "--device", "ipc300@1"}
                              << "give the lines by one of --station";
    QTest::newRow("port and line") << QStringList{"--broker", "mqtt://host", "--line", "/dev/null"} + line
                                   << "give the lines by one of --station";
    QTest::newRow("no device") << QStringList{"--broker", "mqtt://host", "--port", "/dev/null"}
                               << "name at least one device";
    QTest::newRow("unknown family") << QStringList{"--broker", "mqtt://host", "--port", "/dev/null", "--device", "s7@1"}
                                    << "s7";
    QTest::newRow("device twice") << QStringList{"--broker", "mqtt://host", "--port", "/dev/null", "--device",
                                                 "ipc300@1", "--device", "ipc300@1"}
                                  << "named twice";
    QTest::newRow("ambiguous device on two lines")
            << QStringList{"--broker", "mqtt://host", "--line", "/dev/null,name=a", "--line", "/dev/zero,name=b",
                           "--device", "ipc300@1"}
            << "ipc300@1";
    QTest::newRow("station file and devices") << QStringList{"--broker", "mqtt://host", "--station", "/nonexistent.json",
                                                             "--device", "ipc300@1"}
                                              << "a station file lists its devices";
    QTest::newRow("missing station file") << QStringList{"--broker", "mqtt://host", "--station", "/nonexistent.json"}
                                          << "/nonexistent.json";
    QTest::newRow("poll without a family") << QStringList{"--broker", "mqtt://host", "--poll", "load_voltage"} + line
                                           << "is not FAMILY:ENTRY";
    QTest::newRow("poll of an unknown family") << QStringList{"--broker", "mqtt://host", "--poll", "s7:x"} + line
                                               << "unknown family 's7'";
    QTest::newRow("poll of an unknown entry") << QStringList{"--broker", "mqtt://host", "--poll", "ipc300:faceplate,nope"}
                    + line << "'nope' is no entry of ipc300";
    QTest::newRow("poll of a write-only entry")
            << QStringList{"--broker", "mqtt://host", "--poll", "ipc300:binary_signal_write"} + line << "cannot be read";
    QTest::newRow("poll of nothing") << QStringList{"--broker", "mqtt://host", "--poll", "ipc300:"} + line
                                     << "name at least one entry of ipc300";
    QTest::newRow("poll of a family twice")
            << QStringList{"--broker", "mqtt://host", "--poll", "ipc300:alarms", "--poll", "ipc300:faceplate"} + line
            << "names ipc300 twice";
    QTest::newRow("heartbeat too fast") << QStringList{"--broker", "mqtt://host", "--heartbeat", "5"} + line
                                        << "--heartbeat must be";
}

void TstJumoPublisher::refused()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QString out;
    QString err;
    QTextStream outStream(&out);
    QTextStream errStream(&err);
    PublisherProgram program(outStream, errStream);
    QCOMPARE(program.run(arguments), std::optional<int>(2));
    QVERIFY2(err.contains(message), qPrintable(err));
    QVERIFY2(!err.contains(QLatin1String("hunter2")) && !err.contains(QLatin1String("hun ter2")), qPrintable(err));
    QVERIFY(!program.publisher());
}

void TstJumoPublisher::passwordFileMissing()
{
    QTemporaryDir dir;
    QString out;
    QString err;
    QTextStream outStream(&out);
    QTextStream errStream(&err);
    PublisherProgram program(outStream, errStream);
    QCOMPARE(program.run({"--broker", "mqtt://station@host", "--password-file", dir.filePath("none"), "--port",
                          "/dev/null", "--device", "ipc300@1"}),
             std::optional<int>(2));
    QVERIFY2(err.contains(QLatin1String("cannot read the password file")), qPrintable(err));
}

void TstJumoPublisher::serviceIsNotRestartedWhenTheNameIsTaken()
{
    // A station of the name online: starting again and again changes nothing.
    QFile unit(QStringLiteral(JUMO_SYSTEMD_UNIT));
    QVERIFY(unit.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(unit.readAll());
    QVERIFY(text.contains(QStringLiteral("\nRestartPreventExitStatus=%1\n").arg(PublisherProgram::nameTakenExitCode)));
    QVERIFY(text.contains(QLatin1String("\nRestart=on-failure\n")));
    QVERIFY(text.contains(QLatin1String("--broker mqtt://publisher@")));   // the user of resources/mosquitto/jumo.acl
}

QTEST_GUILESS_MAIN(TstJumoPublisher)
#include "tst_jumopublisher.moc"
