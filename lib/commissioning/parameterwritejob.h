// Writes a list of parameter differences to a device one by one, each verified by reading
// it back, in the bus's job lane: the devices being monitored keep their polls and
// keepalives, and a cancel stops after the write under way.
#pragma once

#include "bus/bus.h"
#include "bus/job.h"
#include "commissioning/parameterset.h"

namespace jumo {

class ParameterWriteJob : public Job
{
    Q_OBJECT

public:
    ParameterWriteJob(Bus *bus, DeviceId device, QObject *parent = nullptr);

    void start(const QList<ParameterDifference> &differences);
    int succeeded() const { return m_succeeded; }
    int failed() const { return m_failed; }
    // Differences not written because of a cancel.
    int remaining() const { return int(m_pending.size()); }

signals:
    void entryWritten(const QString &id, const jumo::WriteOutcome &outcome);

private:
    void writeNext();

    Bus *m_bus;
    DeviceId m_device;
    QList<ParameterDifference> m_pending;
    int m_total = 0;
    int m_ticket = -1;
    int m_succeeded = 0;
    int m_failed = 0;
};

} // namespace jumo
