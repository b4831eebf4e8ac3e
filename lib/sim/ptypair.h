// A null-modem pair of pseudo-terminals made by socat: the simulated line of the demo
// mode, jumo-sim and the integration tests. Started asynchronously; ready() tells when
// both ends exist.
#pragma once

#include <QObject>
#include <QProcess>
#include <QTimer>

namespace jumo {

class PtyPair : public QObject
{
    Q_OBJECT

public:
    explicit PtyPair(QObject *parent = nullptr);
    ~PtyPair() override;

    // Creates the links directory/"device" and directory/"master".
    void start(const QString &directory);
    void stop();

    QString deviceEnd() const { return m_deviceEnd; }   // where the simulator listens
    QString masterEnd() const { return m_masterEnd; }   // where the client connects
    bool isReady() const { return m_ready; }
    // socat's process id while it runs (tests pull a line by ending it), else 0.
    qint64 processId() const { return m_socat.processId(); }

signals:
    // socat ended after the pair was ready: both ends are gone.
    void ended();
    void ready();
    void failed(const QString &reason);

private:
    void poll();

    QProcess m_socat;
    QTimer m_poll;
    QString m_deviceEnd;
    QString m_masterEnd;
    int m_polls = 0;
    bool m_ready = false;
    bool m_stopping = false;
};

} // namespace jumo
