// Finds devices on a line and names their family, with each family's identify probes
// from its map. Probe answers are shared between families, so an address costs one
// request per distinct probe, and a silent address one timeout.
#pragma once

#include "bus/job.h"
#include "protocol/registermap.h"

#include <QHash>

#include <memory>

namespace jumo {

class Bus;

class DeviceScanner : public Job
{
    Q_OBJECT

public:
    DeviceScanner(Bus &bus, QList<std::shared_ptr<const RegisterMap>> families, QObject *parent = nullptr);

    // Probes the addresses in the job lane of the bus: devices being monitored keep their
    // polls and keepalives meanwhile. Ends Succeeded, Cancelled, or Failed when the line
    // went away.
    void start(int firstAddress, int lastAddress);

signals:
    void progress(int address, int done, int total);
    void found(int address, std::shared_ptr<const jumo::RegisterMap> family);
    // An address answered but matched no family.
    void unknownDevice(int address);
    // Just before unknownDevice: the address answered some probes, then no more, so
    // whether another family would have matched is not known.
    void answeredPartly(int address);

private:
    struct ProbeResult
    {
        bool timedOut = false;
        int exceptionCode = 0;
        QList<quint16> words;
    };

    void nextAddress();
    void evaluate();
    void onProbeFinished(int ticket, const QList<quint16> &words, bool timedOut, int exceptionCode);
    static bool passes(const IdentifyProbe &probe, const ProbeResult &result);

    Bus &m_bus;
    QList<std::shared_ptr<const RegisterMap>> m_families;   // in scan order
    ProtocolInfo m_slowest;                                   // timing that fits every family
    QHash<quint64, ProbeResult> m_cache;                      // (register, words) -> answer
    int m_address = 0;
    int m_last = 0;
    int m_first = 0;
    int m_pendingTicket = -1;
    quint64 m_pendingKey = 0;
    bool m_running = false;
};

} // namespace jumo
