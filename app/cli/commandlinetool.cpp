#include "commandlinetool.h"

#include "familyregistry.h"
#include "mapcommands.h"

namespace jumo {

CommandLineTool::CommandLineTool(QTextStream &out, QTextStream &err, QObject *parent)
    : QObject(parent), m_out(out), m_err(err)
{
}

CommandLineTool::~CommandLineTool() = default;

QString CommandLineTool::usage() const
{
    return tr("Usage: jumoctl COMMAND [options] [arguments]\n"
              "\n"
              "Commissioning and monitoring of JUMO power and process controllers over Modbus RTU.\n"
              "\n"
              "Commands on the register maps:\n"
              "  families                 list the device families and their map files\n"
              "  map FAMILY --csv|--json  print a family's register map\n"
              "  plan FAMILY [ID...]      show the read requests for entries of a family\n"
              "  decode FAMILY ID WORD... decode raw register words as an entry\n"
              "\n"
              "'jumoctl COMMAND --help' describes a command.\n");
}

std::optional<int> CommandLineTool::run(const QStringList &arguments)
{
    if (arguments.isEmpty() || arguments.constFirst() == QLatin1String("--help")
        || arguments.constFirst() == QLatin1String("-h") || arguments.constFirst() == QLatin1String("help")) {
        (arguments.isEmpty() ? m_err : m_out) << usage();
        m_out.flush();
        m_err.flush();
        return arguments.isEmpty() ? 2 : 0;
    }
    if (arguments.constFirst() == QLatin1String("--version")) {
        m_out << QCoreApplication::applicationName() << ' ' << QCoreApplication::applicationVersion() << Qt::endl;
        return 0;
    }

    const QString command = arguments.constFirst();
    const QStringList rest = arguments.mid(1);
    const FamilyRegistry registry = FamilyRegistry::loadDefault();
    MapCommands maps(registry, m_out, m_err);
    if (command == QLatin1String("families"))
        return maps.families(rest);
    // A refused user map file must not go unnoticed, whatever the command.
    for (const QString &error : registry.errors())
        m_err << tr("warning: refused map file: %1").arg(error) << Qt::endl;
    if (command == QLatin1String("map"))
        return maps.map(rest);
    if (command == QLatin1String("plan"))
        return maps.plan(rest);
    if (command == QLatin1String("decode"))
        return maps.decode(rest);

    m_err << tr("jumoctl: unknown command '%1'").arg(command) << Qt::endl << tr("Try 'jumoctl --help'.") << Qt::endl;
    return 2;
}

} // namespace jumo
