#include "sim/ptypair.h"

#include <QDir>
#include <QFileInfo>

#include <csignal>
#include <utility>
#include <sys/prctl.h>

namespace jumo {

PtyPair::PtyPair(QObject *parent) : QObject(parent)
{
    // socat goes when we go, however we go: even a killed HMI leaves no orphan behind.
    m_socat.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGTERM); });
    m_poll.setInterval(10);
    connect(&m_poll, &QTimer::timeout, this, &PtyPair::poll);
    connect(&m_socat, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
        if (error == QProcess::FailedToStart) {
            m_poll.stop();
            emit failed(tr("cannot start socat (is it installed?): %1").arg(m_socat.errorString()));
        }
    });
    connect(&m_socat, &QProcess::finished, this, [this] {
        m_poll.stop();
        if (m_stopping)
            return;
        const bool wasReady = std::exchange(m_ready, false);
        if (!wasReady)
            emit failed(tr("socat ended: %1").arg(QString::fromLocal8Bit(m_socat.readAllStandardError()).trimmed()));
        else
            emit ended();
    });
}

PtyPair::~PtyPair()
{
    stop();
}

void PtyPair::start(const QString &directory)
{
    QDir().mkpath(directory);
    m_deviceEnd = QDir(directory).filePath(QStringLiteral("device"));
    m_masterEnd = QDir(directory).filePath(QStringLiteral("master"));
    QFile::remove(m_deviceEnd);
    QFile::remove(m_masterEnd);
    m_ready = false;
    m_stopping = false;
    m_polls = 0;
    m_socat.start(QStringLiteral("socat"),
                  {QStringLiteral("pty,raw,echo=0,link=") + m_deviceEnd, QStringLiteral("pty,raw,echo=0,link=") + m_masterEnd});
    m_poll.start();
}

void PtyPair::poll()
{
    if (QFileInfo::exists(m_deviceEnd) && QFileInfo::exists(m_masterEnd)) {
        m_poll.stop();
        m_ready = true;
        emit ready();
        return;
    }
    if (++m_polls > 500) {   // 5 s: socat normally needs about 20 ms
        m_poll.stop();
        emit failed(tr("socat did not create the pseudo-terminals"));
    }
}

void PtyPair::stop()
{
    m_poll.stop();
    m_ready = false;
    m_stopping = true;   // asked for: neither failed() nor ended()
    if (m_socat.state() != QProcess::NotRunning) {
        // SIGTERM lets socat remove its links.
        m_socat.terminate();
        if (!m_socat.waitForFinished(2000))
            m_socat.kill();
    }
    m_ready = false;
}

} // namespace jumo
