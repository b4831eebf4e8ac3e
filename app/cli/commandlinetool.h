// The jumoctl command dispatcher: picks the command from the arguments, gives every
// command its own --help, and reports errors on stderr with a non-zero exit code (also
// when its output could not be written).
#pragma once

#include <QObject>
#include <QStringList>
#include <QTextStream>

#include <memory>
#include <optional>

namespace jumo {

class FamilyRegistry;
class FindCommand;
class LineCommands;

class CommandLineTool : public QObject
{
    Q_OBJECT

public:
    CommandLineTool(QTextStream &out, QTextStream &err, QObject *parent = nullptr);
    ~CommandLineTool() override;

    // Runs a command. Returns its exit code, or nullopt when the command works on the
    // event loop and will emit finished() later.
    std::optional<int> run(const QStringList &arguments);
    // A signal while a command runs (SIGINT, SIGTERM, SIGHUP, SIGPIPE): it ends with 128 +
    // the signal's number and a summary.
    void interrupt(int signal);

signals:
    void finished(int exitCode);

private:
    std::optional<int> runCommand(const QStringList &arguments);
    // The exit code, made a failure when the output could not be written (said on stderr).
    int checkOutput(int code);
    QString usage() const;

    QTextStream &m_out;
    QTextStream &m_err;
    std::unique_ptr<FamilyRegistry> m_registry;
    std::unique_ptr<LineCommands> m_lineCommands;
    std::unique_ptr<FindCommand> m_find;
};

} // namespace jumo
