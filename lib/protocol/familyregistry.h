// All device families known at run time: the built-in maps compiled into the library
// and the files found in the user's map folders, validated as they are loaded.
#pragma once

#include "protocol/registermap.h"

#include <QStringList>

#include <memory>

namespace jumo {

class FamilyRegistry
{
public:
    // Loads the built-in maps, then the user folders ($JUMO_MAP_PATH, the application
    // data folder + "/maps"); a user file replaces a built-in family of the same id, and
    // two user files of one family are both refused.
    static FamilyRegistry loadDefault();
    // Loads only the given folders (and the built-ins when asked): used by tests.
    static FamilyRegistry load(const QStringList &folders, bool withBuiltins);

    static QStringList userFolders();

    QList<std::shared_ptr<const RegisterMap>> families() const { return m_families; }
    std::shared_ptr<const RegisterMap> family(const QString &id) const;
    QStringList familyIds() const;
    // Files that were refused, one message per problem.
    QStringList errors() const { return m_errors; }

private:
    void add(const QString &path);
    void put(std::shared_ptr<const RegisterMap> map);

    QList<std::shared_ptr<const RegisterMap>> m_families;
    QStringList m_errors;
};

} // namespace jumo
