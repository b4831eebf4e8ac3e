// Whether each device of a bus is known to be of the family it was added as. On a bus
// that asks for it (the HMI), a device is checked with the families' identify probes
// when it first answers and whenever it answers again after being gone (offline, the
// line lost or closed). Until it is confirmed its values are not shown and nothing is
// written to it; another device at its address is refused, named, until it is gone.
#pragma once

#include "bus/transaction.h"
#include "protocol/registermap.h"

#include <QDateTime>
#include <QHash>
#include <QObject>

#include <memory>

namespace jumo {

class Bus;
class IdentityCheck;

class DeviceIdentities : public QObject
{
    Q_OBJECT

public:
    enum class State { Unconfirmed, Confirmed, Refused };

    explicit DeviceIdentities(Bus &bus, QObject *parent = nullptr);
    ~DeviceIdentities() override;

    // The families that may answer (every known one, to name what answers instead).
    // Empty: no checks, every device counts as confirmed.
    void setFamilies(const QList<std::shared_ptr<const RegisterMap>> &families);
    bool isChecking() const { return !m_families.isEmpty(); }

    State state(DeviceId id) const;
    // The sentence naming what answers instead (Refused), or why no check succeeded yet.
    QString reason(DeviceId id) const;
    QDateTime since(DeviceId id) const;
    // Values may be shown and writes sent.
    bool isTrusted(DeviceId id) const { return state(id) == State::Confirmed; }

    // The device answered a poll: checked now unless it is trusted, refused or under check.
    void heard(DeviceId id);
    // The device was gone (offline): checked again when it answers.
    void forget(DeviceId id);
    // The line was lost or closed: every device is checked again.
    void forgetAll();
    void removeDevice(DeviceId id);

signals:
    void changed(jumo::DeviceId id);

private:
    struct Identity
    {
        State state = State::Unconfirmed;
        QString reason;
        QDateTime since;
        qint64 lastTryMs = -1;   // bus clock; a silent check is tried again after a pause
    };

    void checkNext();
    void onCheckFinished();
    void set(DeviceId id, State state, const QString &reason);

    Bus &m_bus;
    QList<std::shared_ptr<const RegisterMap>> m_families;
    QHash<DeviceId, Identity> m_identities;
    QList<DeviceId> m_queue;
    std::unique_ptr<IdentityCheck> m_check;
    DeviceId m_checking = 0;
    bool m_checkStale = false;   // the device was gone while its check ran
};

} // namespace jumo
