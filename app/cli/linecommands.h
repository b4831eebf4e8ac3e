// The jumoctl commands that talk to devices on a serial line: scan, read, write, dump
// and monitor. Each runs on the event loop and emits finished() with its exit code.
#pragma once

#include "bus/bus.h"
#include "bus/identitycheck.h"
#include "commissioning/commissioningreport.h"
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
class BroadcastGate;
class DeviceScanner;
class EventLog;
class FamilyRegistry;
class IdentityGate;

class LineCommands : public QObject
{
    Q_OBJECT

public:
    LineCommands(const FamilyRegistry &registry, QTextStream &out, QTextStream &err, QObject *parent = nullptr);
    ~LineCommands() override;

    static QStringList commands();
    // Starts a command; an exit code when it ended at once (help, bad arguments).
    std::optional<int> run(const QString &command, const QStringList &arguments);
    // SIGINT or SIGTERM: stops what is under way and ends with 130 or 143 and a summary
    // of what was done.
    void interrupt(int signal);

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

    void addLineOptions(CommandParser &parser, bool namesDevices = true);
    std::optional<int> openLine(CommandParser &parser);
    // FAMILY@ADDRESS as a whole; anything else (a file name with an '@') is not a device.
    static bool isDeviceName(const QString &text);
    bool parseDevice(const QString &text, Target &target);
    std::optional<int> scan(const QStringList &arguments);
    std::optional<int> read(const QStringList &arguments, bool dump);
    void readOnce(bool dump);
    std::optional<int> write(const QStringList &arguments);
    void startWrites(Target target, bool broadcast, const QList<quint8> &verifyAddresses);
    std::optional<int> monitor(const QStringList &arguments);
    void startMonitor(const QStringList &ids, int interval);
    std::optional<int> report(const QStringList &arguments);
    void startReport(const QString &path, const ReportTitle &title);
    // The targets as claims for the identity check.
    QList<IdentityCheck::Claim> claims() const;
    std::optional<int> parameters(const QString &command, const QStringList &arguments);
    // Reads the parameters and identity of the target once; then calls done.
    void readParameters(const std::function<void(const ParameterSet &, const QStringList &failed)> &done);
    void readParametersNow(const std::function<void(const ParameterSet &, const QStringList &failed)> &done);
    void printDifferences(const QList<ParameterDifference> &differences, const QString &oldName, const QString &newName);
    void startRestore(const QList<ParameterDifference> &differences);
    void restoreNext();
    void printValues(const Target &target, const QStringList &ids);
    void writeNext();
    void reportWrite(const QString &id, const WriteOutcome &outcome);
    // Why nothing will be written (the system configuration or --read-only), or empty.
    QString readOnlyNote(const CommandParser &parser) const;
    void finish(int code);
    QString progressSummary() const;

    const FamilyRegistry &m_registry;
    QTextStream &m_out;
    QTextStream &m_err;
    Bus m_bus;
    std::unique_ptr<DeviceScanner> m_scanner;
    EventLog *m_audit = nullptr;
    IdentityGate *m_identity = nullptr;
    BroadcastGate *m_broadcast = nullptr;
    QList<Target> m_targets;
    QStringList m_ids;
    QList<QPair<QString, QString>> m_pendingWrites;
    QList<WriteAssignment> m_assignments;
    int m_restored = 0;
    int m_writesAsked = 0;   // restore: writes in all
    int m_writeTicket = -1;
    bool m_failed = false;
    bool m_uncertain = false;   // a write ended unknown or unverified
    bool m_json = false;
    bool m_csv = false;
    int m_cyclesWanted = 0;
    bool m_finished = false;
    bool m_auditFailed = false;
    QString m_command;
    int m_interruptCode = 0;
    QString m_interruptSummary;
};

} // namespace jumo
