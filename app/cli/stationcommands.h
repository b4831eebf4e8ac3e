// jumoctl station: checks a station file and shows its lines and devices, as every
// line command would take them, without opening a line.
#pragma once

#include <QCoreApplication>
#include <QStringList>
#include <QTextStream>

namespace jumo {

class FamilyRegistry;

class StationCommands
{
    Q_DECLARE_TR_FUNCTIONS(jumo::StationCommands)

public:
    StationCommands(const FamilyRegistry &registry, QTextStream &out, QTextStream &err);

    // 0 and the lines when the file is good, 2 and every problem when it is not.
    int station(const QStringList &arguments);

private:
    const FamilyRegistry &m_registry;
    QTextStream &m_out;
    QTextStream &m_err;
};

} // namespace jumo
