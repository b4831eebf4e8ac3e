// The demo mode's line: a pseudo-terminal pair with the simulator on one end serving one
// device of each family, so the HMI has live values with no hardware.
#pragma once

#include "sim/ptypair.h"
#include "sim/simulatorline.h"

#include <QObject>
#include <QTemporaryDir>

namespace jumo {

class FamilyRegistry;

class DemoLine : public QObject
{
    Q_OBJECT

public:
    explicit DemoLine(const FamilyRegistry &registry, QObject *parent = nullptr);

    // Starts socat and the simulator; ready() gives the port for the client.
    void start();
    SimulatorLine &simulator() { return m_simulator; }
    LineFormat format() const { return m_format; }
    // The demo's devices: family and address, in address order.
    QList<QPair<QString, quint8>> devices() const;

signals:
    void ready(const QString &clientPort);
    void failed(const QString &reason);

private:
    QTemporaryDir m_dir;
    PtyPair m_pty;
    SimulatorLine m_simulator;
    LineFormat m_format;
};

} // namespace jumo
