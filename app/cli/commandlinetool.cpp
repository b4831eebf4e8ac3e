#include "commandlinetool.h"

#include "exitcodes.h"
#include "findcommand.h"
#include "historycommands.h"
#include "protocol/familyregistry.h"
#include "linecommands.h"
#include "mapcommands.h"
#include "modbuslogging.h"
#include "outputcheck.h"
#include "portcommands.h"
#include "stationcommands.h"

#include <QFileDevice>

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
              "The serial ports of this machine:\n"
              "  ports [--json]           list them: stable by-id names, adapters, access\n"
              "  find --port PATH [--from A --to B] [--baud LIST] [--format LIST]\n"
              "                           find devices whose baud rate, format and address\n"
              "                           nobody knows: every setting the families support\n"
              "\n"
              "Stations of several lines:\n"
              "  station FILE [--check|--json]\n"
              "                           check a station file, list its lines and devices\n"
              "\n"
              "Recorded values (no line is opened):\n"
              "  history --station FILE|--db URL DEVICE ENTRY... [--from T --to T] [--csv|--json]\n"
              "                           print what was recorded, with its validity\n"
              "\n"
              "Commands on lines (all take --port PATH --baud N --format 8N1|8E1|8O1|8N2\n"
              "--timeout MS --read-only --verbose for one line, or --line SPEC once per\n"
              "line, or --station FILE); DEVICE is FAMILY@ADDRESS, e.g. ipc300@1, or\n"
              "LINE/FAMILY@ADDRESS where there are several lines; its identity registers must\n"
              "confirm FAMILY (exit code 4 if not; --no-identify skips it). A command of one\n"
              "device opens only its line:\n"
              "  scan [--from A --to B]   find devices and name their family, on every line\n"
              "  read DEVICE ID...        read entries once\n"
              "  write DEVICE ID=VALUE... write entries, verified by reading them back; a bit field's\n"
              "                           ID=VALUE replaces every bit, ID.BIT=0|1 changes one bit only\n"
              "  dump DEVICE [--json]     read every readable entry once\n"
              "  monitor DEVICE... --jsonl|--csv [--interval MS] [--cycles N]\n"
              "                           poll continuously, one record per poll cycle; the\n"
              "                           devices of several lines at once\n"
              "  backup DEVICE FILE       save every parameter of a device to a file\n"
              "  diff DEVICE FILE         compare a device with a file (or FILE FILE)\n"
              "  restore DEVICE FILE [--yes]\n"
              "                           write what differs, each verified by read-back\n"
              "  report DEVICE FILE       commissioning report as PDF (.pdf) or HTML\n"
              "\n"
              "Exit codes: 0 done, 1 failed, 2 wrong arguments or files, 3 a write's outcome is\n"
              "unknown, 4 another family at the address; 129, 130, 141 and 143 after SIGHUP,\n"
              "SIGINT, a closed output (SIGPIPE) and SIGTERM, a command on lines then saying\n"
              "on stderr what it got done.\n"
              "\n"
              "'jumoctl COMMAND --help' describes a command.\n");
}

void CommandLineTool::interrupt(int signal)
{
    if (m_lineCommands)
        m_lineCommands->interrupt(signal);
    else if (m_find)
        m_find->interrupt(signal);
    else
        emit finished(128 + signal);
}

std::optional<int> CommandLineTool::run(const QStringList &arguments)
{
    const std::optional<int> code = runCommand(arguments);
    return code ? std::optional<int>(checkOutput(*code)) : std::nullopt;
}

int CommandLineTool::checkOutput(int code)
{
    // Output that went nowhere (stdout on a full disk) is no success: a script reading
    // the file would take a part for the whole.
    if (!OutputCheck::failed(m_out))
        return code;
    const auto *file = qobject_cast<const QFileDevice *>(m_out.device());
    m_err << tr("jumoctl: the output could not be written: %1")
                     .arg(file && file->error() != QFileDevice::NoError ? file->errorString() : tr("write failed"))
          << Qt::endl;
    // A reader that went away (| head) ends every command alike, as SIGPIPE would.
    if (OutputCheck::closed(m_out) && code < exitcode::HungUp)
        return exitcode::OutputClosed;
    return code == exitcode::Ok ? exitcode::Failed : code;
}

std::optional<int> CommandLineTool::runCommand(const QStringList &arguments)
{
    showModbusLogging(false);   // a line command's --verbose turns it on
    static const QStringList helpWords{QStringLiteral("--help"), QStringLiteral("--help-all"), QStringLiteral("-h"),
                                       QStringLiteral("help")};
    if (arguments.isEmpty() || helpWords.contains(arguments.constFirst())) {
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
    if (command == QLatin1String("ports"))
        return PortCommands(m_out, m_err).ports(rest);
    m_registry = std::make_unique<FamilyRegistry>(FamilyRegistry::loadDefault());
    const FamilyRegistry &registry = *m_registry;
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
    if (command == QLatin1String("station"))
        return StationCommands(registry, m_out, m_err).station(rest);
    if (command == QLatin1String("history"))
        return HistoryCommands(registry, m_out, m_err).history(rest);
    if (command == QLatin1String("find")) {
        m_find = std::make_unique<FindCommand>(registry, m_out, m_err);
        connect(m_find.get(), &FindCommand::finished, this, [this](int code) { emit finished(checkOutput(code)); });
        return m_find->run(rest);
    }
    if (LineCommands::commands().contains(command)) {
        m_lineCommands = std::make_unique<LineCommands>(registry, m_out, m_err);
        connect(m_lineCommands.get(), &LineCommands::finished, this, [this](int code) { emit finished(checkOutput(code)); });
        return m_lineCommands->run(command, rest);
    }

    m_err << tr("jumoctl: unknown command '%1'").arg(command) << Qt::endl << tr("Try 'jumoctl --help'.") << Qt::endl;
    return 2;
}

} // namespace jumo
