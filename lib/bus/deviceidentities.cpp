#include "bus/deviceidentities.h"

#include "bus/bus.h"
#include "bus/identitycheck.h"

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcBus)

namespace jumo {

namespace {

// A check that got no answer is tried again after this pause while the device answers polls.
constexpr qint64 silentRetryMs = 5000;

} // namespace

DeviceIdentities::DeviceIdentities(Bus &bus, QObject *parent) : QObject(parent), m_bus(bus) { }

DeviceIdentities::~DeviceIdentities()
{
    if (m_check)
        m_check->disconnect(this);
}

void DeviceIdentities::setFamilies(const QList<std::shared_ptr<const RegisterMap>> &families)
{
    m_families = families;
    if (m_check)
        m_check->disconnect(this);
    m_check.reset();
    m_checking = 0;
    m_queue.clear();
    if (!families.isEmpty()) {
        m_check = std::make_unique<IdentityCheck>(m_bus, families);
        connect(m_check.get(), &Job::finished, this, &DeviceIdentities::onCheckFinished);
    }
    const QList<DeviceId> known = m_identities.keys();
    m_identities.clear();
    for (DeviceId id : known)
        emit changed(id);
}

DeviceIdentities::State DeviceIdentities::state(DeviceId id) const
{
    if (!isChecking())
        return State::Confirmed;
    return m_identities.value(id).state;
}

QString DeviceIdentities::reason(DeviceId id) const
{
    return m_identities.value(id).reason;
}

QDateTime DeviceIdentities::since(DeviceId id) const
{
    return m_identities.value(id).since;
}

void DeviceIdentities::heard(DeviceId id)
{
    if (!isChecking())
        return;
    Identity &identity = m_identities[id];
    if (identity.state != State::Unconfirmed || id == m_checking || m_queue.contains(id))
        return;
    const qint64 now = m_bus.clockMs();
    if (identity.lastTryMs >= 0 && now - identity.lastTryMs < silentRetryMs)
        return;
    identity.lastTryMs = now;
    m_queue << id;
    checkNext();
}

void DeviceIdentities::forget(DeviceId id)
{
    if (!isChecking())
        return;
    m_queue.removeAll(id);
    if (id == m_checking)
        m_checkStale = true;
    const bool was = m_identities.contains(id) && m_identities.value(id).state != State::Unconfirmed;
    m_identities.remove(id);
    if (was)
        emit changed(id);
}

void DeviceIdentities::forgetAll()
{
    const QList<DeviceId> known = m_identities.keys();
    for (DeviceId id : known)
        forget(id);
}

void DeviceIdentities::removeDevice(DeviceId id)
{
    m_queue.removeAll(id);
    if (id == m_checking)
        m_checkStale = true;
    m_identities.remove(id);
}

void DeviceIdentities::checkNext()
{
    if (!m_check || m_checking || m_queue.isEmpty())
        return;
    m_checking = m_queue.takeFirst();
    m_checkStale = false;
    const std::shared_ptr<const RegisterMap> map = m_bus.deviceMap(m_checking);
    if (!map) {
        m_checking = 0;
        checkNext();
        return;
    }
    m_check->start({{m_bus.deviceAddress(m_checking), map}});
}

void DeviceIdentities::onCheckFinished()
{
    const DeviceId id = std::exchange(m_checking, 0);
    const bool stale = std::exchange(m_checkStale, false);
    if (!stale && m_bus.deviceMap(id) && m_check->result() != Job::Result::Cancelled) {
        const QList<IdentityCheck::Finding> &findings = m_check->findings();
        const IdentityCheck::Verdict verdict = findings.isEmpty() ? IdentityCheck::Verdict::Silent
                                                                  : findings.first().verdict;
        switch (verdict) {
        case IdentityCheck::Verdict::Confirmed:
            set(id, State::Confirmed, QString());
            break;
        case IdentityCheck::Verdict::OtherFamily:
        case IdentityCheck::Verdict::UnknownDevice:
            set(id, State::Refused, IdentityCheck::describe(findings.first()));
            break;
        case IdentityCheck::Verdict::Silent:
            // Tried again on a later answer, after a pause.
            m_identities[id].reason = findings.isEmpty() ? m_check->errorText() : IdentityCheck::describe(findings.first());
            qCInfo(lcBus).noquote() << m_bus.deviceName(id) << "identity not confirmed:" << m_identities[id].reason;
            break;
        }
    }
    checkNext();
}

void DeviceIdentities::set(DeviceId id, State state, const QString &reason)
{
    Identity &identity = m_identities[id];
    identity.state = state;
    identity.reason = reason;
    identity.since = QDateTime::currentDateTime();
    if (state == State::Refused)
        qCWarning(lcBus).noquote() << reason;
    else
        qCInfo(lcBus).noquote() << m_bus.deviceName(id) << "identity confirmed";
    emit changed(id);
}

} // namespace jumo
