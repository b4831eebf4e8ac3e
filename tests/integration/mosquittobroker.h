// Test fixture: Debian's Mosquitto broker on a free local port, with a configuration of
// the test's own in a temporary folder (no persistence: a restart forgets everything
// retained), started and killed by its PID only. Also mosquitto_sub as an independent
// subscriber.
#pragma once

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QHash>
#include <QProcess>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

namespace jumo::test {

inline QString findTool(const QString &name)
{
    const QString found = QStandardPaths::findExecutable(name);
    return found.isEmpty() ? QStandardPaths::findExecutable(name, {QStringLiteral("/usr/sbin"), QStringLiteral("/usr/bin")})
                           : found;
}

class MosquittoBroker
{
public:
    ~MosquittoBroker() { kill(); }

    QString dir() const { return m_dir.path(); }
    QString file(const QString &name) const { return m_dir.filePath(name); }
    quint16 port() const { return m_port; }
    qint64 pid() const { return m_process.processId(); }
    bool isRunning() const { return m_process.state() != QProcess::NotRunning; }

    // extraConfig goes into the listener's section (TLS files, password file). Port 0: a
    // free one, kept for restart().
    bool start(const QString &extraConfig = {}, const QString &listenerOptions = {})
    {
        m_extra = extraConfig;
        m_listenerOptions = listenerOptions;
        m_shipped.clear();
        return launch();
    }
    // A whole configuration, as shipped (resources/mosquitto): its "listener 1883 ..."
    // line gets the test's port, "log_type all" is added; relative file names are taken
    // from this fixture's folder.
    bool startConfig(const QString &configuration)
    {
        m_shipped = configuration;
        return launch();
    }
    bool restart() { return launch(); }

private:
    bool launch()
    {
        if (!m_dir.isValid())
            return false;
        if (m_port == 0) {
            QTcpServer probe;
            if (!probe.listen(QHostAddress::LocalHost))
                return false;
            m_port = probe.serverPort();
        }
        QFile config(file(QStringLiteral("mosquitto.conf")));
        if (!config.open(QIODevice::WriteOnly))
            return false;
        QByteArray text;
        // As root, Mosquitto would become the user "mosquitto", who cannot read this folder.
        if (::geteuid() == 0)
            text += "user root\n";
        if (!m_shipped.isEmpty()) {
            QString shipped = m_shipped;
            shipped.replace(QStringLiteral("listener 1883 127.0.0.1"), QStringLiteral("listener %1 127.0.0.1").arg(m_port));
            text += shipped.toUtf8() + "\nlog_type all\n";
        } else {
            text += "per_listener_settings true\npersistence false\nlog_dest stderr\nlog_type all\n";
            text += QStringLiteral("listener %1 127.0.0.1\n").arg(m_port).toUtf8();
            text += m_extra.isEmpty() ? QByteArray("allow_anonymous true\n") : m_extra.toUtf8();
        }
        config.write(text);
        config.close();
        const QString broker = findTool(QStringLiteral("mosquitto"));
        if (broker.isEmpty()) {
            qWarning("mosquitto is not installed (.ci/setup installs it)");
            return false;
        }
        m_process.setProcessChannelMode(QProcess::MergedChannels);
        m_process.setStandardOutputFile(file(QStringLiteral("mosquitto.log")), QIODevice::Append);
        m_process.setWorkingDirectory(m_dir.path());
        m_process.start(broker, {QStringLiteral("-c"), config.fileName()});
        if (!m_process.waitForStarted(10000))
            return false;
        // Ready when it accepts connections.
        for (int i = 0; i < 200 && isRunning(); ++i) {
            QTcpSocket socket;
            socket.connectToHost(QHostAddress::LocalHost, m_port);
            if (socket.waitForConnected(100))
                return true;
            QTest::qWait(50);
        }
        qWarning().noquote() << "mosquitto did not start:" << log();
        return false;
    }

public:
    // SIGKILL to our broker's PID: no goodbye to anyone, nothing saved.
    void kill()
    {
        if (!isRunning())
            return;
        m_process.kill();
        m_process.waitForFinished(10000);
    }
    QString log() const
    {
        QFile f(file(QStringLiteral("mosquitto.log")));
        return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
    }

private:
    QTemporaryDir m_dir;
    QProcess m_process;
    quint16 m_port = 0;
    QString m_extra;
    QString m_listenerOptions;
    QString m_shipped;
};

// mosquitto_sub as a fresh, independent subscriber: the retained messages under a filter
// as they arrive on subscribing (it ends at the first message that is not retained, or
// after waitS seconds). Topic -> payload.
inline QHash<QString, QByteArray> retainedMessages(quint16 port, const QString &filter, const QStringList &extra = {},
                                                   int waitS = 10)
{
    QProcess sub;
    QStringList args{QStringLiteral("-h"), QStringLiteral("127.0.0.1"), QStringLiteral("-p"), QString::number(port),
                     QStringLiteral("-v"), QStringLiteral("-t"), filter, QStringLiteral("--retained-only"),
                     QStringLiteral("-W"), QString::number(waitS)};
    sub.start(findTool(QStringLiteral("mosquitto_sub")), args + extra);
    // Waited for with the event loop running: a simulator in the test's own process
    // answers the station's requests meanwhile. A blocking wait of seconds starved it,
    // the station's reads timed out and its values were published as unknown.
    QElapsedTimer waited;
    waited.start();
    while (sub.state() != QProcess::NotRunning && waited.elapsed() < (waitS + 10) * 1000)
        QTest::qWait(20);
    QHash<QString, QByteArray> messages;
    for (const QByteArray &line : sub.readAllStandardOutput().split('\n')) {
        const qsizetype space = line.indexOf(' ');
        if (space > 0)
            messages.insert(QString::fromUtf8(line.left(space)), line.mid(space + 1));
    }
    return messages;
}

} // namespace jumo::test
