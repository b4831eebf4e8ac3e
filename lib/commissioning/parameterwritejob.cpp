#include "commissioning/parameterwritejob.h"

namespace jumo {

ParameterWriteJob::ParameterWriteJob(Bus *bus, DeviceId device, QObject *parent)
    : Job(parent), m_bus(bus), m_device(device)
{
    connect(m_bus, &Bus::writeFinished, this, [this](int ticket, const WriteOutcome &outcome) {
        if (ticket != m_ticket)
            return;
        m_ticket = -1;
        const ParameterDifference done = m_pending.takeFirst();
        outcome.succeeded() ? ++m_succeeded : ++m_failed;
        emit entryWritten(done.id, outcome);
        emit progressChanged(m_succeeded + m_failed, m_total);
        writeNext();
    });
}

void ParameterWriteJob::start(const QList<ParameterDifference> &differences)
{
    begin();
    m_pending = differences;
    m_total = int(differences.size());
    m_succeeded = 0;
    m_failed = 0;
    emit progressChanged(0, m_total);
    writeNext();
}

void ParameterWriteJob::writeNext()
{
    if (isCancelled() && !m_pending.isEmpty()) {
        finish(Result::Cancelled, tr("cancelled after %1 of %2 writes").arg(m_succeeded + m_failed).arg(m_total));
        return;
    }
    if (m_pending.isEmpty()) {
        finish(m_failed == 0 ? Result::Succeeded : Result::Failed,
               m_failed == 0 ? QString() : tr("%n write(s) failed", nullptr, m_failed));
        return;
    }
    m_ticket = m_bus->write(m_device, m_pending.first().id, m_pending.first().newValue, true, Bus::Lane::Job);
}

} // namespace jumo
