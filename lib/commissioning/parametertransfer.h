// Backup, compare and restore of a device's parameters for the HMI and jumoctl: a read
// job, then (for a restore) a write job, with the signals their callers use. Every signal
// comes from the event loop, never from inside a bus callback.
#pragma once

#include "commissioning/parameterreadjob.h"
#include "commissioning/parameterwritejob.h"

namespace jumo {

class ParameterTransfer : public QObject
{
    Q_OBJECT

public:
    ParameterTransfer(Bus *bus, DeviceId device, QObject *parent = nullptr);

    // Reads every parameter afresh (polling keeps going).
    void read();
    // Writes the new values of the differences, in order, each verified by read-back.
    void write(const QList<ParameterDifference> &differences);
    void cancel();
    bool isBusy() const { return m_read->isRunning() || m_write->isRunning(); }

signals:
    void progress(int done, int total);
    void readFinished(const jumo::ParameterSet &set, const QStringList &failed);
    void entryWritten(const QString &id, const jumo::WriteOutcome &outcome);
    void writeFinished(int succeeded, int failed, bool cancelled);

private:
    ParameterReadJob *m_read;
    ParameterWriteJob *m_write;
};

} // namespace jumo
