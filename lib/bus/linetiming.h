// Time a request takes on an RS-485 line, from the manuals' timing chapters: request and
// reply on the wire, the 3.5-character gaps, the device's processing time or configured
// minimum response time. Used for timeouts and by the bus benchmark.
#pragma once

#include "bus/modbusrequest.h"
#include "protocol/lineformat.h"
#include "protocol/registermap.h"

namespace jumo::LineTiming {

constexpr int readRequestBytes = 8;
constexpr int readReplyBytes(int words) { return 5 + 2 * words; }
constexpr int writeRequestBytes(int words) { return words == 1 ? 8 : 9 + 2 * words; }
constexpr int writeReplyBytes = 8;
// Added to the timeout of a line reached over TCP (a gateway or a device server): the
// network's round trip and the gateway's own queueing, on top of the serial side's timing.
constexpr int networkMarginMs = 250;
constexpr int exceptionReplyBytes = 5;

// The theoretical best: the line is busy for exactly this long per request: request,
// frame gap, the device's time, reply, and the frame gap or the family's turnaround.
double transactionMs(const LineFormat &format, int requestBytes, int replyBytes, double deviceMs,
                     double turnaroundMs = 0);
// What the device needs between request and reply: its processing time, or the
// configured minimum response time when longer.
double deviceMs(const ProtocolInfo &protocol, int minimumResponseTimeMs);
// How long to wait for a reply before calling it lost: the worst case plus a margin
// for USB adapters and the operating system.
int timeoutMs(const LineFormat &format, int requestBytes, int replyBytes, const ProtocolInfo &protocol,
              int minimumResponseTimeMs);

// The wait QModbusRtuSerialClient keeps before each request: 3.5 characters, at least 2 ms.
double interFrameDelayMs(const LineFormat &format);
// The most words a read plan bridges between two wanted entries: reading them costs less
// wire time than one more request (its framing, two frame gaps, the device's typical
// processing time, the client's gap before a request).
int bridgeableGapWords(const LineFormat &format, const ProtocolInfo &protocol);
// What a quick scan allows a device to answer in: real devices and our peers answer within
// a few ms; one slower than this is heard answering later and probed again at the full
// timeout.
constexpr double quickAnswerMs = 20.0;
// The family timing a quick scan probes with: the device's time cut to quickAnswerMs.
ProtocolInfo quickTiming(const ProtocolInfo &protocol);

// Whether a lost answer may still come and be taken for the next request's.
enum class LateAnswer {
    Guarded,    // the next request may go to the same address: wait it out
    Harmless,   // a quick scan's probe: nothing goes to that address soon, and an answer
                // from it later carries its address and is heard as a mismatch
};
// How long nobody may talk after a request ended so: after a lost or garbled reply as
// long again as the timeout, so a late answer cannot be taken for the next request's (Qt
// clears its buffer right before each send); after a reply the family's turnaround; after
// a broadcast the devices' time to carry it out.
qint64 quietAfterMs(const LineFormat &format, const ModbusRequest &request, const ModbusResult &result,
                    const ProtocolInfo &protocol, int minimumResponseTimeMs,
                    LateAnswer late = LateAnswer::Guarded);

} // namespace jumo::LineTiming
