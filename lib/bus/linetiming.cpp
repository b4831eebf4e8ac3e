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

qint64 quietAfterMs(const LineFormat &format, const ModbusRequest &request, const ModbusResult &result,
                    const ProtocolInfo &protocol, int minimumResponseTimeMs)
{
    if (request.isBroadcast() && result.status == ModbusResult::Status::Ok) {
        // Qt calls a broadcast done when its bytes reach the driver, not the wire.
        const double wire = format.wireTimeMs(request.requestBytes());
        return qint64(wire + std::max(100.0, protocol.processingTimeMaxMs + minimumResponseTimeMs));
    }
    if (result.status == ModbusResult::Status::Timeout || result.status == ModbusResult::Status::BadReply)
        return std::max(request.timeoutMs, timeoutMs(format, request.requestBytes(), request.replyBytes(), protocol,
                                                     minimumResponseTimeMs));
    return qint64(std::max(0.0, protocol.turnaroundMs - interFrameDelayMs(format)) + 0.5);
}

} // namespace jumo::LineTiming
