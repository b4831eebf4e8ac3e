// Reads a register map file (docs/map-format.md) and validates it completely, so that
// a broken file is refused as a whole with messages naming file, entry and problem.
#pragma once

#include "protocol/registermap.h"

#include <QByteArray>
#include <QStringList>

#include <optional>

namespace jumo {

struct MapLoadResult
{
    std::optional<RegisterMap> map;
    QStringList errors;   // each "file: entry 'id' (0xADDR): problem"

    bool ok() const { return map.has_value(); }
};

class MapLoader
{
public:
    static MapLoadResult loadFile(const QString &path);
    static MapLoadResult loadData(const QByteArray &json, const QString &sourceName);
};

} // namespace jumo
