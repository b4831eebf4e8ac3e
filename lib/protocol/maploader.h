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
    // The built-in maps are below 100 kB; a file many times that size is no map.
    static constexpr qint64 maxFileBytes = 4 * 1024 * 1024;

    static MapLoadResult loadFile(const QString &path);
    static MapLoadResult loadData(const QByteArray &json, const QString &sourceName);
};

} // namespace jumo
