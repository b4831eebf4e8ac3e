// The values of every device on a line with their validity, and the device's request
// statistics. Values turn current when a block is read, stale when their poll class's
// allowance passes without a new reading (a setting read every minute is current for
// two; an alarm word read every second for three seconds), and unknown when the read,
// the device or the line fails; the last value is kept as "last known", never shown as
// current.
#pragma once

#include "bus/devicestatistics.h"
#include "bus/entrystate.h"
#include "bus/modbusrequest.h"
#include "protocol/registermap.h"

#include <QHash>
#include <QSet>
#include <QStringList>

#include <array>
#include <memory>

namespace jumo {

using DeviceId = int;

class ValueStore
{
public:
    void addDevice(DeviceId id, std::shared_ptr<const RegisterMap> map);
    void removeDevice(DeviceId id);
    bool contains(DeviceId id) const { return m_devices.contains(id); }

    const EntryState *state(DeviceId id, const QString &entryId) const;
    const DeviceStatistics *statistics(DeviceId id) const;
    DeviceStatistics *statistics(DeviceId id);
    // A request to the device ended so: its statistics count it.
    void count(DeviceId device, const ModbusResult &result, double roundTripMs);

    // How long a value stays current after it was read: per class, each entry in the
    // class it is read in (entries not named: live).
    void setAllowance(DeviceId id, qint64 ms);
    void setAllowance(DeviceId id, PollClass pollClass, qint64 ms);
    void setClasses(DeviceId id, const QHash<QString, PollClass> &classes);
    // The live values a view shows and their allowance (shorter than the live class's).
    void setShownLive(DeviceId id, const QSet<QString> &entryIds, qint64 ms);
    qint64 allowance(DeviceId id, PollClass pollClass = PollClass::Live) const;
    qint64 allowance(DeviceId id, const QString &entryId) const;

    // A block arrived: the entries inside it are decoded and current. Returns their ids.
    QStringList store(DeviceId id, const QList<const RegisterEntry *> &entries, quint16 start,
                      const QList<quint16> &words, qint64 now);
    // The entries could not be read: unknown from now on, for this reason.
    QStringList fail(DeviceId id, const QList<const RegisterEntry *> &entries, ReadError error, int exceptionCode,
                     qint64 now);
    // Every entry of the device that is not unknown already turns unknown (the device went
    // offline, the line was lost or closed). Returns the ids that changed.
    QStringList invalidate(DeviceId id, ReadError reason, qint64 now);
    // Current values older than the allowance turn stale. Returns the ids that changed.
    QStringList sweep(DeviceId id, qint64 now);
    // The earliest time a current value of the device turns stale, or -1.
    qint64 nextStaleMs(DeviceId id) const;

private:
    struct Device
    {
        std::shared_ptr<const RegisterMap> map;
        QHash<QString, EntryState> values;
        DeviceStatistics stats;
        std::array<qint64, 3> allowanceMs{10000, 10000, 10000};
        QHash<QString, PollClass> classes;
        QSet<QString> shownLive;
        qint64 shownAllowanceMs = 0;
        // The allowance of the class a value was read in: a setting a view has just
        // moved up is as current as it was a moment ago, until it is read again.
        QHash<QString, qint64> readAllowanceMs;

        qint64 classAllowanceOf(const QString &entryId) const
        {
            const qint64 ofClass = allowanceMs[size_t(classes.value(entryId, PollClass::Live))];
            // On a full line the live class's allowance is that of values read once a
            // minute; the ones a view shows are read every few seconds.
            if (shownAllowanceMs > 0 && shownLive.contains(entryId))
                return std::min(ofClass, shownAllowanceMs);
            return ofClass;
        }
        qint64 allowanceOf(const QString &entryId) const
        {
            return std::max(classAllowanceOf(entryId), readAllowanceMs.value(entryId, 0));
        }
    };

    QHash<DeviceId, Device> m_devices;
};

} // namespace jumo
