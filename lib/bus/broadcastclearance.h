// Clears a broadcast of one family for a line: address 0 reaches every device, and the
// same register means something else to another family, so a broadcast may go out only
// on a line known to carry no other device. This job knows it the one way a line can
// tell: a scan of the whole address range, which stops at the first other device.
#pragma once

#include "bus/job.h"
#include "protocol/registermap.h"

#include <memory>

namespace jumo {

class Bus;
class DeviceScanner;

class BroadcastClearance : public Job
{
    Q_OBJECT

public:
    static constexpr int firstAddress = 1;
    static constexpr int lastAddress = 255;

    BroadcastClearance(Bus &bus, QList<std::shared_ptr<const RegisterMap>> families, QObject *parent = nullptr);
    ~BroadcastClearance() override;

    // Scans firstAddress..lastAddress. Ends Succeeded when every device that answers is of
    // the family, else Failed naming the first other device.
    void start(std::shared_ptr<const RegisterMap> family);
    // The devices of the family the scan found: where a broadcast can be read back.
    QList<quint8> familyAddresses() const { return m_found; }

signals:
    void progress(int address);

private:
    void refuse(const QString &reason);
    void onCancel() override;

    std::unique_ptr<DeviceScanner> m_scanner;
    std::shared_ptr<const RegisterMap> m_family;
    QList<quint8> m_found;
    QString m_refusal;
};

} // namespace jumo
