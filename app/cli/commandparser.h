// QCommandLineParser set up the way every jumoctl command uses it: its own --help,
// errors on stderr, and no exit() behind the caller's back.
#pragma once

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

#include <optional>

namespace jumo {

class CommandParser : public QCommandLineParser
{
    Q_DECLARE_TR_FUNCTIONS(jumo::CommandParser)

public:
    CommandParser(const QString &command, const QString &description);

    // Parses "jumoctl COMMAND args...". Returns an exit code when the caller should stop
    // (help shown: 0; bad arguments: 2), nullopt to go on.
    std::optional<int> parseArguments(const QStringList &arguments, QTextStream &out, QTextStream &err,
                                      int minPositional, int maxPositional = -1);

private:
    QString m_command;
};

} // namespace jumo
