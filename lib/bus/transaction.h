// A piece of line work that is not a poll: an operator's write with its reads before and
// after, or a job's read or write. It hands the scheduler one request at a time, decides
// itself which failures may be repeated (reads and values may, actions may not), and
// reports once when it is over.
#pragma once

#include "bus/modbusrequest.h"
#include "protocol/registermap.h"

#include <optional>

namespace jumo {

using DeviceId = int;

class Transaction
{
public:
    // Operator work goes next; job work (scan, backup, restore, report) takes at most
    // every other turn while devices are monitored.
    enum class Lane { Operator, Job };
    // What the scheduler does after a result.
    enum class Next { Continue, RetryAfterQuiet };

    Transaction(int ticket, Lane lane, DeviceId device) : m_ticket(ticket), m_lane(lane), m_device(device) { }
    virtual ~Transaction() = default;
    Transaction(const Transaction &) = delete;
    Transaction &operator=(const Transaction &) = delete;

    int ticket() const { return m_ticket; }
    Lane lane() const { return m_lane; }
    DeviceId device() const { return m_device; }   // -1: none (probe, broadcast)
    bool isFinished() const { return m_finished; }

    // The next request to send (timeout not yet set), or nullopt once finished.
    virtual std::optional<ModbusRequest> nextRequest() const = 0;
    // The family timing of the next request's addressee.
    virtual ProtocolInfo timing() const = 0;
    // The next request must follow the last one at once, with nothing in between
    // (read-modify-write).
    virtual bool holdsLine() const { return false; }
    // A quick scan's probe: a short timeout, one attempt, and no quiet time after a lost
    // answer (nothing goes to its address soon; an answer from it later is heard as a
    // reply that fits no request).
    virtual bool isQuickProbe() const { return false; }
    // The answer to the request last handed out.
    virtual Next onResult(const ModbusResult &result, int maxRetries) = 0;
    // The transaction ends before its next request is sent: the line went down or was
    // closed, or it was cancelled.
    virtual void abort(const QString &reason) = 0;
    // A device is gone from the line: no further request for it.
    virtual void forgetDevice(DeviceId) { }

protected:
    void setFinished() { m_finished = true; }

private:
    int m_ticket;
    Lane m_lane;
    DeviceId m_device;
    bool m_finished = false;
};

} // namespace jumo
