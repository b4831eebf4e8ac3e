#include "sim/demoline.h"

#include "protocol/familyregistry.h"

namespace jumo {

DemoLine::DemoLine(const FamilyRegistry &registry, QObject *parent) : QObject(parent)
{
    m_format = *LineFormat::parse(38400, QStringLiteral("8N1"));
    quint8 address = 1;
    for (const char *family : {"ipc300", "tya200", "quantrol", "dtron300"}) {
        if (const auto map = registry.family(QLatin1String(family)))
            m_simulator.addDevice(map, address++);
    }
    m_simulator.setTickInterval(100);
    connect(&m_pty, &PtyPair::failed, this, &DemoLine::failed);
    // Without its pty the simulator's port only reports hang-ups: it closes.
    connect(&m_pty, &PtyPair::ended, this, [this] {
        m_simulator.close();
        emit failed(tr("the simulated line ended (socat stopped)"));
    });
    connect(&m_pty, &PtyPair::ready, this, [this] {
        QString error;
        if (!m_simulator.open(m_pty.deviceEnd(), m_format, &error)) {
            emit failed(tr("the simulator cannot open %1: %2").arg(m_pty.deviceEnd(), error));
            return;
        }
        // As on a real line, the devices answer only at the line's settings (a change in the
        // connection bar is felt); where the end cannot be watched they answer at any.
        m_simulator.watchClientEnd(m_pty.masterEnd());
        emit ready(m_pty.masterEnd());
    });
}

void DemoLine::start()
{
    if (!m_dir.isValid()) {
        emit failed(tr("no temporary folder for the demo line"));
        return;
    }
    m_pty.start(m_dir.path());
}

QList<QPair<QString, quint8>> DemoLine::devices() const
{
    QList<QPair<QString, quint8>> out;
    for (SimulatedDevice *d : m_simulator.devices())
        out << qMakePair(d->map().family, d->address());
    return out;
}

} // namespace jumo
