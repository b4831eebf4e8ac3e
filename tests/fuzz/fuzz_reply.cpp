// Fuzz target: a reply frame arriving from the line, for a request the bus sent. The input
// is one byte choosing the family (its ids in order), the request frame (a read, a single
// or a multiple write, as the bus sends them) and then the reply bytes as received. The
// reply goes the way of the product: framed and CRC-checked as the receiver does, turned
// into a data unit by Qt's own client code (QModbusClient::processResponse, as
// QModbusRtuSerialClient does on reception), classified by RtuTransport::resultOf, and the
// words of a read stored and decoded into every entry inside it (every type and word
// order the maps use). Nothing may crash, hang or read out of bounds, and a result the
// bus would decode must fit its request.
#include "bus/rtutransport.h"
#include "bus/valuestore.h"
#include "protocol/familyregistry.h"
#include "protocol/rtuframe.h"
#include "protocol/valuecodec.h"

#include <QModbusRtuSerialClient>

#include <algorithm>
#include <cstdint>

using namespace jumo;

namespace {

// Qt's decoding of a response into a data unit, as the client applies it on reception.
class QtDecoder : public QModbusRtuSerialClient
{
public:
    using QModbusRtuSerialClient::processResponse;
};

const QList<std::shared_ptr<const RegisterMap>> &maps()
{
    static const FamilyRegistry registry = FamilyRegistry::load({}, true);
    static const QList<std::shared_ptr<const RegisterMap>> sorted = [] {
        auto list = registry.families();
        std::sort(list.begin(), list.end(), [](const auto &a, const auto &b) { return a->family < b->family; });
        return list;
    }();
    return sorted;
}

quint16 word(QByteArrayView bytes, int at)
{
    return quint16((quint8(bytes[at]) << 8) | quint8(bytes[at + 1]));
}

// The request the bus would have sent for this frame, or nullopt if it sends no such frame.
std::optional<ModbusRequest> requestOf(QByteArrayView frame)
{
    const quint8 slave = quint8(frame[0]);
    const quint8 function = quint8(frame[1]);
    if (function == 0x03) {
        const quint16 count = word(frame, 4);
        if (slave == 0 || count < 1 || count > 125)
            return std::nullopt;
        return ModbusRequest::read(slave, word(frame, 2), count);
    }
    QList<quint16> words;
    if (function == 0x06) {
        words << word(frame, 4);
    } else if (function == 0x10) {
        const int count = word(frame, 4);
        if (count < 2 || count > 123 || quint8(frame[6]) != 2 * count || frame.size() < 7 + 2 * count + 2)
            return std::nullopt;
        for (int i = 0; i < count; ++i)
            words << word(frame, 7 + 2 * i);
    } else {
        return std::nullopt;
    }
    return ModbusRequest::write(slave, word(frame, 2), words);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static QtDecoder qt;
    if (size < 1 + 8)
        return 0;
    const auto map = maps().at(data[0] % maps().size());
    const QByteArrayView input(reinterpret_cast<const char *>(data + 1), qsizetype(size - 1));
    const std::optional<int> requestLength = RtuFrame::expectedLength(input, RtuFrame::Direction::Request);
    if (!requestLength || *requestLength < 8 || input.size() < *requestLength)
        return 0;
    const std::optional<ModbusRequest> request = requestOf(input.first(*requestLength));
    if (!request)
        return 0;
    const QByteArrayView reply = input.sliced(*requestLength);

    // The receiver: a frame of the length its head announces, with a good CRC, from the
    // slave asked and for the function asked (anything else is discarded and waited past).
    const std::optional<int> length = RtuFrame::expectedLength(reply, RtuFrame::Direction::Response);
    ModbusResult result;
    if (request->isBroadcast()) {
        result = RtuTransport::resultOf(*request, QModbusDevice::NoError, {}, {}, {});
    } else if (!length || *length < 4 || reply.size() < *length || !RtuFrame::hasValidCrc(reply.first(*length))
               || quint8(reply[0]) != request->slave
               || (quint8(reply[1]) & 0x7f) != quint8(request->function)) {
        result = RtuTransport::resultOf(*request, QModbusDevice::TimeoutError, {}, {}, QStringLiteral("timeout"));
    } else {
        const QByteArrayView pdu = reply.sliced(1, *length - 3);
        const QModbusResponse response(QModbusPdu::FunctionCode(quint8(pdu[0])), pdu.sliced(1).toByteArray());
        QModbusDataUnit unit(QModbusDataUnit::HoldingRegisters, request->start,
                             request->isWrite() ? request->words : QList<quint16>(request->count));
        QModbusDevice::Error error = QModbusDevice::NoError;
        if (response.isException())
            error = QModbusDevice::ProtocolError;
        else if (!qt.processResponse(response, &unit))
            error = QModbusDevice::UnknownError;
        result = RtuTransport::resultOf(*request, error, unit, response, QStringLiteral("error"));
        if (!result.replyFrame.isEmpty() && !RtuFrame::hasValidCrc(result.replyFrame))
            __builtin_trap();
    }
    if (result.status == ModbusResult::Status::Exception && (result.exceptionCode < 0 || result.exceptionCode > 255))
        __builtin_trap();
    if (result.status != ModbusResult::Status::Ok || request->isWrite())
        return 0;
    if (result.words.size() != request->count)
        __builtin_trap();   // the bus would decode words that do not fit the request

    // The words of the block are stored and every entry inside it decoded.
    QList<const RegisterEntry *> inside;
    for (const RegisterEntry &e : map->entries()) {
        if (e.isReadable() && e.address >= request->start && e.address + e.wordCount() <= request->start + request->count)
            inside << &e;
    }
    ValueStore store;
    store.addDevice(1, map);
    store.store(1, inside, request->start, result.words, 1);
    for (const RegisterEntry *e : std::as_const(inside)) {
        const EntryState *s = store.state(1, e->id);
        const QString exact = ValueCodec::exactText(
                *e, *map, std::span(result.words).subspan(e->address - request->start, e->wordCount()));
        if (!s || s->value.display.size() > 1 << 20 || exact.size() > 1 << 20)
            __builtin_trap();
    }
    return 0;
}
