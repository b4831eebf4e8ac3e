#include "bus/identitycheck.h"

#include "bus/devicescanner.h"

#include <algorithm>

namespace jumo {

namespace {

bool sameProbe(const IdentifyProbe &a, const IdentifyProbe &b)
{
    return a.address == b.address && a.words == b.words && a.test == b.test && a.text == b.text && a.mask == b.mask
           && a.exceptionCode == b.exceptionCode;
}

} // namespace

IdentityCheck::IdentityCheck(Bus &bus, QList<std::shared_ptr<const RegisterMap>> families, QObject *parent)
    : Job(parent), m_scanner(std::make_unique<DeviceScanner>(bus, std::move(families)))
{
    connect(m_scanner.get(), &DeviceScanner::found, this,
            [this](int, const std::shared_ptr<const RegisterMap> &family) {
                const bool same = family->family == m_current.claim.family->family
                                  || indistinguishable(*family, *m_current.claim.family);
                m_current.verdict = same ? Verdict::Confirmed : Verdict::OtherFamily;
                m_current.found = family;
            });
    // A device that stopped answering part way (replies lost on a noisy line) is not
    // shown to be another one: refusing it would lock the right device out until it goes
    // offline. It counts as silent and is asked again.
    connect(m_scanner.get(), &DeviceScanner::answeredPartly, this, [this](int) { m_current.partial = true; });
    connect(m_scanner.get(), &DeviceScanner::unknownDevice, this, [this](int) {
        if (!m_current.partial)
            m_current.verdict = Verdict::UnknownDevice;
    });
    connect(m_scanner.get(), &Job::finished, this, &IdentityCheck::onScannerFinished);
}

IdentityCheck::~IdentityCheck() = default;

void IdentityCheck::start(const QList<Claim> &claims)
{
    m_claims = claims;
    m_findings.clear();
    begin();
    checkNext();
}

bool IdentityCheck::indistinguishable(const RegisterMap &a, const RegisterMap &b)
{
    return a.identify.size() == b.identify.size()
           && std::equal(a.identify.cbegin(), a.identify.cend(), b.identify.cbegin(), sameProbe);
}

bool IdentityCheck::foundOtherDevice() const
{
    return std::any_of(m_findings.cbegin(), m_findings.cend(), [](const Finding &f) {
        return f.verdict == Verdict::OtherFamily || f.verdict == Verdict::UnknownDevice;
    });
}

QString IdentityCheck::describe(const Finding &finding)
{
    const QString named = QStringLiteral("%1@%2").arg(finding.claim.family->family).arg(finding.claim.address);
    switch (finding.verdict) {
    case Verdict::Confirmed:
        return tr("%1: confirmed").arg(named);
    case Verdict::OtherFamily:
        return tr("%1 refused: the device at address %2 is a %3 (%4), not a %5")
                .arg(named)
                .arg(finding.claim.address)
                .arg(finding.found->family, finding.found->name, finding.claim.family->family);
    case Verdict::UnknownDevice:
        return tr("%1 refused: the device at address %2 answers, but its identity registers match no known family, "
                  "so it is no %3")
                .arg(named)
                .arg(finding.claim.address)
                .arg(finding.claim.family->family);
    case Verdict::Silent:
        break;
    }
    return tr("%1: no answer at address %2, so its family cannot be confirmed").arg(named).arg(finding.claim.address);
}

void IdentityCheck::checkNext()
{
    if (isCancelled()) {
        finish(Result::Cancelled);
        return;
    }
    if (m_findings.size() == m_claims.size()) {
        QStringList refusals;
        for (const Finding &f : std::as_const(m_findings)) {
            if (f.verdict != Verdict::Confirmed)
                refusals << describe(f);
        }
        finish(refusals.isEmpty() ? Result::Succeeded : Result::Failed, refusals.join(QLatin1Char('\n')));
        return;
    }
    m_current = Finding{m_claims.at(m_findings.size()), Verdict::Silent, nullptr, false};
    m_scanner->start(m_current.claim.address, m_current.claim.address);
}

void IdentityCheck::onScannerFinished()
{
    if (m_scanner->result() == Result::Failed) {
        finish(Result::Failed, m_scanner->errorText());
        return;
    }
    m_findings << m_current;
    checkNext();
}

void IdentityCheck::onCancel()
{
    m_scanner->cancel();
}

} // namespace jumo
