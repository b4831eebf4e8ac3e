// Test fixtures for integration tests: a socat pseudo-terminal line in a temporary
// folder, and two interchangeable peers on its far end: our simulator (in-process) and
// the independent libmodbus server (tests/peers, a separate process).
#pragma once

#include "protocol/familyregistry.h"
#include "sim/ptypair.h"
#include "sim/simulatorline.h"

#include <QFileInfo>
#include <QProcess>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

namespace jumo::test {

inline const FamilyRegistry &families()
{
    static const FamilyRegistry registry = FamilyRegistry::load({}, true);
    return registry;
}

// Entries the bus tests poll, and the value a peer's slave holds in each.
inline const QStringList polledIds{"load_voltage", "analog_output_value"};

inline double expectedValue(const QString &id, quint8 slave)
{
    return (id == "load_voltage" ? 200.0 : 40.0) + slave;
}

inline LineFormat testFormat()
{
    return *LineFormat::parse(19200, QStringLiteral("8N1"));
}

// A null-modem pty pair made by socat in its own temporary folder.
class TestLine
{
public:
    bool start()
    {
        if (!m_dir.isValid())
            return false;
        QSignalSpy ready(&m_pty, &PtyPair::ready);
        m_pty.start(m_dir.path());
        return m_pty.isReady() || ready.wait(10000);
    }
    void stop() { m_pty.stop(); }
    // Makes the pair again at the same paths, as an adapter plugged back in.
    bool restart()
    {
        QSignalSpy ready(&m_pty, &PtyPair::ready);
        m_pty.start(m_dir.path());
        return m_pty.isReady() || ready.wait(10000);
    }
    QString deviceEnd() const { return m_pty.deviceEnd(); }
    QString masterEnd() const { return m_pty.masterEnd(); }
    qint64 socatPid() const { return m_pty.processId(); }

private:
    QTemporaryDir m_dir;
    PtyPair m_pty;
};

// What a test needs from the device end of the line, whoever implements it.
class Peer
{
public:
    virtual ~Peer() = default;
    virtual QString name() const = 0;
    virtual bool start(const QString &port, const QList<quint8> &slaves) = 0;
    virtual void stop() = 0;
    virtual bool setWords(quint8 slave, quint16 address, const QList<quint16> &words) = 0;
    virtual QList<quint16> words(quint8 slave, quint16 address, int count) = 0;
    // mode: none, drop, late, stray, badcrc, exception, dead; count -1 = until cleared.
    virtual bool setFault(quint8 slave, const QString &mode, int count = -1, int argument = 0) = 0;
    // Write frames (0x06, 0x10) that reached the peer so far.
    virtual int writeFrames() = 0;
};

class SimulatorPeer : public Peer
{
public:
    explicit SimulatorPeer(const QString &family = QStringLiteral("ipc300")) : m_family(family) { }

    QString name() const override { return QStringLiteral("simulator"); }

    bool start(const QString &port, const QList<quint8> &slaves) override
    {
        for (quint8 s : slaves)
            m_line.addDevice(families().family(m_family), s);
        m_port = port;
        return m_line.open(port, testFormat());
    }
    void stop() override { m_line.close(); }
    // ipc300@1, tya200@2, quantrol@3 and dtron300@4, their models running.
    bool startOneOfEachFamily(const QString &port)
    {
        quint8 address = 1;
        for (const char *family : {"ipc300", "tya200", "quantrol", "dtron300"})
            m_line.addDevice(families().family(family), address++);
        m_line.setTickInterval(100);
        return start(port, {});
    }
    bool reopen() { return m_line.open(m_port, testFormat()); }

    bool setWords(quint8 slave, quint16 address, const QList<quint16> &words) override
    {
        return m_line.device(slave) && m_line.device(slave)->setWords(address, words);
    }

    QList<quint16> words(quint8 slave, quint16 address, int count) override
    {
        QList<quint16> out;
        for (int i = 0; i < count; ++i)
            out << m_line.device(slave)->word(quint16(address + i));
        return out;
    }

