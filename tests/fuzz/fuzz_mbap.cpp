// Fuzz target: what a Modbus TCP gateway sends, taken apart by the TCP transport's framer
// (MbapFramer). The input is a request (6 bytes: unit, kind, start, count or value) and
// then events: a byte 0xFF ends the request by its timeout, 0xFE makes the connection
// anew, any other byte n feeds the next (n % 64) + 1 bytes as one reading of the socket.
// A request that ends is followed by the next (a new transaction). Nothing may crash or
// read out of bounds, the framer may hold no more than one incomplete frame, and a reply
// taken as good must be, byte for byte, a frame received since the request went out with
// its transaction id, protocol id 0, its unit, and a function and length that fit it.
#include "bus/mbapframer.h"
#include "protocol/mbapframe.h"

#include "fuzzrequests.h"

#include <cstdint>

using namespace jumo;
using namespace jumo::fuzz;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 6)
        return 0;
    const ModbusRequest request = requestOf(data);
    MbapFramer framer;
    framer.frame(request);
    QByteArray sinceSent;
    size_t at = 6;
    while (at < size) {
        const uint8_t event = data[at++];
        if (event == 0xFF || event == 0xFE) {
            if (event == 0xFF) {
                bool broken = false;
                const ModbusResult result = framer.timedOut(&broken);
                if (result.status != ModbusResult::Status::Timeout || (broken && framer.pendingBytes() != 0))
                    __builtin_trap();
            } else {
                framer.reset();
            }
            framer.frame(request);
            sinceSent.clear();
            continue;
        }
        const size_t length = std::min<size_t>(event % 64 + 1, size - at);
        const QByteArrayView chunk(reinterpret_cast<const char *>(data + at), qsizetype(length));
        at += length;
        sinceSent.append(chunk.data(), chunk.size());
        const quint16 transaction = framer.transaction();
        const MbapFramer::Outcome outcome = framer.received(chunk);
        if (framer.pendingBytes() >= 6 + MbapFrame::maxLength)
            __builtin_trap();   // more than one incomplete frame kept
        if (outcome.broken && framer.pendingBytes() != 0)
            __builtin_trap();
        if (!outcome.result)
            continue;
        const ModbusResult &result = *outcome.result;
        if (result.status == ModbusResult::Status::Ok) {
            if (request.function == ModbusRequest::Function::ReadHolding && result.words.size() != request.count)
                __builtin_trap();
            if (!sinceSent.contains(MbapFrame::build(transaction, request.slave, acceptedPdu(request, result))))
                __builtin_trap();   // taken from a frame that is not this request's answer
        } else if (result.status == ModbusResult::Status::Exception) {
            if (result.exceptionCode < 0 || result.exceptionCode > 255)
                __builtin_trap();
        } else if (result.status != ModbusResult::Status::BadReply || result.errorText.isEmpty()) {
            __builtin_trap();
        }
        framer.frame(request);
        sinceSent.clear();
    }
    return 0;
}
