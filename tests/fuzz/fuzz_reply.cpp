// Fuzz target: a reply frame arriving from the line. The first two bytes choose a family
// and a read block of its full poll plan; the rest is the frame. It is checked as the
// receiver does (expected length, CRC), parsed (exception or byte count and words), and
// its words are stored and decoded into every entry of the block (every type and word
// order the maps use). Nothing may crash, hang or read out of bounds.
#include "bus/valuestore.h"
#include "protocol/familyregistry.h"
#include "protocol/readplanner.h"
#include "protocol/rtuframe.h"
#include "protocol/valuecodec.h"

#include <QCoreApplication>

#include <cstdint>

using namespace jumo;

namespace {

const FamilyRegistry &registry()
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return r;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2)
        return 0;
    const auto families = registry().families();
    const auto map = families.at(data[0] % families.size());
    QList<const RegisterEntry *> readable;
    for (const RegisterEntry &e : map->entries()) {
        if (e.isReadable() && e.alias.isEmpty())
            readable << &e;
    }
    const ReadPlan plan = ReadPlanner::plan(*map, readable);
    if (plan.blocks.isEmpty())
        return 0;
    const ReadBlock &block = plan.blocks.at(data[1] % plan.blocks.size());
    const QByteArray frame(reinterpret_cast<const char *>(data + 2), qsizetype(size - 2));

    const std::optional<int> length = RtuFrame::expectedLength(frame, RtuFrame::Direction::Response);
    if (!length || *length < 0 || frame.size() < *length || !RtuFrame::hasValidCrc(frame.left(*length)))
        return 0;
    const QByteArray pdu = frame.mid(1, *length - 3);
    if (pdu.isEmpty() || (quint8(pdu.at(0)) & 0x80))
        return 0;   // an exception: nothing to decode
    if (pdu.size() < 2)
        return 0;
    const int bytes = quint8(pdu.at(1));
    QList<quint16> words;
    for (int i = 0; i + 1 < bytes && 3 + i < pdu.size(); i += 2)
        words << quint16((quint8(pdu.at(2 + i)) << 8) | quint8(pdu.at(3 + i)));
    if (words.size() != block.count)
        return 0;   // the bus refuses a reply of the wrong length before decoding it
    ValueStore store;
    store.addDevice(1, map);
    store.store(1, block.entries, block.start, words, 1);
    for (const RegisterEntry *e : block.entries) {
        const EntryState *s = store.state(1, e->id);
        const int offset = e->address - block.start;
        const QString exact = ValueCodec::exactText(*e, *map, std::span(words).subspan(offset, e->wordCount()));
        if ((s && s->value.display.size() > 1 << 20) || exact.size() > 1 << 20)
            __builtin_trap();
    }
    return 0;
}
