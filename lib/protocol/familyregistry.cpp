#include "protocol/familyregistry.h"

#include "protocol/maploader.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QMap>
#include <QSet>
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
    if (withBuiltins) {
        const QDir builtins(QStringLiteral(":/maps"));
        for (const QString &name : builtins.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
            registry.add(builtins.filePath(name));
    }
    // User files: two of one family leave it open which the user meant, so neither is
    // taken (the built-in family, if any, stays).
    QMap<QString, QList<std::shared_ptr<const RegisterMap>>> userMaps;
    QSet<QString> seen;
    for (const QString &folder : folders) {
        // A folder named twice (JUMO_MAP_PATH=a:a, a/, a link to it) is read once: its
        // files are not two definitions of their families.
        const QFileInfo info(folder);
        const QString canonical = info.canonicalFilePath().isEmpty() ? info.absoluteFilePath() : info.canonicalFilePath();
        if (seen.contains(canonical))
            continue;
        seen.insert(canonical);
        const QDir dir(folder);
        for (const QString &name : dir.entryList({QStringLiteral("*.json")}, QDir::Files | QDir::System, QDir::Name)) {
            MapLoadResult result = MapLoader::loadFile(dir.filePath(name));
            if (result.ok())
                userMaps[result.map->family] << std::make_shared<const RegisterMap>(std::move(*result.map));
            else
                registry.m_errors << result.errors;
        }
    }
    for (auto it = userMaps.cbegin(); it != userMaps.cend(); ++it) {
        if (it->size() == 1) {
            registry.put(it->first());
            continue;
        }
        QStringList files;
        for (const auto &map : *it)
            files << map->sourceFile;
        registry.m_errors << QCoreApplication::translate("jumo::FamilyRegistry",
                                                         "%1: family '%2' is defined by each of these files, so none "
                                                         "of them is used")
                                     .arg(files.join(QStringLiteral(", ")), it.key());
    }
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
    put(std::make_shared<const RegisterMap>(std::move(*result.map)));
}

void FamilyRegistry::put(std::shared_ptr<const RegisterMap> map)
{
    // A user file of a built-in family replaces it.
    auto it = std::find_if(m_families.begin(), m_families.end(),
                           [&](const auto &m) { return m->family == map->family; });
    if (it != m_families.end())
        *it = std::move(map);
    else
        m_families << std::move(map);
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