    bool setFault(quint8 slave, const QString &mode, int count, int argument) override
    {
        Fault f;
        f.remaining = count;
        if (mode == "none")
            f.mode = FaultMode::None;
        else if (mode == "drop")
            f.mode = FaultMode::Drop;
        else if (mode == "late")
            f.mode = FaultMode::Late, f.lateMs = argument;
        else if (mode == "stray")
            f.mode = FaultMode::StrayByte;
        else if (mode == "badcrc")
            f.mode = FaultMode::BadCrc;
        else if (mode == "exception")
            f.mode = FaultMode::Exception, f.exceptionCode = argument;
        else if (mode == "dead")
            f.mode = FaultMode::Dead;
        else
            return false;
        m_line.setFault(slave, f);
        return true;
    }

    int writeFrames() override { return m_line.writeRequestsReceived(); }

    SimulatorLine &line() { return m_line; }

private:
    QString m_family;
    QString m_port;
    SimulatorLine m_line;
};

// The libmodbus server, driven through its stdin/stdout protocol.
class LibmodbusPeer : public Peer
{
public:
    ~LibmodbusPeer() override { stop(); }

    QString name() const override { return QStringLiteral("libmodbus"); }

    bool start(const QString &port, const QList<quint8> &slaves) override
    {
        QStringList args{"--port", port, "--baud", "19200", "--format", "8N1"};
        for (quint8 s : slaves)
            args << "--slave" << QString::number(s);
        m_process.setProcessChannelMode(QProcess::SeparateChannels);
        m_process.start(QStringLiteral(JUMO_TEST_PEER), args);
        return waitForLine("ready");
    }

    // As a Modbus TCP gateway on 127.0.0.1 (port 0: a free one, see tcpPort()).
    bool startTcp(const QList<quint8> &slaves, quint16 port = 0)
    {
        QStringList args{"--tcp", QString::number(port)};
        for (quint8 s : slaves)
            args << "--slave" << QString::number(s);
        m_writeFrames = 0;
        m_lines.clear();
        m_process.setProcessChannelMode(QProcess::SeparateChannels);
        m_process.start(QStringLiteral(JUMO_TEST_PEER), args);
        if (!waitForLine("ready"))
            return false;
        return m_tcpPort != 0;
    }
    quint16 tcpPort() const { return m_tcpPort; }
    // The gateway dies (SIGKILL to this peer's own process only).
    void kill()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.kill();
        m_process.waitForFinished(3000);
    }

    void stop() override
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.write("quit\n");
        if (!m_process.waitForFinished(3000))
            m_process.kill();
        m_process.waitForFinished(1000);
    }

    bool setWords(quint8 slave, quint16 address, const QList<quint16> &words) override
    {
        QString line = QStringLiteral("set %1 %2").arg(slave).arg(address);
        for (quint16 w : words)
            line += QStringLiteral(" %1").arg(w);
        return command(line);
    }

    QList<quint16> words(quint8 slave, quint16 address, int count) override
    {
        QList<quint16> out;
        if (!command(QStringLiteral("get %1 %2 %3").arg(slave).arg(address).arg(count)))
            return out;
        for (const QString &hex : m_lastRegs)
            out << quint16(hex.toUInt(nullptr, 16));
        return out;
    }

    bool setFault(quint8 slave, const QString &mode, int count, int argument) override
    {
        QString line = QStringLiteral("fault %1 %2").arg(slave).arg(mode);
        if (mode == "late" || mode == "exception")
            line += QStringLiteral(" %1").arg(argument);
        if (count > 0 && mode != "dead" && mode != "none")
            line += QStringLiteral(" %1").arg(count);
        return command(line);
    }

    int writeFrames() override
    {
        readAvailable();
        return m_writeFrames;
    }

