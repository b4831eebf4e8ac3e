#include "commissioning/parametertransfer.h"

namespace jumo {

ParameterTransfer::ParameterTransfer(Bus *bus, DeviceId device, QObject *parent)
    : QObject(parent), m_read(new ParameterReadJob(bus, device, this)), m_write(new ParameterWriteJob(bus, device, this))
{
    connect(m_read, &Job::progressChanged, this, &ParameterTransfer::progress);
    connect(m_write, &Job::progressChanged, this, &ParameterTransfer::progress);
    connect(m_write, &ParameterWriteJob::entryWritten, this, &ParameterTransfer::entryWritten);
    connect(m_read, &Job::finished, this, [this] {
        QStringList failed = m_read->failedIds();
        if (m_read->result() == Job::Result::Cancelled)
            failed = {tr("cancelled")};
        else if (m_read->result() == Job::Result::Failed && failed.isEmpty())
            failed = {m_read->errorText()};
        emit readFinished(m_read->parameters(), failed);
    });
    connect(m_write, &Job::finished, this, [this] {
        emit writeFinished(m_write->succeeded(), m_write->failed(), m_write->result() == Job::Result::Cancelled);
    });
}

void ParameterTransfer::read()
{
    m_read->start();
}

void ParameterTransfer::write(const QList<ParameterDifference> &differences)
{
    m_write->start(differences);
}

void ParameterTransfer::cancel()
{
    m_read->cancel();
    m_write->cancel();
}

} // namespace jumo
