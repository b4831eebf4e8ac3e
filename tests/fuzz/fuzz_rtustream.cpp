// Fuzz target: what a serial device server passes on, taken apart by the RTU-over-TCP
// transport's stream framer (RtuStreamFramer). The input is two requests (6 bytes each:
// address, kind, start, count or value) and then events on a clock in milliseconds: 0xFF
// ends the request under way by its timeout, 0xFE lets 100 ms pass, 0xFD switches to the
// other request for what goes out next, any other byte n feeds the next (n % 64) + 1
// bytes as one reading of the socket (1 ms later). A request goes out when the framer
// lets it (holdUntil), and the next one when it ends. Nothing may crash or read out of
// bounds, the bytes kept stay bounded, no request is held longer than a late reply is
// owed, and a reply taken must be, byte for byte, a frame (valid CRC) received since its
// request went out, from its address, with a function and length that fit it.
#include "bus/rtustreamframer.h"
#include "protocol/rtuframe.h"

#include "fuzzrequests.h"

#include <cstdint>

using namespace jumo;
using namespace jumo::fuzz;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 12)
        return 0;
    ModbusRequest requests[2] = {requestOf(data), requestOf(data + 6)};
    requests[0].timeoutMs = requests[1].timeoutMs = 200;
    int next = 0;
    RtuStreamFramer framer;
    qint64 now = 0;
    const ModbusRequest *underWay = nullptr;
    QByteArray sinceSent;
    // Sends the next request if the framer lets it go now.
    const auto trySend = [&] {
        if (underWay)
            return;
        const qint64 until = framer.holdUntil(requests[next], now);
        if (until > now + RtuStreamFramer::lateReplyMs)
            __builtin_trap();   // held longer than any reply is owed
        if (until > now)
            return;
        framer.frame(requests[next], now);
        underWay = &requests[next];
        sinceSent.clear();
    };
    trySend();
    size_t at = 12;
    while (at < size) {
        const uint8_t event = data[at++];
        if (event == 0xFF) {
            if (underWay) {
                const ModbusResult result = framer.timedOut(now);
                if (result.status != ModbusResult::Status::Timeout)
                    __builtin_trap();
                underWay = nullptr;
            }
        } else if (event == 0xFE) {
            now += 100;
        } else if (event == 0xFD) {
            next = 1 - next;
        } else {
            const size_t length = std::min<size_t>(event % 64 + 1, size - at);
            const QByteArrayView chunk(reinterpret_cast<const char *>(data + at), qsizetype(length));
            at += length;
            now += 1;
            sinceSent.append(chunk.data(), chunk.size());
            const std::optional<ModbusResult> result = framer.received(chunk, now);
            if (framer.pendingBytes() > 2 * RtuStreamFramer::keptBytes)
                __builtin_trap();
            if (result) {
                if (!underWay)
                    __builtin_trap();   // a result with nothing asked
                if (result->status == ModbusResult::Status::Ok) {
                    if (underWay->function == ModbusRequest::Function::ReadHolding
                        && result->words.size() != underWay->count)
                        __builtin_trap();
                    if (!sinceSent.contains(RtuFrame::build(underWay->slave, acceptedPdu(*underWay, *result))))
                        __builtin_trap();   // taken from bytes that are not this request's answer
                } else if (result->status != ModbusResult::Status::Exception) {
                    __builtin_trap();   // a frame that does not fit is dropped, never the result
                }
                underWay = nullptr;
            }
        }
        trySend();
    }
    return 0;
}