private:
    bool command(const QString &line)
    {
        m_process.write(line.toLatin1() + '\n');
        return waitForLine("ok");
    }

    // Reads what the peer printed, counting the write frames it received.
    void readAvailable()
    {
        while (m_process.canReadLine()) {
            const QString line = QString::fromLatin1(m_process.readLine()).trimmed();
            if (line.startsWith("rx ") && line.size() >= 7) {
                const QString function = line.mid(5, 2);
                if (function == "06" || function == "10")
                    ++m_writeFrames;
            } else if (line.startsWith("regs ")) {
                m_lastRegs = line.mid(5).split(' ', Qt::SkipEmptyParts);
            } else if (line.startsWith("listening ")) {
                m_tcpPort = quint16(line.mid(10).toUInt());
            }
            m_lines << line;
        }
    }

    bool waitForLine(const QString &wanted)
    {
        QElapsedTimer timer;
        timer.start();
        while (timer.elapsed() < 10000) {
            readAvailable();
            const qsizetype index = m_lines.indexOf(wanted);
            if (index >= 0) {
                m_lines.remove(0, index + 1);
                return true;
            }
            for (const QString &l : std::as_const(m_lines)) {
                if (l.startsWith("error"))
                    return false;
            }
            if (m_process.state() == QProcess::NotRunning)
                return false;
            // Keep the event loop going: the client under test lives on it.
            QTest::qWait(5);
        }
        return false;
    }

    QProcess m_process;
    QStringList m_lines;
    QStringList m_lastRegs;
    int m_writeFrames = 0;
    quint16 m_tcpPort = 0;
};

// A free TCP port on 127.0.0.1 at the moment of asking (for programs that cannot be
// told to pick one themselves).
inline quint16 freeTcpPort()
{
    QTcpServer probe;
    return probe.listen(QHostAddress::LocalHost, 0) ? probe.serverPort() : 0;
}

// A serial device server as socat makes one: a pty (where a peer serves the devices)
// bridged to one TCP connection on 127.0.0.1. Raw bytes both ways, as an NPort does.
// socat ends with that connection (its fork option would let an old child still read
// the pty while the next client's is already there).
class DeviceServer
{
public:
    ~DeviceServer() { kill(); }

    bool start(quint16 port = 0)
    {
        if (!m_dir.isValid())
            return false;
        for (int attempt = 0; attempt < 5; ++attempt) {
            m_port = port ? port : freeTcpPort();
            QFile::remove(ptyPath());
            m_process.setProcessChannelMode(QProcess::SeparateChannels);
            // The pty first: socat opens it at once, then waits for the one connection.
            m_process.start(QStringLiteral("socat"),
                            {"-d", "-d", QStringLiteral("PTY,link=%1,raw,echo=0").arg(ptyPath()),
                             QStringLiteral("TCP-LISTEN:%1,bind=127.0.0.1,reuseaddr").arg(m_port)});
            if (!m_process.waitForStarted(5000))
                return false;
            QElapsedTimer timer;
            timer.start();
            QByteArray err;
            while (timer.elapsed() < 10000 && m_process.state() == QProcess::Running) {
                err += m_process.readAllStandardError();
                if (err.contains("listening on") && QFileInfo::exists(ptyPath()))
                    return true;
                QTest::qWait(10);
            }
            kill();
            if (port)
                QTest::qWait(200);   // the same port: perhaps not free again yet
        }
        return false;
    }
    // The device server goes away (SIGKILL to this socat only): the connection drops, the pty closes.
    void kill()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.kill();
        m_process.waitForFinished(3000);
    }
    QString ptyPath() const { return m_dir.filePath("ttyServer"); }
    quint16 port() const { return m_port; }
    QString url() const { return QStringLiteral("rtu+tcp://127.0.0.1:%1").arg(m_port); }

private:
    QTemporaryDir m_dir;
    QProcess m_process;
    quint16 m_port = 0;
};

inline std::unique_ptr<Peer> makePeer(const QString &name)
{
    if (name == "libmodbus")
        return std::make_unique<LibmodbusPeer>();
    return std::make_unique<SimulatorPeer>();
}

} // namespace jumo::test
