#include "bus/linetiming.h"

#include <algorithm>
#include <cmath>

namespace jumo::LineTiming {

double transactionMs(const LineFormat &format, int requestBytes, int replyBytes, double deviceMs, double turnaroundMs)
{
    return format.wireTimeMs(requestBytes) + format.frameGapMs() + deviceMs + format.wireTimeMs(replyBytes)
            + std::max(format.frameGapMs(), turnaroundMs);
}

double deviceMs(const ProtocolInfo &protocol, int minimumResponseTimeMs)
{
    return std::max(protocol.processingTimeMaxMs, double(minimumResponseTimeMs));
}

int timeoutMs(const LineFormat &format, int requestBytes, int replyBytes, const ProtocolInfo &protocol,
              int minimumResponseTimeMs)
{
    const double worst = transactionMs(format, requestBytes, replyBytes, deviceMs(protocol, minimumResponseTimeMs));
    return int(std::ceil(worst * 1.25 + 50.0));
}

double interFrameDelayMs(const LineFormat &format)
{
    return std::max(2.0, format.frameGapMs());
}

int bridgeableGapWords(const LineFormat &format, const ProtocolInfo &protocol)
{
    // The manuals give only the worst case (250 ms for a dTRON); weighed by that, every
    // gap would be worth reading. Devices and our peers answer within a few ms.
    constexpr double typicalProcessingMs = 5.0;
    const double device = std::min(protocol.processingTimeMaxMs, typicalProcessingMs);
    const double request = transactionMs(format, readRequestBytes, readReplyBytes(0), device, protocol.turnaroundMs)
            + interFrameDelayMs(format);
    return int(request / format.wireTimeMs(2));
}

ProtocolInfo quickTiming(const ProtocolInfo &protocol)
{
    ProtocolInfo quick = protocol;
    quick.processingTimeMaxMs = std::min(protocol.processingTimeMaxMs, quickAnswerMs);
    return quick;
}

qint64 quietAfterMs(const LineFormat &format, const ModbusRequest &request, const ModbusResult &result,
                    const ProtocolInfo &protocol, int minimumResponseTimeMs, LateAnswer late)
{
    if (request.isBroadcast() && result.status == ModbusResult::Status::Ok) {
        // Qt calls a broadcast done when its bytes reach the driver, not the wire.
        const double wire = format.wireTimeMs(request.requestBytes());
        return qint64(wire + std::max(100.0, protocol.processingTimeMaxMs + minimumResponseTimeMs));
    }
    const bool lost = result.status == ModbusResult::Status::Timeout || result.status == ModbusResult::Status::BadReply;
    if (lost && late == LateAnswer::Guarded)
        return std::max(request.timeoutMs, timeoutMs(format, request.requestBytes(), request.replyBytes(), protocol,
                                                     minimumResponseTimeMs));
    return qint64(std::max(0.0, protocol.turnaroundMs - interFrameDelayMs(format)) + 0.5);
}

} // namespace jumo::LineTiming
