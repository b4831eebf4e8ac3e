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

} // namespace jumo::LineTiming
