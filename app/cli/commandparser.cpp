#include "commandparser.h"

namespace jumo {

CommandParser::CommandParser(const QString &command, const QString &description) : m_command(command)
{
    setApplicationDescription(description);
    addHelpOption();
    setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
}

std::optional<int> CommandParser::parseArguments(const QStringList &arguments, QTextStream &out, QTextStream &err,
                                                 int minPositional, int maxPositional)
{
    // QCommandLineParser expects the program name first; "jumoctl map" plays that part.
    QStringList args = arguments;
    args.prepend(QStringLiteral("jumoctl ") + m_command);
    if (!parse(args)) {
        err << tr("jumoctl %1: %2").arg(m_command, errorText()) << Qt::endl
            << tr("Try 'jumoctl %1 --help'.").arg(m_command) << Qt::endl;
        return 2;
    }
    // --help-all (Qt's options as well) is --help here: the commands take no Qt options.
    if (isSet(QStringLiteral("help")) || isSet(QStringLiteral("help-all"))) {
        // helpText() names the program only; the command belongs right after it.
        QString help = helpText();
        const qsizetype programStart = help.indexOf(QLatin1Char(' ')) + 1;
        const qsizetype programEnd = help.indexOf(QLatin1Char(' '), programStart);
        if (programStart > 0 && programEnd > programStart)
            help.replace(programStart, programEnd - programStart, QStringLiteral("jumoctl ") + m_command);
        out << help;
        out.flush();
        return 0;
    }
    const qsizetype count = positionalArguments().size();
    if (count < minPositional || (maxPositional >= 0 && count > maxPositional)) {
        err << tr("jumoctl %1: wrong number of arguments").arg(m_command) << Qt::endl
            << tr("Try 'jumoctl %1 --help'.").arg(m_command) << Qt::endl;
        return 2;
    }
    return std::nullopt;
}

} // namespace jumo
