// A transport for unit tests of the bus: requests are answered by simulated devices (or
// by nobody) after the time the line would take, on a manual clock, so minutes of line
// time run in milliseconds. Faults are injected per request. The pty integration tests
// against the simulator and the libmodbus peer remain the proof that the bus works.
#pragma once

#include "bus/clock.h"
#include "bus/linetiming.h"
#include "bus/transport.h"
#include "sim/simulateddevice.h"

#include <QHash>

#include <functional>

namespace jumo::test {

class FakeTransport final : public Transport
{
public:
    struct Sent
    {
        qint64 atMs = 0;
        ModbusRequest request;
    };

    FakeTransport(ManualClock *clock, QHash<quint8, SimulatedDevice *> devices, LineFormat format)
        : m_clock(clock), m_devices(std::move(devices)), m_format(format)
    {
    }

    // Requests for which this returns true get no answer (a lost reply).
    std::function<bool(const ModbusRequest &)> drop;
    // Requests for which this returns true are executed and answered with a reply that
    // does not fit them (another echo): what RtuTransport calls BadReply.
    std::function<bool(const ModbusRequest &)> misfit;
    // Extra time a slave takes before it answers (its processing time beyond the usual
    // few ms). An answer that comes after its request's timeout is a late answer: heard
    // as a mismatch by the request under way when it arrives, or by nobody.
    QHash<quint8, int> answerDelayMs;
    QList<Sent> sent;
    // Late answers that came while a request of the same slave and function was under
    // way: the real client would take them for that request's answer (wrong data).
    int lateAnswersTakenAsOwn = 0;
    // Late answers heard, and those that came while no request was out (lost unheard).
    int lateAnswersHeard = 0;
    int lateAnswersUnheard = 0;

    bool open(QString *) override
    {
        m_open = true;
        return true;
    }

    void close() override
    {
        m_open = false;
        abortPending();
    }

    bool isOpen() const override { return m_open; }
    double interFrameDelayMs() const override { return std::max(2.0, m_format.frameGapMs()); }

    void send(const ModbusRequest &request) override
    {
        sent << Sent{m_clock->nowMs(), request};
        ModbusResult result = answer(request);
        double duration = 0;
        if (request.isBroadcast())
            duration = m_format.wireTimeMs(request.requestBytes());
        else if (result.status == ModbusResult::Status::Timeout)
            duration = request.timeoutMs;
        else
            duration = LineTiming::transactionMs(m_format, request.requestBytes(),
                                                 result.status == ModbusResult::Status::Exception
                                                         ? LineTiming::exceptionReplyBytes
                                                         : request.replyBytes(),
                                                 3.0 + answerDelayMs.value(request.slave));
        if (!request.isBroadcast() && result.status != ModbusResult::Status::Timeout
            && duration > request.timeoutMs) {
            // The answer comes, but after the timeout: whoever is asked then hears it.
            const qint64 arrives = m_clock->nowMs() + qint64(std::ceil(duration));
            m_clock->callAt(arrives, this, [this, request] { lateAnswer(request); });
            result = ModbusResult{};
            duration = request.timeoutMs;
        }
        const quint64 id = ++m_sequence;
        m_pending = id;
        m_pendingRequest = request;
        m_pendingMismatches = 0;
        m_clock->callAt(m_clock->nowMs() + qint64(std::ceil(duration)), this, [this, id, result] {
            if (m_pending != id)
                return;
            m_pending = 0;
            ModbusResult r = result;
            r.mismatches += m_pendingMismatches;
            emit finished(r);
        });
    }

    // The adapter is pulled: what was under way is lost, then the port is gone.
    void pull()
    {
        m_open = false;
        abortPending();
        emit lost(QStringLiteral("the adapter was unplugged"));
    }

    // Requests sent to a slave, optionally only of one function code and start address.
    int count(quint8 slave, int function = -1, int start = -1) const
    {
        int n = 0;
        for (const Sent &s : sent) {
            if (s.request.slave == slave && (function < 0 || int(s.request.function) == function)
                && (start < 0 || s.request.start == start))
                ++n;
        }
        return n;
    }

private:
    void lateAnswer(const ModbusRequest &late)
    {
        if (!m_pending) {
            ++lateAnswersUnheard;
            return;
        }
        if (m_pendingRequest.slave == late.slave && m_pendingRequest.function == late.function)
            ++lateAnswersTakenAsOwn;
        ++lateAnswersHeard;
        ++m_pendingMismatches;
    }

    void abortPending()
    {
        if (!m_pending)
            return;
        m_pending = 0;
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = QStringLiteral("aborted");
        emit finished(result);
    }

    ModbusResult answer(const ModbusRequest &request)
    {
        ModbusResult result;
        if (request.isBroadcast()) {
            for (SimulatedDevice *d : std::as_const(m_devices))
                d->process(request.pdu(), true);
            result.status = ModbusResult::Status::Ok;
            return result;
        }
        SimulatedDevice *device = m_devices.value(request.slave);
        for (SimulatedDevice *d : std::as_const(m_devices)) {
            // IPC 300 and TYA 200 answer address 255 whatever their own.
            if (!device && d->map().protocol.alwaysAnswersAddress == int(request.slave))
                device = d;
        }
        if (!device)
            return result;   // nobody there: a timeout
        const QByteArray reply = device->process(request.pdu(), false);
        if (drop && drop(request))
            return result;   // executed, but the answer is lost on the way back
        if (reply.isEmpty())
            return result;
        if (misfit && misfit(request)) {
            result.status = ModbusResult::Status::BadReply;
            result.errorText = QStringLiteral("write reply names 1 word(s) at 7 where 1 at 111 were written");
            return result;
        }
        if (quint8(reply[0]) & 0x80) {
            result.status = ModbusResult::Status::Exception;
            result.exceptionCode = quint8(reply[1]);
            return result;
        }
        result.status = ModbusResult::Status::Ok;
        if (!request.isWrite()) {
            for (int i = 2; i + 1 < reply.size(); i += 2)
                result.words << quint16(quint8(reply[i]) << 8 | quint8(reply[i + 1]));
        }
        return result;
    }

    ManualClock *m_clock;
    QHash<quint8, SimulatedDevice *> m_devices;
    LineFormat m_format;
    bool m_open = false;
    quint64 m_sequence = 0;
    quint64 m_pending = 0;
    ModbusRequest m_pendingRequest;
    int m_pendingMismatches = 0;
};

} // namespace jumo::test
