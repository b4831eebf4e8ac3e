// One read outside the poll plan: a scan probe, an identity check, or a block a job needs
// now (backup, report). Reads may be repeated after a lost answer; the result, good or
// not, is reported once.
#pragma once

#include "bus/transaction.h"

#include <functional>

namespace jumo {

class ReadTransaction final : public Transaction
{
public:
    using Finished = std::function<void(const ModbusResult &)>;

    ReadTransaction(int ticket, Lane lane, DeviceId device, ModbusRequest request, ProtocolInfo timing, int maxAttempts,
                    Finished finished)
        : Transaction(ticket, lane, device), m_request(std::move(request)), m_timing(std::move(timing)),
          m_maxAttempts(maxAttempts), m_finished(std::move(finished))
    {
    }

    std::optional<ModbusRequest> nextRequest() const override
    {
        return isFinished() ? std::nullopt : std::optional<ModbusRequest>(m_request);
    }
    ProtocolInfo timing() const override { return m_timing; }
    bool isQuickProbe() const override { return m_quick; }
    void setQuickProbe() { m_quick = true; m_maxAttempts = 1; }

    Next onResult(const ModbusResult &result, int) override
    {
        const bool lost = result.deviceSilent();
        if (lost && ++m_attempts < m_maxAttempts)
            return Next::RetryAfterQuiet;
        finish(result);
        return Next::Continue;
    }

    void abort(const QString &reason) override
    {
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = reason;
        finish(result);
    }

    void forgetDevice(DeviceId device) override
    {
        if (device == this->device())
            abort(QStringLiteral("device removed"));
    }

private:
    void finish(const ModbusResult &result)
    {
        if (isFinished())
            return;
        setFinished();
        if (m_finished)
            m_finished(result);
    }

    ModbusRequest m_request;
    ProtocolInfo m_timing;
    int m_maxAttempts;
    int m_attempts = 0;
    bool m_quick = false;
    Finished m_finished;
};

} // namespace jumo
