// The jumoctl commands that talk to devices on a serial line: scan, read, write, dump
// and monitor. Each runs on the event loop and emits finished() with its exit code.
#pragma once

#include "bus/bus.h"
#include "commissioning/parameterset.h"
#include "writeassignment.h"

#include <QObject>
#include <QStringList>
#include <QTextStream>

#include <functional>
#include <memory>
#include <optional>

namespace jumo {

class CommandParser;
class DeviceScanner;
class FamilyRegistry;

class LineCommands : public QObject
{
    Q_OBJECT

public:
    LineCommands(const FamilyRegistry &registry, QTextStream &out, QTextStream &err, QObject *parent = nullptr);
    ~LineCommands() override;

    static QStringList commands();
    // Starts a command; an exit code when it ended at once (help, bad arguments).
    std::optional<int> run(const QString &command, const QStringList &arguments);

signals:
    void finished(int exitCode);

private:
    struct Target
    {
        std::shared_ptr<const RegisterMap> map;
        quint8 address = 0;
        DeviceId id = 0;
        int cycles = 0;
    };

    void addLineOptions(CommandParser &parser);
    std::optional<int> openLine(CommandParser &parser);
    bool parseDevice(const QString &text, Target &target);
    std::optional<int> scan(const QStringList &arguments);
    std::optional<int> read(const QStringList &arguments, bool dump);
    std::optional<int> write(const QStringList &arguments);
    std::optional<int> monitor(const QStringList &arguments);
    std::optional<int> report(const QStringList &arguments);
    std::optional<int> parameters(const QString &command, const QStringList &arguments);
    // Reads the parameters and identity of the target once; then calls done.
    void readParameters(const std::function<void(const ParameterSet &, const QStringList &failed)> &done);
    void printDifferences(const QList<ParameterDifference> &differences, const QString &oldName, const QString &newName);
    void restoreNext();
    void printValues(const Target &target, const QStringList &ids);
    void writeNext();
    void reportWrite(const QString &id, const WriteOutcome &outcome);
    // Why nothing will be written (the system configuration or --read-only), or empty.
    QString readOnlyNote(const CommandParser &parser) const;
    void finish(int code);

    const FamilyRegistry &m_registry;
    QTextStream &m_out;
    QTextStream &m_err;
    Bus m_bus;
    std::unique_ptr<DeviceScanner> m_scanner;
    QList<Target> m_targets;
    QStringList m_ids;
    QList<QPair<QString, QString>> m_pendingWrites;
    QList<WriteAssignment> m_assignments;
    int m_restored = 0;
    int m_writeTicket = -1;
    bool m_failed = false;
    bool m_uncertain = false;   // a write ended unknown or unverified
    bool m_json = false;
    bool m_csv = false;
    int m_cyclesWanted = 0;
    bool m_finished = false;
};

} // namespace jumo
