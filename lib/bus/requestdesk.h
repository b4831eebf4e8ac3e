// What the users of a bus ask of it beyond polling: writes of values, bit changes,
// broadcasts, setpoint holds, probes and reads of entries. Each passes the checks every
// request passes (read-only mode, the device, the entry, the value, the line) and goes
// to the scheduler as a transaction; a refusal is reported like any outcome, queued,
// with the ticket the caller got. Part of the Bus, which it serves.
#pragma once

#include "bus/transaction.h"
#include "protocol/registermap.h"

#include <QHash>
#include <QStringList>

namespace jumo {

class Bus;

class RequestDesk
{
public:
    explicit RequestDesk(Bus &bus) : m_bus(bus) { }

    int write(DeviceId id, const QString &entryId, const QString &value, bool verify, Transaction::Lane lane);
    int writeBits(DeviceId id, const QString &entryId, const QHash<QString, bool> &bits, Transaction::Lane lane);
    int writeBroadcast(const QString &family, const QString &entryId, const QString &value);
    QString setHold(DeviceId id, const QString &entryId, const QString &value, int intervalMs);
    int probe(quint8 slave, quint16 address, quint16 count, const ProtocolInfo &timing, bool quick);
    int readEntries(DeviceId id, const QStringList &entryIds);

private:
    // The checks every write passes before it may be queued; a refusal is reported.
    bool mayWrite(int ticket, const RegisterMap *map, const QString &entryId);
    // The device is confirmed to be of its family (where the bus checks); else refused.
    bool trusted(int ticket, DeviceId id);

    Bus &m_bus;
};

} // namespace jumo
