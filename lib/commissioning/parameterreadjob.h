// Reads every parameter of a device afresh, with its identity, into a ParameterSet: a job
// in the bus's job lane, so the devices being monitored keep their polls meanwhile.
#pragma once

#include "bus/bus.h"
#include "bus/job.h"
#include "commissioning/parameterset.h"

namespace jumo {

class ParameterReadJob : public Job
{
    Q_OBJECT

public:
    ParameterReadJob(Bus *bus, DeviceId device, QObject *parent = nullptr);

    void start();
    // After finished(): the parameters read, and the ids that could not be read.
    const ParameterSet &parameters() const { return m_set; }
    const QStringList &failedIds() const { return m_failed; }

private:
    void onCancel() override { m_bus->cancel(m_ticket); }
    void onEntriesRead(int ticket, const QStringList &failed);

    Bus *m_bus;
    DeviceId m_device;
    QStringList m_ids;
    int m_ticket = -1;
    ParameterSet m_set;
    QStringList m_failed;
};

} // namespace jumo
