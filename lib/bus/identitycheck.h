// Confirms that the devices a command names are of the family it names, with the scan's
// own judgement (the identify probes of every map, in scan order), before anything is
// read from them or written to them: a wrong family reads and writes the wrong words.
#pragma once

#include "bus/job.h"
#include "protocol/registermap.h"

#include <memory>

namespace jumo {

class Bus;
class DeviceScanner;

class IdentityCheck : public Job
{
    Q_OBJECT

public:
    struct Claim
    {
        quint8 address = 0;
        std::shared_ptr<const RegisterMap> family;
    };
    enum class Verdict { Confirmed, OtherFamily, UnknownDevice, Silent };
    struct Finding
    {
        Claim claim;
        Verdict verdict = Verdict::Silent;
        std::shared_ptr<const RegisterMap> found;   // OtherFamily: what answers instead
        bool partial = false;                       // Silent: some probes were answered
    };

    IdentityCheck(Bus &bus, QList<std::shared_ptr<const RegisterMap>> families, QObject *parent = nullptr);
    ~IdentityCheck() override;

    // Checks the claims one after the other in the job lane. Ends Succeeded when every
    // device is confirmed, else Failed with one sentence per device in errorText().
    void start(const QList<Claim> &claims);

    const QList<Finding> &findings() const { return m_findings; }
    // A device answers that is not of the named family (or of none we know).
    bool foundOtherDevice() const;
    // The sentence for a finding that is not a confirmation.
    static QString describe(const Finding &finding);
    // Families whose identify probes are the same cannot be told apart by a device:
    // either of them is confirmed by the other's answer.
    static bool indistinguishable(const RegisterMap &a, const RegisterMap &b);

private:
    void checkNext();
    void onScannerFinished();
    void onCancel() override;

    std::unique_ptr<DeviceScanner> m_scanner;
    QList<Claim> m_claims;
    QList<Finding> m_findings;
    Finding m_current;
};

} // namespace jumo
