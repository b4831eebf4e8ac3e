// Fuzz target: a register map file (JSON) as a user might put one in the map folder.
// Loading must either accept it or refuse it with messages; an accepted map must plan
// its reads and describe its entries without trouble.
#include "protocol/maploader.h"
#include "protocol/readplanner.h"

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
        if (b.count == 0 || b.entries.isEmpty())
            __builtin_trap();
    }
    return 0;
}
