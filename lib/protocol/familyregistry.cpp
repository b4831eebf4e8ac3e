#include "protocol/familyregistry.h"

#include "protocol/maploader.h"

#include <QDir>
#include <QStandardPaths>

#include <algorithm>

namespace jumo {

FamilyRegistry FamilyRegistry::loadDefault()
{
    return load(userFolders(), true);
}

FamilyRegistry FamilyRegistry::load(const QStringList &folders, bool withBuiltins)
{
    FamilyRegistry registry;
    QStringList paths;
    if (withBuiltins) {
        const QDir builtins(QStringLiteral(":/maps"));
        for (const QString &name : builtins.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
            paths << builtins.filePath(name);
    }
    for (const QString &folder : folders) {
        const QDir dir(folder);
        for (const QString &name : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
            paths << dir.filePath(name);
    }
    for (const QString &path : std::as_const(paths))
        registry.add(path);
    std::stable_sort(registry.m_families.begin(), registry.m_families.end(),
                     [](const auto &a, const auto &b) { return a->family < b->family; });
    return registry;
}

QStringList FamilyRegistry::userFolders()
{
    QStringList folders;
    const QString env = qEnvironmentVariable("JUMO_MAP_PATH");
    if (!env.isEmpty())
        folders << env.split(QLatin1Char(':'), Qt::SkipEmptyParts);
    const QString data = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
    if (!data.isEmpty())
        folders << data + QStringLiteral("/jumo/maps");
    return folders;
}

void FamilyRegistry::add(const QString &path)
{
    MapLoadResult result = MapLoader::loadFile(path);
    if (!result.ok()) {
        m_errors << result.errors;
        return;
    }
    auto map = std::make_shared<const RegisterMap>(std::move(*result.map));
    // A later file of the same family (a user folder) replaces the earlier one.
    auto it = std::find_if(m_families.begin(), m_families.end(),
                           [&](const auto &m) { return m->family == map->family; });
    if (it != m_families.end())
        *it = map;
    else
        m_families << map;
}

std::shared_ptr<const RegisterMap> FamilyRegistry::family(const QString &id) const
{
    for (const auto &m : m_families) {
        if (m->family == id)
            return m;
    }
    return nullptr;
}

QStringList FamilyRegistry::familyIds() const
{
    QStringList ids;
    for (const auto &m : m_families)
        ids << m->family;
    return ids;
}

} // namespace jumo
