// Reads all parameters of a device on a bus into a ParameterSet, and writes a list of
// differences back one by one, each verified by read-back: with progress and cancel,
// for the HMI's backup, compare and restore.
#pragma once

#include "bus/bus.h"
#include "commissioning/parameterset.h"

namespace jumo {

class ParameterTransfer : public QObject
{
    Q_OBJECT

public:
    ParameterTransfer(Bus *bus, DeviceId device, QObject *parent = nullptr);

    // Waits until every parameter has been read afresh (polling keeps going).
    void read();
    // Writes the new values of the differences, in order.
    void write(const QList<ParameterDifference> &differences);
    void cancel();
    bool isBusy() const { return m_reading || !m_pending.isEmpty() || m_ticket >= 0; }

signals:
    void progress(int done, int total);
    void readFinished(const jumo::ParameterSet &set, const QStringList &failed);
    void entryWritten(const QString &id, const jumo::WriteOutcome &outcome);
    void writeFinished(int succeeded, int failed, bool cancelled);

private:
    void onEntriesUpdated(DeviceId device, const QStringList &ids);
    void finishRead();
    void writeNext();

    Bus *m_bus;
    DeviceId m_device;
    QStringList m_ids;
    QSet<QString> m_fresh;
    qint64 m_startMs = 0;
    bool m_reading = false;
    QList<ParameterDifference> m_pending;
    int m_total = 0;
    int m_ticket = -1;
    int m_succeeded = 0;
    int m_failed = 0;
    bool m_cancelled = false;
};

} // namespace jumo
