// The jumoctl commands that work on the register maps alone, without a serial line:
// families, map, plan and decode.
#pragma once

#include <QCoreApplication>
#include <QStringList>
#include <QTextStream>

namespace jumo {

class FamilyRegistry;
class RegisterMap;

class MapCommands
{
    Q_DECLARE_TR_FUNCTIONS(jumo::MapCommands)

public:
    MapCommands(const FamilyRegistry &registry, QTextStream &out, QTextStream &err);

    int families(const QStringList &arguments);
    int map(const QStringList &arguments);
    int plan(const QStringList &arguments);
    int decode(const QStringList &arguments);

    // The CSV header scripts rely on.
    static QString csvHeader();
    static QStringList csvRows(const RegisterMap &map);

private:
    const RegisterMap *requireFamily(const QString &id);

    const FamilyRegistry &m_registry;
    QTextStream &m_out;
    QTextStream &m_err;
};

} // namespace jumo
