// Fuzz target: a register map file (JSON) as a user might put one in the map folder.
// Loading must either accept it or refuse it with messages; an accepted map must plan
// its reads within the family's word limit, and decode and format every entry from any
// words (zeros, ones, a NaN, the largest float) in English and German without trouble.
#include "protocol/maploader.h"
#include "protocol/readplanner.h"
#include "protocol/valuecodec.h"
#include "protocol/valueformat.h"

#include <QLocale>

#include <cstdint>

using namespace jumo;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray json(reinterpret_cast<const char *>(data), qsizetype(size));
    const MapLoadResult result = MapLoader::loadData(json, QStringLiteral("fuzz.json"));
    if (!result.map)
        return 0;
    QList<const RegisterEntry *> readable;
    for (const RegisterEntry &e : result.map->entries()) {
        if (e.isReadable() && e.alias.isEmpty())
            readable << &e;
    }
    const ReadPlan plan = ReadPlanner::plan(*result.map, readable);
    for (const ReadBlock &b : plan.blocks) {
        if (b.count == 0 || b.entries.isEmpty() || b.count > 125)
            __builtin_trap();
    }
    static const QLocale english(QLocale::English), german(QLocale::German);
    const QList<quint16> patterns[] = {{0x0000}, {0xFFFF}, {0x0000, 0x7FC0}, {0xFFFF, 0x7F7F}, {0x8000, 0x0001}};
    for (const RegisterEntry *e : std::as_const(readable)) {
        for (const QList<quint16> &pattern : patterns) {
            QList<quint16> words;
            for (int i = 0; i < e->wordCount(); ++i)
                words << pattern.at(i % pattern.size());
            const DecodedValue v = ValueCodec::decode(*e, *result.map, words);
            (void)ValueFormat::withUnit(v, *e, english);
            (void)ValueFormat::withUnit(v, *e, german);
            (void)ValueCodec::exactText(*e, *result.map, words);
        }
    }
    return 0;
}
