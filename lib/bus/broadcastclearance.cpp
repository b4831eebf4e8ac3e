#include "bus/broadcastclearance.h"

#include "bus/devicescanner.h"
#include "bus/identitycheck.h"

namespace jumo {

BroadcastClearance::BroadcastClearance(Bus &bus, QList<std::shared_ptr<const RegisterMap>> families, QObject *parent)
    : Job(parent), m_scanner(std::make_unique<DeviceScanner>(bus, std::move(families)))
{
    connect(m_scanner.get(), &DeviceScanner::progress, this, [this](int address, int, int) { emit progress(address); });
    connect(m_scanner.get(), &DeviceScanner::found, this,
            [this](int address, const std::shared_ptr<const RegisterMap> &found) {
                if (found->family == m_family->family || IdentityCheck::indistinguishable(*found, *m_family))
                    m_found << quint8(address);
                else
                    refuse(tr("not broadcast: address %1 answers as %2, and the words of %3 mean something else "
                              "to it")
                                   .arg(address)
                                   .arg(found->family, m_family->family));
            });
    connect(m_scanner.get(), &DeviceScanner::unknownDevice, this, [this](int address) {
        refuse(tr("not broadcast: a device of no known family answers at address %1").arg(address));
    });
    connect(m_scanner.get(), &Job::finished, this, [this] {
        if (!m_refusal.isEmpty())
            finish(Result::Failed, m_refusal);
        else if (m_scanner->result() == Result::Succeeded)
            finish(Result::Succeeded);
        else
            finish(m_scanner->result(), m_scanner->errorText());
    });
}

BroadcastClearance::~BroadcastClearance() = default;

void BroadcastClearance::start(std::shared_ptr<const RegisterMap> family)
{
    m_family = std::move(family);
    m_found.clear();
    m_refusal.clear();
    begin();
    m_scanner->start(firstAddress, lastAddress);
}

void BroadcastClearance::refuse(const QString &reason)
{
    if (m_refusal.isEmpty())
        m_refusal = reason;
    m_scanner->cancel();
}

void BroadcastClearance::onCancel()
{
    m_scanner->cancel();
}

} // namespace jumo
