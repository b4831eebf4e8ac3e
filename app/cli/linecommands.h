// The jumoctl commands that talk to devices on lines: scan, read, write, dump, monitor,
// backup, diff, restore and report. The lines come from --port, --line (repeatable) or
// a station file; a command of one device opens only that device's line, monitor and
// scan work on several lines at once, each its own Bus. Each command runs on the event
// loop and emits finished() with its exit code.
#pragma once

#include "bus/bus.h"
#include "bus/identitycheck.h"
#include "bus/stationconfig.h"
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
    // SIGINT, SIGTERM, SIGHUP or SIGPIPE: stops what is under way and ends with 130, 143,
    // 129 or 141 and a summary of what was done.
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
        qsizetype line = 0;   // index into m_station.lines
        // monitor: the identity as the bus found it
        bool confirmed = false;    // of its family, at some time of the run
        bool otherFamily = false;  // another family answered at its address
        QString identityProblem;   // why it is not confirmed now, empty when it did not answer
    };

    // One line of the command at work. Declared after the bus, the gate and the scanner
    // that use it are destroyed first.
    struct Line
    {
        QString name;
        std::unique_ptr<Bus> bus;
        std::unique_ptr<IdentityGate> identity;
        std::unique_ptr<DeviceScanner> scanner;
        int found = 0;            // scan
        QString progress;         // scan: "address 5 (5 of 247)"
        qint64 scanStartedMs = 0; // scan: the bus's clock at its start
        bool scanDone = false;
        bool lost = false;        // the line is lost now (it may come back)
    };

    void addLineOptions(CommandParser &parser, bool namesDevices = true);
    // The lines given by --port, --line or --station, into m_station; an exit code when
    // they are missing, conflict or are bad.
    std::optional<int> readStation(const CommandParser &parser);
    std::optional<BusSettings> lineDefaults(const CommandParser &parser);
    // The line of that index, created (not opened) on first use.
    Line &prepareLine(qsizetype index);
    // Opens every prepared line; an exit code when one cannot be opened.
    std::optional<int> openLines(CommandParser &parser);
    Line &lineOf(const Target &target) { return *m_lines.at(size_t(target.line)); }
    Bus &busOf(const Target &target) { return *lineOf(target).bus; }
    // The line of a command of one device.
    Bus &bus() { return busOf(m_targets.first()); }
    IdentityGate &identity() { return *lineOf(m_targets.first()).identity; }
    // A line went away: monitor and scan go on with the others; other commands end.
    void lineLost(qsizetype index, const QString &message);
    QString lineMessage(qsizetype index, const QString &message) const;
    // FAMILY@ADDRESS as a whole, LINE/ before it allowed; anything else (a file name with
    // an '@') is not a device.
    static bool isDeviceName(const QString &text);
    // LINE/FAMILY@ADDRESS, or FAMILY@ADDRESS on a station of one line; needs m_station.
    bool parseDevice(const QString &text, Target &target);
    // As the command line names it: "LINE/FAMILY@ADDRESS" when there are several lines.
    QString targetName(const Target &target) const;
    void scanFinished(qsizetype index);
    // What the scan will do and cost, said before it starts.
    QString scanPlan(const DeviceScanner &scanner, const Bus &bus, int from, int to) const;
    void showScanProgress();
    void clearScanProgress();
    std::optional<int> scan(const QStringList &arguments);
    std::optional<int> read(const QStringList &arguments, bool dump);
    void readOnce(bool dump);
    std::optional<int> write(const QStringList &arguments);
    void startWrites(Target target, bool broadcast, const QList<quint8> &verifyAddresses);
    std::optional<int> monitor(const QStringList &arguments);
    void startMonitor(const QStringList &ids, int interval);
    // One monitor record; without a cycle time when the line is lost.
    void printRecord(const Target &target, const QStringList &entryIds, std::optional<double> cycleMs);
    QStringList monitorEntries(const Target &target) const;
    // Takes the target's identity from its bus's condition; false while its first check
    // runs, and for the cycle it was confirmed in (no record then: nothing is known of it
    // yet).
    bool noteIdentity(Target &target);
    // The devices never confirmed during a monitor, named on stderr; the exit code with
    // them (1, or 4 where another family answered).
    int reportUnconfirmed(int code);
    void checkMonitorDone();
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
    // Why nothing will be written on the target's line (the system configuration,
    // --read-only or the station file), or empty.
    QString readOnlyNote(const CommandParser &parser, const Target &target) const;
    // There is no folder for the audit log (no HOME): says so; the command writes nothing.
    bool auditLogMissing();
    void finish(int code);
    // The output's reader is gone: ends the command as SIGPIPE does (true), before it
    // takes a step that nobody would see.
    bool stopIfOutputClosed();
    QString progressSummary() const;

    const FamilyRegistry &m_registry;
    QTextStream &m_out;
    QTextStream &m_err;
    StationConfig m_station;
    bool m_stationRead = false;
    std::vector<std::unique_ptr<Line>> m_lines;   // by index of m_station.lines; null: not used
    QString m_logFolder;        // of the audit log; empty: there is none
    QString m_logFolderError;   // why there is none
    EventLog *m_audit = nullptr;
    std::unique_ptr<BroadcastGate> m_broadcast;   // declared after the lines: it goes before the bus it uses
    QStringList m_monitorIds;
    QList<Target> m_targets;
    QStringList m_ids;
    QList<QPair<QString, QString>> m_pendingWrites;
    QList<WriteAssignment> m_assignments;
    int m_restored = 0;
    int m_writesAsked = 0;   // restore: writes in all
    int m_writeTicket = -1;
    bool m_failed = false;
    bool m_uncertain = false;   // a write ended unknown or unverified
    bool m_differs = false;     // diff: the device and the file differ
    bool m_json = false;
    bool m_csv = false;
    bool m_monitoring = false;
    int m_progressWidth = 0;   // of the scan's progress line on stderr
    int m_cyclesWanted = 0;
    bool m_finished = false;
    bool m_auditFailed = false;
    QString m_command;
    int m_interruptCode = 0;
    QString m_interruptSummary;
};

} // namespace jumo
