#include "protocol/csv.h"
#include "linecommands.h"

#include "bus/lineaddress.h"

#include "commissioning/parametertransfer.h"

#include "broadcastgate.h"
#include "commandparser.h"
#include "prompt.h"
#include "quitonsignal.h"
#include "exitcodes.h"
#include "identitygate.h"
#include "commissioning/commissioningreport.h"
#include "bus/devicescanner.h"
#include "logs/eventlog.h"
#include "logs/eventlogreader.h"
#include "protocol/familyregistry.h"
#include "protocol/filesaver.h"
#include "protocol/printable.h"
#include "protocol/regularfile.h"
#include "reportwriter.h"
#include "jumoversion.h"
#include "logs/writeaudit.h"
#include "modbuslogging.h"
#include "outputcheck.h"
#include "systemsettings.h"

#include <QDateTime>
#include <QDir>
#include <QFileDevice>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSettings>

#include <csignal>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace jumo {

namespace {

QString joinedAddresses(const QList<int> &addresses)
{
    QStringList parts;
    for (int a : addresses)
        parts << QString::number(a);
    return parts.join(QStringLiteral(", "));
}

QJsonValue jsonValue(const EntryState &state)
{
    if (!state.isCurrent() || !state.value.isOk())
        return QJsonValue();
    return QJsonValue::fromVariant(state.value.value);
}

QString deviceName(const RegisterMap &map, quint8 address)
{
    return QStringLiteral("%1@%2").arg(map.family).arg(address);
}

// A command reports only values read now: anything not current is a failure.
bool isFailure(const EntryState *state)
{
    return !state || !state->isCurrent();
}

// The status read and dump report, in the words README lists for them: a device that
// stopped answering during the read (offline after two lost blocks) timed out.
QString readStatus(const EntryState *state)
{
    if (!state || (state->validity == Validity::Unknown && state->error == ReadError::DeviceOffline))
        return QStringLiteral("timeout");
    return state->statusName();
}

// The words of the monitor's JSON contract (and of the MQTT topics).
QString conditionName(DeviceCondition::State state)
{
    switch (state) {
    case DeviceCondition::State::Online:
        return QStringLiteral("online");
    case DeviceCondition::State::Offline:
        return QStringLiteral("offline");
    case DeviceCondition::State::LineLost:
        return QStringLiteral("line_lost");
    case DeviceCondition::State::Disconnected:
        return QStringLiteral("disconnected");
    case DeviceCondition::State::Identifying:
        return QStringLiteral("identifying");
    case DeviceCondition::State::WrongDevice:
        return QStringLiteral("wrong_device");
    }
    return QStringLiteral("disconnected");
}

} // namespace

LineCommands::LineCommands(const FamilyRegistry &registry, QTextStream &out, QTextStream &err, QObject *parent)
    : QObject(parent), m_registry(registry), m_out(out), m_err(err)
{
    // Writes from the command line are audited like the HMI's, in the same log. Without
    // a folder for it, nothing is written (auditLogMissing()).
    m_logFolder = EventLog::defaultFolder(&m_logFolderError);
    m_audit = new EventLog(m_logFolder + QStringLiteral("/write-audit.jsonl"), this);
    // Rotated as the HMI rotates it: the same settings.
    m_audit->setRotation(EventLog::Rotation::fromSettings(QSettings(QStringLiteral("jumo"), QStringLiteral("jumo-hmi"))));
    connect(m_audit, &EventLog::writeFailed, this, [this](const QString &message) {
        m_err << tr("the audit log did not take a record: %1").arg(message) << Qt::endl;
        m_auditFailed = true;
    });
}

LineCommands::~LineCommands() = default;

QStringList LineCommands::commands()
{
    return {QStringLiteral("scan"),   QStringLiteral("read"), QStringLiteral("write"),  QStringLiteral("dump"),
            QStringLiteral("monitor"), QStringLiteral("backup"), QStringLiteral("diff"), QStringLiteral("restore"),
            QStringLiteral("report")};
}

std::optional<int> LineCommands::run(const QString &command, const QStringList &arguments)
{
    m_command = command;
    if (command == QLatin1String("scan"))
        return scan(arguments);
    if (command == QLatin1String("read"))
        return read(arguments, false);
    if (command == QLatin1String("dump"))
        return read(arguments, true);
    if (command == QLatin1String("write"))
        return write(arguments);
    if (command == QLatin1String("monitor"))
        return monitor(arguments);
    if (command == QLatin1String("report"))
        return report(arguments);
    return parameters(command, arguments);
}

void LineCommands::addLineOptions(CommandParser &parser, bool namesDevices)
{
    if (namesDevices)
        IdentityGate::addOption(parser);
    parser.addOption({QStringLiteral("port"),
                      tr("The one line: a serial port (its /dev/serial/by-id name, which 'jumoctl ports' lists, or "
                         "/dev/ttyUSB0, say), tcp://HOST[:PORT] for a Modbus TCP gateway (port 502 by default; the "
                         "device address is the unit id) or rtu+tcp://HOST:PORT for raw RTU through a serial device "
                         "server."),
                      tr("address")});
    parser.addOption({QStringLiteral("line"),
                      tr("A line, given once per line: its ADDRESS, then as needed ,name=NAME ,baud=N "
                         ",format=8N1 ,timeout=MS ,min-response=MS ,retries=N ,read-only, e.g. "
                         "/dev/ttyUSB0,name=a,baud=19200. Unnamed lines are line1, line2, ... The options below are "
                         "the defaults of every --line."),
                      tr("spec")});
    parser.addOption({QStringLiteral("station"),
                      tr("Station file (JSON) with the lines, their settings and devices."), tr("file")});
    parser.addOption({QStringLiteral("baud"),
                      tr("Baud rate: 4800, 9600, 19200 or 38400 (default 9600); behind a gateway, its serial side's "
                         "(it sets the timing)."),
                      tr("rate"),
                      QStringLiteral("9600")});
    parser.addOption({QStringLiteral("format"), tr("Data format: 8N1, 8E1, 8O1 or 8N2 (default 8N1)."), tr("format"),
                      QStringLiteral("8N1")});
    parser.addOption({QStringLiteral("timeout"),
                      tr("Reply timeout in ms (default: derived from the baud rate and the device family)."), tr("ms")});
    parser.addOption({QStringLiteral("min-response"),
                      tr("Minimum response time configured in the devices, in ms (default 0)."), tr("ms"),
                      QStringLiteral("0")});
    parser.addOption({QStringLiteral("retries"), tr("Retries after a lost reply (default 2)."), tr("n"),
                      QStringLiteral("2")});
    parser.addOption({QStringLiteral("read-only"),
                      tr("Never write to any line (control-room mode; the system configuration can set it for "
                         "everyone, a station file for one line).")});
    parser.addOption({QStringLiteral("verbose"),
                      tr("Show Qt's Modbus messages (CRC errors, timeouts, frames) on stderr.")});
}

std::optional<BusSettings> LineCommands::lineDefaults(const CommandParser &parser)
{
    BusSettings settings;
    bool ok = false;
    const int baud = parser.value(QStringLiteral("baud")).toInt(&ok);
    const std::optional<LineFormat> format = LineFormat::parse(ok ? baud : 0, parser.value(QStringLiteral("format")));
    if (!format) {
        m_err << tr("unsupported baud rate or data format: %1 %2")
                         .arg(parser.value(QStringLiteral("baud")), parser.value(QStringLiteral("format")))
              << Qt::endl;
        return std::nullopt;
    }
    settings.format = *format;
    if (parser.isSet(QStringLiteral("timeout"))) {
        settings.timeoutMs = parser.value(QStringLiteral("timeout")).toInt(&ok);
        if (!ok || settings.timeoutMs < 10 || settings.timeoutMs > 60000) {
            m_err << tr("--timeout must be 10..60000 ms") << Qt::endl;
            return std::nullopt;
        }
    }
    settings.minimumResponseTimeMs = parser.value(QStringLiteral("min-response")).toInt(&ok);
    if (!ok || settings.minimumResponseTimeMs < 0 || settings.minimumResponseTimeMs > 500) {
        m_err << tr("--min-response must be 0..500 ms") << Qt::endl;
        return std::nullopt;
    }
    settings.retries = parser.value(QStringLiteral("retries")).toInt(&ok);
    if (!ok || settings.retries < 0 || settings.retries > 10) {
        m_err << tr("--retries must be 0..10") << Qt::endl;
        return std::nullopt;
    }
    return settings;
}

std::optional<int> LineCommands::readStation(const CommandParser &parser)
{
    if (m_stationRead)
        return std::nullopt;
    const bool port = parser.isSet(QStringLiteral("port"));
    const QStringList specs = parser.values(QStringLiteral("line"));
    const bool stationFile = parser.isSet(QStringLiteral("station"));
    if (int(port) + int(!specs.isEmpty()) + int(stationFile) > 1) {
        m_err << tr("give the lines one way: --port, --line or --station") << Qt::endl;
        return exitcode::Usage;
    }
    QString error;
    if (stationFile) {
        for (const QString &option : {QStringLiteral("baud"), QStringLiteral("format"), QStringLiteral("timeout"),
                                      QStringLiteral("min-response"), QStringLiteral("retries")}) {
            if (parser.isSet(option)) {
                m_err << tr("--%1 does not go with --station: the station file sets each line's own").arg(option)
                      << Qt::endl;
                return exitcode::Usage;
            }
        }
        const QString path = parser.value(QStringLiteral("station"));
        std::optional<StationConfig> station = StationConfig::load(path, m_registry, &error);
        if (!station) {
            m_err << error << Qt::endl;
            return exitcode::Usage;
        }
        if (station->lines.isEmpty()) {
            m_err << tr("%1: the station has no lines").arg(path) << Qt::endl;
            return exitcode::Usage;
        }
        // A relative path in the file is meant from where the file is.
        for (LineConfig &line : station->lines)
            line.settings.portName = LineAddress::absolutePort(line.settings.portName, QFileInfo(path).absolutePath());
        m_station = std::move(*station);
    } else {
        const std::optional<BusSettings> defaults = lineDefaults(parser);
        if (!defaults)
            return exitcode::Usage;
        QList<LineConfig> lines;
        if (port) {
            LineConfig line;
            line.settings = *defaults;
            line.settings.portName = LineAddress::absolutePort(parser.value(QStringLiteral("port")), QDir::currentPath());
            lines << line;
        }
        for (const QString &spec : specs) {
            std::optional<LineConfig> line = StationConfig::parseLineSpec(spec, *defaults, &error);
            if (!line) {
                m_err << error << Qt::endl;
                return exitcode::Usage;
            }
            line->settings.portName = LineAddress::absolutePort(line->settings.portName, QDir::currentPath());
            lines << *line;
        }
        if (lines.isEmpty() || lines.constFirst().settings.portName.isEmpty()) {
            m_err << tr("give the line: --port PATH, --line SPEC (once per line) or --station FILE") << Qt::endl;
            return exitcode::Usage;
        }
        std::optional<StationConfig> station = StationConfig::fromLines(lines, &error);
        if (!station) {
            m_err << error << Qt::endl;
            return exitcode::Usage;
        }
        for (LineConfig &line : station->lines)
            line.settings.portName = LineAddress::absolutePort(line.settings.portName, QDir::currentPath());
        m_station = std::move(*station);
    }
    // As in the HMI: the system configuration can make every tool read-only; --read-only
    // makes every line of this command read-only, a station file one line.
    for (const QString &warning : SystemSettings::warnings())
        m_err << tr("warning: %1").arg(warning) << Qt::endl;
    const bool readOnly = parser.isSet(QStringLiteral("read-only")) || SystemSettings::readOnly();
    for (LineConfig &line : m_station.lines)
        line.settings.readOnly = line.settings.readOnly || readOnly;
    m_lines.resize(size_t(m_station.lines.size()));
    m_stationRead = true;
    return std::nullopt;
}

LineCommands::Line &LineCommands::prepareLine(qsizetype index)
{
    std::unique_ptr<Line> &line = m_lines.at(size_t(index));
    if (!line) {
        line = std::make_unique<Line>();
        line->name = m_station.lines.at(index).name;
        line->bus = std::make_unique<Bus>();
        line->bus->setSettings(m_station.lines.at(index).settings);
        // Writes from the command line are audited like the HMI's, in the same log.
        new WriteAudit(line->bus.get(), m_audit, line->bus.get());
        line->identity = std::make_unique<IdentityGate>(*line->bus, m_registry, m_err);
    }
    return *line;
}

std::optional<int> LineCommands::openLines(CommandParser &parser)
{
    showModbusLogging(parser.isSet(QStringLiteral("verbose")));
    for (size_t i = 0; i < m_lines.size(); ++i) {
        Line *line = m_lines[i].get();
        if (!line)
            continue;
        line->identity->configure(parser);
        if (!line->bus->open()) {
            m_err << lineMessage(qsizetype(i), line->bus->lastError()) << Qt::endl;
            return exitcode::Failed;
        }
        connect(line->bus.get(), &Bus::lineError, this,
                [this, i](const QString &message) { lineLost(qsizetype(i), message); });
        connect(line->bus.get(), &Bus::stateChanged, this, [line](LineState state) {
            if (state == LineState::Connected)
                line->lost = false;
        });
    }
    return std::nullopt;
}

QString LineCommands::lineMessage(qsizetype index, const QString &message) const
{
    if (m_station.lines.size() < 2)
        return message;
    return tr("line %1: %2").arg(m_station.lines.at(index).name, message);
}

void LineCommands::lineLost(qsizetype index, const QString &message)
{
    m_err << lineMessage(index, message) << Qt::endl;
    m_failed = true;
    Line &line = *m_lines.at(size_t(index));
    line.lost = true;
    const bool othersAlive = std::any_of(m_lines.cbegin(), m_lines.cend(),
                                         [](const std::unique_ptr<Line> &l) { return l && !l->lost; });
    if (m_monitoring) {
        // Its devices say so at once (unknown, line_lost); the bus tries to reopen it.
        for (const Target &t : std::as_const(m_targets)) {
            if (t.line == index)
                printRecord(t, monitorEntries(t), std::nullopt);
        }
        if (othersAlive) {
            checkMonitorDone();
            return;
        }
    } else if (line.scanner && othersAlive) {
        line.scanner->cancel();
        return;
    }
    // A write under way when the line went ends as unknown from the event loop, after
    // this: its outcome is said and audited first, and it outweighs the loss.
    QMetaObject::invokeMethod(
            this, [this] { finish(m_uncertain ? exitcode::Uncertain : exitcode::Failed); }, Qt::QueuedConnection);
}

bool LineCommands::isDeviceName(const QString &text)
{
    static const QRegularExpression pattern(
            QRegularExpression::anchoredPattern(QStringLiteral("([A-Za-z0-9_.-]{1,32}/)?[a-z][a-z0-9_]*@[0-9]{1,3}")));
    return pattern.match(text).hasMatch();
}

QString LineCommands::targetName(const Target &target) const
{
    const QString device = deviceName(*target.map, target.address);
    return m_station.lines.size() > 1 ? QStringLiteral("%1/%2").arg(m_station.lines.at(target.line).name, device)
                                      : device;
}

bool LineCommands::parseDevice(const QString &text, Target &target)
{
    QString device;
    QString error;
    target.line = m_station.lineOfDevice(text, &device, &error);
    if (target.line < 0) {
        m_err << error << Qt::endl;
        return false;
    }
    const QString family = device.section(QLatin1Char('@'), 0, 0);
    bool ok = false;
    const int address = device.section(QLatin1Char('@'), 1).toInt(&ok);
    target.map = m_registry.family(family);
    if (!target.map || !ok || !isDeviceName(device)) {
        m_err << tr("'%1' is not a device: use FAMILY@ADDRESS, e.g. ipc300@1 (families: %2)")
                         .arg(text, m_registry.familyIds().join(QStringLiteral(", ")))
              << Qt::endl;
        return false;
    }
    if (address < 1 || address > 255) {
        m_err << tr("device address %1 is outside 1..255").arg(address) << Qt::endl;
        return false;
    }
    const ProtocolInfo &p = target.map->protocol;
    if ((address < p.addressMin || address > p.addressMax) && address != p.alwaysAnswersAddress.value_or(0)) {
        m_err << tr("a %1 cannot have address %2: its addresses are %3..%4")
                         .arg(target.map->family)
                         .arg(address)
                         .arg(p.addressMin)
                         .arg(p.addressMax)
              << Qt::endl;
        return false;
    }
    target.address = quint8(address);
    return true;
}

void LineCommands::interrupt(int signal)
{
    if (m_finished || m_interruptCode)
        return;
    m_interruptCode = signal == SIGTERM  ? exitcode::Terminated
            : signal == SIGHUP            ? exitcode::HungUp
            : signal == SIGPIPE           ? exitcode::OutputClosed
                                          : exitcode::Interrupted;
    m_interruptSummary = progressSummary();
    // Jobs stop asking; closing the line drops what has not gone out, and a write under
    // way ends as unknown. Their outcomes (and audit records) arrive from the event loop:
    // the command ends right after them.
    for (const std::unique_ptr<Line> &line : m_lines) {
        if (!line)
            continue;
        line->identity->cancel();
        if (line->scanner)
            line->scanner->cancel();
    }
    if (m_broadcast)
        m_broadcast->cancel();
    for (const std::unique_ptr<Line> &line : m_lines) {
        if (line)
            line->bus->close();
    }
    QMetaObject::invokeMethod(this, [this] { finish(m_interruptCode); }, Qt::QueuedConnection);
}

QString LineCommands::progressSummary() const
{
    if (m_command == QLatin1String("scan")) {
        int found = 0;
        for (const std::unique_ptr<Line> &line : m_lines)
            found += line ? line->found : 0;
        return tr("%n device(s) found before the scan stopped", nullptr, found);
    }
    if (m_command == QLatin1String("monitor")) {
        int cycles = 0;
        for (const Target &t : m_targets)
            cycles += t.cycles;
        return tr("%n poll cycle(s) printed", nullptr, cycles);
    }
    if (m_command == QLatin1String("write") || m_command == QLatin1String("restore")) {
        if (m_writesAsked == 0)
            return tr("nothing was written");
        const bool restore = m_command == QLatin1String("restore");
        const int left = int(restore ? m_pendingWrites.size() : m_assignments.size());
        QString summary = tr("%1 of %n write(s) done", nullptr, m_writesAsked).arg(m_writesAsked - left);
        if (restore)
            summary += tr(" (%n restored and verified)", nullptr, m_restored);
        const bool underWay = m_writeTicket >= 0 && left > 0;
        if (underWay)
            summary += tr("; %1 was being written: its outcome is unknown, check the device")
                               .arg(restore ? m_pendingWrites.first().first : m_assignments.first().entryId);
        if (left - underWay > 0)
            summary += tr("; %n not written", nullptr, left - underWay);
        return summary;
    }
    if (m_command == QLatin1String("backup"))
        return tr("no backup saved");
    if (m_command == QLatin1String("report"))
        return tr("no report written");
    return tr("nothing was written");
}

bool LineCommands::stopIfOutputClosed()
{
    // SIGPIPE arrives through the event loop, after the step that raised it: the next
    // write is not sent for a reader that is gone.
    if (!OutputCheck::closed(m_out))
        return false;
    interrupt(SIGPIPE);
    return true;
}

void LineCommands::finish(int code)
{
    if (m_finished)
        return;
    m_finished = true;
    if (m_interruptCode) {
        code = m_interruptCode;
        m_err << '\n'   // after a prompt or a progress line
              << signalSummary(code - 128, m_interruptSummary) << Qt::endl;
    }
    if (m_auditFailed && code == exitcode::Ok)
        code = exitcode::Failed;
    // diff as diff(1): 1 says the two differ; any other failure (no answer, a lost line)
    // is trouble.
    if (m_command == QLatin1String("diff") && code == exitcode::Failed && !m_differs)
        code = exitcode::Usage;
    if (m_monitoring)
        code = reportUnconfirmed(code);
    m_out.flush();
    m_err.flush();
    for (const std::unique_ptr<Line> &line : m_lines) {
        if (line)
            line->bus->close();
    }
    emit finished(code);
}

std::optional<int> LineCommands::scan(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("scan"),
                         tr("Finds devices on the line and names their family; with several lines (--line, "
                            "--station), on every line at once."));
    addLineOptions(parser, false);
    parser.addOption({QStringLiteral("from"), tr("First address (default 1)."), tr("address"), QStringLiteral("1")});
    parser.addOption({QStringLiteral("to"), tr("Last address (default 247)."), tr("address"), QStringLiteral("247")});
    parser.addOption({QStringLiteral("thorough"),
                      tr("Probe every address at the full timeout (the slowest family's worst case), twice where "
                         "silent. Slow; the default quick scan probes again at the full timeout wherever it heard "
                         "anything.")});
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 0, 0))
        return stop;
    const bool thorough = parser.isSet(QStringLiteral("thorough"));
    bool okFrom = false;
    bool okTo = false;
    const int from = parser.value(QStringLiteral("from")).toInt(&okFrom);
    const int to = parser.value(QStringLiteral("to")).toInt(&okTo);
    if (!okFrom || !okTo || from < 1 || to > 255 || from > to) {
        m_err << tr("--from and --to must be addresses 1..255, from <= to") << Qt::endl;
        return 2;
    }
    if (const auto stop = readStation(parser))
        return stop;
    for (qsizetype i = 0; i < m_station.lines.size(); ++i)
        prepareLine(i);
    if (const auto stop = openLines(parser))
        return stop;
    for (qsizetype i = 0; i < m_station.lines.size(); ++i) {
        Line &line = *m_lines[size_t(i)];
        line.scanner = std::make_unique<DeviceScanner>(*line.bus, m_registry.families());
        line.scanner->setMode(thorough ? DeviceScanner::Mode::Thorough : DeviceScanner::Mode::Quick);
        connect(line.scanner.get(), &DeviceScanner::progress, this, [this, i](int address, int done, int total) {
            const qint64 left = (m_lines[size_t(i)]->scanner->remainingMs() + 999) / 1000;
            m_lines[size_t(i)]->progress =
                    tr("address %1 (%2 of %3), about %n s left", nullptr, int(left)).arg(address).arg(done + 1).arg(total);
            showScanProgress();
        });
        connect(line.scanner.get(), &DeviceScanner::found, this,
                [this, i](int address, std::shared_ptr<const RegisterMap> map) {
                    clearScanProgress();
                    if (address == map->protocol.alwaysAnswersAddress) {
                        // Every device of the family answers there, whatever its own address.
                        m_err << lineMessage(i, tr("address %1 answers as %2, which every %2 does whatever its own "
                                                   "address: not listed")
                                                        .arg(address)
                                                        .arg(map->family))
                              << Qt::endl;
                        return;
                    }
                    Target target;
                    target.map = map;
                    target.address = quint8(address);
                    target.line = i;
                    m_out << targetName(target) << '\t' << map->name << Qt::endl;
                    ++m_lines[size_t(i)]->found;
                });
        connect(line.scanner.get(), &DeviceScanner::unknownDevice, this, [this, i](int address) {
            clearScanProgress();
            m_err << lineMessage(i, tr("address %1 answers, but matches no known family").arg(address))
                  << Qt::endl;
        });
        connect(line.scanner.get(), &Job::finished, this, [this, i] { scanFinished(i); });
        m_err << lineMessage(i, scanPlan(*line.scanner, *line.bus, from, to)) << Qt::endl;
        line.scanStartedMs = line.bus->clockMs();
        line.scanner->start(from, to);
    }
    return std::nullopt;
}

QString LineCommands::scanPlan(const DeviceScanner &scanner, const Bus &bus, int from, int to) const
{
    const int full = scanner.fullTimeoutMs();
    if (scanner.effectiveMode(from, to) == DeviceScanner::Mode::Quick) {
        QString plan = tr("quick scan of addresses %1..%2: each probed once at %3 ms, again at the full %4 ms where "
                          "anything was heard (--thorough probes every address at the full timeout)")
                               .arg(from)
                               .arg(to)
                               .arg(scanner.quickTimeoutMs())
                               .arg(full);
        const QList<int> listeners = scanner.listenersFor(from, to);
        if (!listeners.isEmpty())
            plan += QLatin1String("; ")
                    + tr("the range is short, so %n address(es) outside it (%1) are probed once first, to hear "
                         "late answers; what answers there is not reported",
                         nullptr, int(listeners.size()))
                              .arg(joinedAddresses(listeners));
        return plan;
    }
    const qint64 worst = (scanner.thoroughWorstMs(from, to) + 999) / 1000;
    const QString why = scanner.mode() == DeviceScanner::Mode::Thorough
            ? tr("as asked")
            : bus.lineKind() == LineAddress::Kind::ModbusTcp
            ? tr("a Modbus TCP gateway answers every request itself, at its own timeout")
            : tr("the range is too short to listen for late answers after a quick pass, and the timeout too long "
                 "to borrow listeners for it");
    return tr("thorough scan of addresses %1..%2 (%3): a silent address costs two probes at %4 ms, each followed "
              "by as long a quiet time; up to %n s", nullptr, int(worst))
            .arg(from)
            .arg(to)
            .arg(why)
            .arg(full);
}

void LineCommands::showScanProgress()
{
    QStringList parts;
    for (const std::unique_ptr<Line> &line : m_lines) {
        if (!line->scanDone && !line->progress.isEmpty())
            parts << (m_lines.size() > 1 ? QStringLiteral("%1 %2").arg(line->name, line->progress) : line->progress);
    }
    const QString text = tr("scanning %1").arg(parts.join(QStringLiteral(", ")));
    m_err << '\r' << text.leftJustified(m_progressWidth) << Qt::flush;
    m_progressWidth = int(text.size());
}

void LineCommands::clearScanProgress()
{
    m_err << '\r' << QString(m_progressWidth, QLatin1Char(' ')) << '\r';
    m_progressWidth = 0;
}

void LineCommands::scanFinished(qsizetype index)
{
    Line &line = *m_lines[size_t(index)];
    line.scanDone = true;
    clearScanProgress();
    const double seconds = double(line.bus->clockMs() - line.scanStartedMs) / 1000.0;
    QString summary = tr("%n device(s) found in %1 s", nullptr, line.found).arg(seconds, 0, 'f', 1);
    if (line.scanner->reprobed() > 0)
        summary += QLatin1String("; ")
                + tr("%n address(es) probed again at the full timeout", nullptr, line.scanner->reprobed());
    if (m_lines.size() > 1)
        summary = tr("%1: %2").arg(line.name, summary);
    m_err << summary << Qt::endl;
    if (!std::all_of(m_lines.cbegin(), m_lines.cend(), [](const std::unique_ptr<Line> &l) { return l->scanDone; }))
        return;
    // A line without a device is worth a look (a wrong baud rate, a loose wire): a failure.
    bool empty = false;
    int found = 0;
    for (const std::unique_ptr<Line> &l : m_lines) {
        empty = empty || l->found == 0;
        found += l->found;
    }
    if (m_lines.size() > 1)
        m_err << tr("%n device(s) found", nullptr, found) << Qt::endl;
    finish(empty || m_failed ? exitcode::Failed : exitcode::Ok);
}

void LineCommands::printValues(const Target &target, const QStringList &ids)
{
    if (m_json) {
        QJsonArray array;
        for (const QString &id : ids) {
            const RegisterEntry *e = target.map->entry(id);
            const EntryState *s = busOf(target).entryState(target.id, id);
            if (isFailure(s))
                m_failed = true;
            array.append(QJsonObject{{"family", target.map->family},
                                     {"address", int(target.address)},
                                     {"id", id},
                                     {"label", e->label},
                                     {"register", formatAddress(e->address)},
                                     {"value", s ? jsonValue(*s) : QJsonValue()},
                                     {"unit", e->unit},
                                     {"status", readStatus(s)}});
        }
        m_out << QJsonDocument(array).toJson(QJsonDocument::Indented);
        return;
    }
    for (const QString &id : ids) {
        const RegisterEntry *e = target.map->entry(id);
        const EntryState *s = busOf(target).entryState(target.id, id);
        QString shown;
        if (isFailure(s)) {
            m_failed = true;
            shown = s && s->error == ReadError::Exception
                    ? tr("exception %1: %2").arg(s->exceptionCode).arg(target.map->exceptionMeaning(s->exceptionCode))
                    : s && s->error == ReadError::NotAvailable ? tr("not available on this device (exception 2)")
                                                                 : tr("no answer");
        } else {
            shown = printable(s->value.display);
            if (s->value.isOk() && !e->unit.isEmpty())
                shown += QLatin1Char(' ') + e->unit;
        }
        m_out << formatAddress(e->address) << "  " << id << " = " << shown << "  [" << readStatus(s) << ']' << Qt::endl;
    }
}

std::optional<int> LineCommands::read(const QStringList &arguments, bool dump)
{
    CommandParser parser(dump ? QStringLiteral("dump") : QStringLiteral("read"),
                         dump ? tr("Reads every readable entry of a device once.")
                              : tr("Reads entries of a device once."));
    addLineOptions(parser);
    parser.addOption({QStringLiteral("json"),
                      tr("JSON array of {family, address, id, label, register, value, unit, status}.")});
    parser.addPositionalArgument(QStringLiteral("device"),
                                 tr("FAMILY@ADDRESS, e.g. ipc300@1; LINE/FAMILY@ADDRESS where there are several lines."));
    if (!dump)
        parser.addPositionalArgument(QStringLiteral("id"), tr("Entry ids."), QStringLiteral("id..."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, dump ? 1 : 2, dump ? 1 : -1))
        return stop;
    if (const auto stop = readStation(parser))
        return stop;
    QStringList args = parser.positionalArguments();
    Target target;
    if (!parseDevice(args.takeFirst(), target))
        return 2;
    QStringList ids;
    if (dump) {
        for (const RegisterEntry &e : target.map->entries()) {
            if (e.isReadable() && e.alias.isEmpty())
                ids << e.id;
        }
    } else {
        for (const QString &id : std::as_const(args)) {
            const RegisterEntry *e = target.map->entry(id);
            if (!e) {
                m_err << tr("'%1' is not an entry of %2").arg(id, target.map->family) << Qt::endl;
                return 2;
            }
            if (!e->isReadable()) {
                m_err << tr("'%1' is write-only").arg(id) << Qt::endl;
                return 2;
            }
            ids << id;
        }
    }
    m_json = parser.isSet(QStringLiteral("json"));
    m_targets = {target};
    m_ids = ids;
    prepareLine(target.line);
    if (const auto stop = openLines(parser))
        return stop;
    identity().pass(claims(), [this, dump] { readOnce(dump); }, [this](int code) { finish(code); },
                     [this] {
                         // Nothing answers: report the entries as unread, read nothing.
                         printValues(m_targets.first(), m_ids);
                         m_err << tr("some entries could not be read") << Qt::endl;
                         finish(exitcode::Failed);
                     });
    return std::nullopt;
}

void LineCommands::readOnce(bool dump)
{
    Target &target = m_targets.first();
    bus().setPolling(false);
    target.id = bus().addDevice(target.map, target.address);
    bus().setPollEntries(target.id, dump ? QStringList() : m_ids);
    connect(&bus(), &Bus::pollCycleFinished, this, [this](DeviceId id, double) {
        if (id != m_targets.first().id)
            return;
        printValues(m_targets.first(), m_ids);
        if (m_failed)
            m_err << tr("some entries could not be read") << Qt::endl;
        finish(m_failed ? 1 : 0);
    });
    bus().requestCycle(target.id);
}

std::optional<int> LineCommands::write(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("write"),
                         tr("Writes entries of a device; each write is verified by reading it back.\n"
                            "\n"
                            "ID=VALUE writes the whole entry: for a bit field it replaces EVERY bit of\n"
                            "the word. ID.BIT=0|1 (or on|off, true|false) changes that bit only and keeps\n"
                            "the others as the device reports them, read just before the write; bits of\n"
                            "one entry given together go out in one write.\n"
                            "\n"
                            "Exit code: 0 every write confirmed (or acknowledged, where nothing reads it\n"
                            "back); 1 a write failed (refused by the device, read back different, not\n"
                            "sent, read-only mode); 3 the outcome of a write is unknown or unverified\n"
                            "(its answer was lost; a command is never sent twice): check the device;\n"
                            "2 wrong arguments, nothing sent."));
    addLineOptions(parser);
    parser.addOption({QStringLiteral("verify"),
                      tr("For a broadcast (FAMILY@0): the addresses to read it back from, e.g. 1,2,5."),
                      tr("addresses")});
    BroadcastGate::addOptions(parser);
    parser.addPositionalArgument(QStringLiteral("device"),
                                 tr("FAMILY@ADDRESS, or FAMILY@0 for a broadcast; LINE/ before it where there are "
                                    "several lines."));
    parser.addPositionalArgument(QStringLiteral("assignment"),
                                 tr("ID=VALUE, e.g. input_setpoint=42.5, or ID.BIT=0|1, e.g. "
                                    "binary_signal_write.digital_output=1."),
                                 QStringLiteral("id=value|id.bit=0|1..."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 2))
        return stop;
    if (const auto stop = readStation(parser))
        return stop;
    QStringList args = parser.positionalArguments();
    const QString deviceText = args.takeFirst();
    Target target;
    QString device;
    QString lineError;
    target.line = m_station.lineOfDevice(deviceText, &device, &lineError);
    if (target.line < 0) {
        m_err << lineError << Qt::endl;
        return 2;
    }
    const bool broadcast = device.endsWith(QLatin1String("@0"));
    if (broadcast) {
        target.map = m_registry.family(device.chopped(2));
        if (!target.map) {
            m_err << tr("'%1' is not a device: use FAMILY@ADDRESS").arg(deviceText) << Qt::endl;
            return 2;
        }
    } else if (!parseDevice(deviceText, target)) {
        return 2;
    }
    QList<quint8> verifyAddresses;
    if (broadcast) {
        for (const QString &a : parser.value(QStringLiteral("verify")).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            bool ok = false;
            const int address = a.toInt(&ok);
            if (!ok || address < 1 || address > 255) {
                m_err << tr("--verify takes addresses 1..255, not '%1'").arg(a) << Qt::endl;
                return 2;
            }
            verifyAddresses << quint8(address);
        }
    }
    // Everything is checked before the line is opened: nothing is sent for a typo.
    QString error;
    const std::optional<QList<WriteAssignment>> assignments = WriteAssignment::parse(*target.map, args, broadcast, &error);
    if (!assignments) {
        m_err << error << Qt::endl;
        return 2;
    }
    if (auditLogMissing())
        return exitcode::Failed;
    m_assignments = *assignments;
    m_targets = {target};
    Line &line = prepareLine(target.line);
    if (broadcast) {
        m_broadcast = std::make_unique<BroadcastGate>(*line.bus, m_registry, m_err);
        if (const auto stop = m_broadcast->configure(parser, target.map, verifyAddresses))
            return stop;
    }
    if (const QString note = readOnlyNote(parser, target); !note.isEmpty())
        m_err << note << Qt::endl;
    if (const auto stop = openLines(parser))
        return stop;
    identity().recordSkipsIn(m_audit);
    if (broadcast)
        m_broadcast->pass(
                identity(), m_audit,
                [this, target](const QList<quint8> &readBack) { startWrites(target, true, readBack); },
                [this](int code) { finish(code); });
    else
        identity().pass({{target.address, target.map}}, [this, target] { startWrites(target, false, {}); },
                         [this](int code) { finish(code); });
    return std::nullopt;
}

void LineCommands::startWrites(Target target, bool broadcast, const QList<quint8> &verifyAddresses)
{
    m_writesAsked = int(m_assignments.size());
    bus().setPolling(false);
    if (broadcast) {
        // The bus reads a broadcast back from every device of the family it knows.
        for (quint8 address : std::as_const(verifyAddresses))
            bus().addDevice(target.map, address);
        target.address = 0;
    } else {
        target.id = bus().addDevice(target.map, target.address);
    }
    m_targets = {target};
    connect(&bus(), &Bus::writeFinished, this, [this](int ticket, const WriteOutcome &outcome) {
        if (ticket != m_writeTicket)
            return;
        m_writeTicket = -1;
        reportWrite(m_assignments.takeFirst().entryId, outcome);
        writeNext();
    });
    // Read what is readable first, so the output and the audit log show the old values.
    QStringList readable;
    for (const WriteAssignment &a : std::as_const(m_assignments)) {
        if (!broadcast && target.map->entry(a.entryId)->isReadable())
            readable << a.entryId;
    }
    if (readable.isEmpty()) {
        writeNext();
        return;
    }
    bus().setPollEntries(target.id, readable);
    connect(&bus(), &Bus::pollCycleFinished, this, [this](DeviceId, double) { writeNext(); },
            Qt::SingleShotConnection);
    bus().requestCycle(target.id);
}

void LineCommands::reportWrite(const QString &id, const WriteOutcome &outcome)
{
    QTextStream &stream = outcome.succeeded() ? m_out : m_err;
    stream << id << ": ";
    // These messages do not name their result: the word a script and a person look for.
    if (outcome.result == WriteOutcome::Result::Unknown)
        stream << tr("unknown, check the device: ");
    else if (outcome.result == WriteOutcome::Result::Unverified)
        stream << tr("unverified: ");
    stream << outcome.message;
    const EntryState *old = m_targets.first().address ? bus().entryState(m_targets.first().id, id) : nullptr;
    if (outcome.succeeded() && old && old->hasValue())
        stream << ' ' << tr("(was %1)").arg(old->value.display);
    stream << Qt::endl;
    const bool uncertain = outcome.result == WriteOutcome::Result::Unknown
            || outcome.result == WriteOutcome::Result::Unverified;
    m_uncertain |= uncertain;
    m_failed |= !outcome.succeeded() && !uncertain;
}

void LineCommands::writeNext()
{
    if (m_interruptCode || stopIfOutputClosed())
        return;
    if (m_assignments.isEmpty()) {
        // An unknown outcome outweighs a failure: the device has to be looked at.
        finish(m_uncertain ? exitcode::Uncertain : m_failed ? 1 : 0);
        return;
    }
    const Target &target = m_targets.first();
    const WriteAssignment &next = m_assignments.first();
    if (next.isBitChange())
        m_writeTicket = bus().writeBits(target.id, next.entryId, next.bits);
    else
        m_writeTicket = target.address == 0 ? bus().writeBroadcast(target.map->family, next.entryId, next.value)
                                            : bus().write(target.id, next.entryId, next.value);
}

bool LineCommands::auditLogMissing()
{
    if (!m_logFolder.isEmpty())
        return false;
    m_err << tr("%1; writes are kept in the audit log, so nothing is written").arg(m_logFolderError) << Qt::endl;
    return true;
}

QString LineCommands::readOnlyNote(const CommandParser &parser, const Target &target) const
{
    if (SystemSettings::readOnly())
        return tr("read-only mode is set by the system configuration (%1): nothing is written to the devices")
                .arg(SystemSettings::fileName());
    if (parser.isSet(QStringLiteral("read-only")))
        return tr("read-only mode (--read-only): nothing is written to the devices");
    if (m_station.lines.at(target.line).settings.readOnly)
        return tr("the line %1 is read-only (station file): nothing is written to the devices")
                .arg(m_station.lines.at(target.line).name);
    return {};
}

std::optional<int> LineCommands::monitor(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("monitor"),
                         tr("Polls devices continuously and prints every poll cycle; devices of several lines are "
                            "polled at once, each line on its own.\n"
                            "\n"
                            "A device that does not answer does not stop the others: its records say so\n"
                            "(condition offline), and its family is checked whenever it answers (again);\n"
                            "until then it has no values. Devices never confirmed are named at the end.\n"
                            "\n"
                            "Exit code: 0 every value read; 1 a value could not be read, a line was lost,\n"
                            "or a device was never confirmed; 4 another family answered at a device's\n"
                            "address and it was never confirmed; 129, 130, 141, 143 after a signal."));
    addLineOptions(parser);
    parser.addOption({QStringLiteral("interval"), tr("Poll interval per device in ms (default 0: as fast as the line allows)."),
                      tr("ms"), QStringLiteral("0")});
    parser.addOption({QStringLiteral("cycles"), tr("Stop after this many cycles of every device (default: run until stopped)."),
                      tr("n"), QStringLiteral("0")});
    parser.addOption({QStringLiteral("ids"), tr("Comma-separated entry ids to poll (default: all readable entries)."),
                      tr("ids")});
    parser.addOption({QStringLiteral("jsonl"), tr("One JSON object per completed poll cycle of a device.")});
    parser.addOption({QStringLiteral("csv"), tr("CSV rows: time,device,id,value,unit,status.")});
    parser.addPositionalArgument(QStringLiteral("device"),
                                 tr("FAMILY@ADDRESS; LINE/FAMILY@ADDRESS where there are several lines (default with "
                                    "--station: every device of the station file)."),
                                 QStringLiteral("device..."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 0))
        return stop;
    m_json = parser.isSet(QStringLiteral("jsonl"));
    m_csv = parser.isSet(QStringLiteral("csv"));
    if (m_json == m_csv) {
        m_err << tr("jumoctl monitor: give exactly one of --jsonl and --csv") << Qt::endl;
        return 2;
    }
    bool ok = false;
    const int interval = parser.value(QStringLiteral("interval")).toInt(&ok);
    if (!ok || interval < 0) {
        m_err << tr("--interval must be a number of ms >= 0") << Qt::endl;
        return 2;
    }
    m_cyclesWanted = parser.value(QStringLiteral("cycles")).toInt(&ok);
    if (!ok || m_cyclesWanted < 0) {
        m_err << tr("--cycles must be a number >= 0") << Qt::endl;
        return 2;
    }
    if (const auto stop = readStation(parser))
        return stop;
    QStringList devices = parser.positionalArguments();
    if (devices.isEmpty()) {
        for (const StationDevice &d : m_station.devices())
            devices << StationConfig::qualifiedName(m_station.lines.at(d.line).name, d.device);
    }
    if (devices.isEmpty()) {
        m_err << tr("jumoctl monitor: name at least one device (or give a station file that lists them)") << Qt::endl;
        return 2;
    }
    const QStringList ids = parser.value(QStringLiteral("ids")).split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString &text : std::as_const(devices)) {
        Target target;
        if (!parseDevice(text, target))
            return 2;
        for (const QString &id : ids) {
            const RegisterEntry *e = target.map->entry(id);
            if (!e || !e->isReadable()) {
                m_err << tr("'%1' is not a readable entry of %2").arg(id, target.map->family) << Qt::endl;
                return 2;
            }
        }
        m_targets << target;
        prepareLine(target.line);
    }
    m_monitorIds = ids;
    if (const auto stop = openLines(parser))
        return stop;
    // Devices come and go while they are monitored: none is checked once before, each is
    // checked by its bus whenever it answers (again), as in the HMI.
    startMonitor(m_monitorIds, interval);
    return std::nullopt;
}

QStringList LineCommands::monitorEntries(const Target &target) const
{
    if (!m_monitorIds.isEmpty())
        return m_monitorIds;
    QStringList entryIds;
    for (const RegisterEntry &e : target.map->entries()) {
        if (e.isReadable() && e.alias.isEmpty())
            entryIds << e.id;
    }
    return entryIds;
}

void LineCommands::startMonitor(const QStringList &ids, int interval)
{
    m_monitoring = true;
    if (m_csv)
        m_out << "time,device,id,value,unit,status" << Qt::endl;
    for (const std::unique_ptr<Line> &line : m_lines) {
        if (line && !line->identity->isSkipped())
            line->bus->setIdentityCheck(m_registry.families());
    }
    for (Target &target : m_targets) {
        Bus &bus = busOf(target);
        target.id = bus.addDevice(target.map, target.address);
        bus.setPollEntries(target.id, ids);
        bus.setPollInterval(target.id, interval);
    }
    for (size_t i = 0; i < m_lines.size(); ++i) {
        if (!m_lines[i])
            continue;
        connect(m_lines[i]->bus.get(), &Bus::pollCycleFinished, this, [this](DeviceId id, double cycleMs) {
            auto target = std::find_if(m_targets.begin(), m_targets.end(), [id](const Target &t) { return t.id == id; });
            if (target == m_targets.end() || !noteIdentity(*target))
                return;
            printRecord(*target, monitorEntries(*target), cycleMs);
            // Polling on into output that goes nowhere would only hide the failure.
            if (stopIfOutputClosed())
                return;
            if (OutputCheck::failed(m_out)) {
                finish(exitcode::Failed);
                return;
            }
            ++target->cycles;
            checkMonitorDone();
        });
    }
}

void LineCommands::printRecord(const Target &target, const QStringList &entryIds, std::optional<double> cycleMs)
{
    Bus &bus = busOf(target);
    const QString time = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
    const QString device = targetName(target);
    if (m_json) {
        QJsonObject values;
        QJsonObject status;
        for (const QString &e : entryIds) {
            const EntryState *s = bus.entryState(target.id, e);
            values.insert(e, s ? jsonValue(*s) : QJsonValue());
            status.insert(e, s ? s->statusName() : QStringLiteral("timeout"));
            m_failed |= isFailure(s);
        }
        m_out << QJsonDocument(QJsonObject{{"time", time},
                                           {"line", m_station.lines.at(target.line).name},
                                           {"device", device},
                                           {"condition", conditionName(bus.condition(target.id).state)},
                                           {"cycle_ms", cycleMs ? QJsonValue(*cycleMs) : QJsonValue()},
                                           {"values", values},
                                           {"status", status}})
                         .toJson(QJsonDocument::Compact)
              << Qt::endl;
        return;
    }
    for (const QString &e : entryIds) {
        const EntryState *s = bus.entryState(target.id, e);
        const RegisterEntry *entry = target.map->entry(e);
        const QString value = csvField(s && s->isCurrent() && s->value.isOk() ? s->value.display : QString());
        m_out << time << ',' << device << ',' << e << ',' << value << ',' << entry->unit << ','
              << (s ? s->statusName() : QStringLiteral("timeout")) << '\n';
        m_failed |= isFailure(s);
    }
    m_out.flush();
}

bool LineCommands::noteIdentity(Target &target)
{
    const DeviceCondition condition = busOf(target).condition(target.id);
    switch (condition.state) {
    case DeviceCondition::State::Online:
        // The cycle under way when it was confirmed: what it read before is not its own
        // yet; the next cycle reads it all.
        for (const QString &id : monitorEntries(target)) {
            const EntryState *s = busOf(target).entryState(target.id, id);
            if (s && !s->isCurrent() && s->error == ReadError::Unconfirmed)
                return false;
        }
        target.confirmed = true;
        target.identityProblem.clear();
        break;
    case DeviceCondition::State::Identifying:
        // Its first check is under way: nothing to tell of it yet.
        if (condition.detail.isEmpty())
            return false;
        target.identityProblem = condition.detail;
        break;
    case DeviceCondition::State::WrongDevice:
        if (target.identityProblem != condition.detail)
            m_err << lineMessage(target.line, condition.detail) << Qt::endl;
        target.identityProblem = condition.detail;
        target.otherFamily = true;
        break;
    default:
        break;
    }
    return true;
}

int LineCommands::reportUnconfirmed(int code)
{
    bool otherFamily = false;
    for (const Target &t : std::as_const(m_targets)) {
        if (t.confirmed)
            continue;
        m_err << lineMessage(t.line, t.identityProblem.isEmpty()
                                             ? tr("never confirmed: %1 did not answer").arg(deviceName(*t.map, t.address))
                                             : tr("never confirmed: %1").arg(t.identityProblem))
              << Qt::endl;
        otherFamily |= t.otherFamily;
        code = code == exitcode::Ok ? exitcode::Failed : code;
    }
    return otherFamily && code == exitcode::Failed ? exitcode::WrongDevice : code;
}

void LineCommands::checkMonitorDone()
{
    // A device whose line is lost holds nobody up: its records said so.
    if (m_cyclesWanted > 0 && std::all_of(m_targets.cbegin(), m_targets.cend(), [this](const Target &t) {
            return t.cycles >= m_cyclesWanted || lineOf(t).lost;
        }))
        finish(m_failed ? 1 : 0);
}

void LineCommands::readParameters(const std::function<void(const ParameterSet &, const QStringList &)> &done)
{
    identity().pass(claims(), [this, done] { readParametersNow(done); }, [this](int code) { finish(code); });
}

void LineCommands::readParametersNow(const std::function<void(const ParameterSet &, const QStringList &)> &done)
{
    Target &target = m_targets.first();
    QStringList ids = ParameterSet::parameterIds(*target.map) + target.map->identity;
    if (target.map->entry(QStringLiteral("software_version")))
        ids << QStringLiteral("software_version");
    ids.removeDuplicates();
    bus().setPolling(false);
    target.id = bus().addDevice(target.map, target.address);
    bus().setPollEntries(target.id, ids);
    auto *transfer = new ParameterTransfer(&bus(), target.id, this);
    connect(transfer, &ParameterTransfer::readFinished, this,
            [this, done](const ParameterSet &set, const QStringList &failed) {
                QStringList reasons;
                for (const QString &id : failed) {
                    const EntryState *s = bus().entryState(m_targets.first().id, id);
                    reasons << QStringLiteral("%1 (%2)").arg(id, s ? s->statusName() : QStringLiteral("timeout"));
                }
                done(set, reasons);
            });
    transfer->read();
}

void LineCommands::printDifferences(const QList<ParameterDifference> &differences, const QString &oldName,
                                    const QString &newName)
{
    if (differences.isEmpty()) {
        m_out << tr("no differences") << Qt::endl;
        return;
    }
    m_out << tr("%n parameter(s) differ (%1 -> %2):", nullptr, int(differences.size())).arg(oldName, newName) << Qt::endl;
    for (const ParameterDifference &d : differences) {
        m_out << "  " << d.id << " (" << d.label << "): " << (d.oldValue.isNull() ? tr("(missing)") : printable(d.oldDisplay))
              << " -> " << (d.newValue.isNull() ? tr("(missing)") : printable(d.newDisplay));
        if (!d.unit.isEmpty())
            m_out << ' ' << d.unit;
        m_out << Qt::endl;
    }
}

std::optional<int> LineCommands::parameters(const QString &command, const QStringList &arguments)
{
    const bool backup = command == QLatin1String("backup");
    const bool restore = command == QLatin1String("restore");
    CommandParser parser(command, backup ? tr("Saves every parameter of a device to a file.")
                                  : restore ? tr("Writes the parameters of a file that differ from the device, each "
                                                 "verified by read-back.")
                                            : tr("Compares a device with a parameter file, or two files.\n"
                                                 "\n"
                                                 "Exit code (as diff(1)): 0 nothing differs; 1 something does; 2 a\n"
                                                 "problem: a file that cannot be read or compared (another family,\n"
                                                 "unknown ids, invalid values, another software version), a device\n"
                                                 "that does not answer; 4 another family at the address."));
    addLineOptions(parser);
    if (restore)
        parser.addOption({QStringLiteral("yes"), tr("Write without asking.")});
    parser.addPositionalArgument(QStringLiteral("device"),
                                 command == QLatin1String("diff")
                                         ? tr("FAMILY@ADDRESS (LINE/FAMILY@ADDRESS where there are several lines), "
                                              "or a first parameter file.")
                                         : tr("FAMILY@ADDRESS, e.g. ipc300@1; LINE/FAMILY@ADDRESS where there are "
                                              "several lines."));
    parser.addPositionalArgument(QStringLiteral("file"), tr("Parameter file (JSON)."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 2, 2))
        return stop;
    const QString first = parser.positionalArguments().at(0);
    const QString path = parser.positionalArguments().at(1);

    auto load = [this](const QString &file) -> std::optional<ParameterSet> {
        QString error;
        const std::optional<QByteArray> json = RegularFile::read(file, RegularFile::defaultLimit, &error);
        if (!json) {
            m_err << tr("cannot read %1").arg(error) << Qt::endl;
            return std::nullopt;
        }
        std::optional<ParameterSet> set = ParameterSet::fromJson(*json, &error);
        if (!set)
            m_err << file << ": " << error << Qt::endl;
        return set;
    };

    if (command == QLatin1String("diff") && !isDeviceName(first)) {
        const std::optional<ParameterSet> a = load(first);
        const std::optional<ParameterSet> b = load(path);
        if (!a || !b)
            return 2;
        const auto map = m_registry.family(a->family);
        if (!map || a->family != b->family) {
            m_err << tr("the files are for different or unknown families: %1, %2").arg(a->family, b->family) << Qt::endl;
            return 2;
        }
        // Checked as a file compared with a device is: ids, parameters, values.
        for (const auto &[set, name] : {std::make_pair(&*a, first), std::make_pair(&*b, path)}) {
            const QString problem = set->incompatibility(*map, QString());
            if (!problem.isEmpty()) {
                m_err << name << ": " << problem << Qt::endl;
                return 2;
            }
        }
        const QList<ParameterDifference> d = a->differences(*b, *map);
        printDifferences(d, first, path);
        return d.isEmpty() ? 0 : 1;
    }

    if (const auto stop = readStation(parser))
        return stop;
    Target target;
    if (!parseDevice(first, target))
        return 2;
    // A file that cannot be compared is a problem of diff's (2, as diff(1)), not a
    // difference; restore refuses it (1). Checked before the line is opened, as diff
    // FILE FILE checks its files; the software version once the device has told it.
    const int refusedCode = restore ? exitcode::Failed : exitcode::Usage;
    std::optional<ParameterSet> file;
    if (!backup) {
        file = load(path);
        if (!file)
            return 2;
        if (const QString problem = file->incompatibility(*target.map, QString()); !problem.isEmpty()) {
            m_err << tr("refused: %1").arg(problem) << Qt::endl;
            return refusedCode;
        }
    }
    if (const QString note = restore ? readOnlyNote(parser, target) : QString(); !note.isEmpty()) {
        m_err << note << Qt::endl << tr("read-only mode: nothing would be restored") << Qt::endl;
        return 1;
    }
    if (restore && auditLogMissing())
        return exitcode::Failed;
    m_targets = {target};
    prepareLine(target.line);
    if (const auto stop = openLines(parser))
        return stop;
    if (restore)
        identity().recordSkipsIn(m_audit);
    const bool yes = restore && parser.isSet(QStringLiteral("yes"));
    readParameters([this, backup, restore, path, file, yes, first, refusedCode](const ParameterSet &device,
                                                                              const QStringList &failed) {
        if (!failed.isEmpty()) {
            m_err << tr("these parameters could not be read, nothing was done: %1").arg(failed.join(QStringLiteral(", ")))
                  << Qt::endl;
            finish(1);
            return;
        }
        const RegisterMap &map = *m_targets.first().map;
        if (backup) {
            QString error;
            if (!FileSaver::save(path, device.toJson(), &error)) {
                m_err << error << Qt::endl;
                finish(exitcode::Failed);
                return;
            }
            m_out << tr("%n parameter(s) of %1 saved to %2", nullptr, int(device.values.size())).arg(first, path)
                  << Qt::endl;
            finish(0);
            return;
        }
        const QString refused = file->incompatibility(map, device.softwareVersion);
        if (!refused.isEmpty()) {
            m_err << tr("refused: %1").arg(refused) << Qt::endl;
            finish(refusedCode);
            return;
        }
        const QList<ParameterDifference> shown = device.differences(*file, map);
        printDifferences(shown, first, path);
        if (!restore) {
            m_differs = !shown.isEmpty();
            finish(m_differs ? exitcode::Failed : exitcode::Ok);
            return;
        }
        const QList<ParameterDifference> differences = ParameterSet::toRestore(shown);
        if (const int left = int(shown.size() - differences.size()); left > 0)
            m_out << tr("%n parameter(s) missing from the file are left as they are.", nullptr, left) << Qt::endl;
        if (differences.isEmpty()) {
            finish(0);
            return;
        }
        if (yes) {
            startRestore(differences);
            return;
        }
        // A person at a terminal confirms; a script has to say --yes. The event loop runs
        // while the question waits, so Ctrl-C ends the command at once.
        auto *prompt = new Prompt(m_out, 0, this);
        prompt->ask(tr("Write %n parameter(s) to the device? [y/N] ", nullptr, int(differences.size())),
                    [this, differences](const QString &text) {
                        const QString answer = text.toLower();
                        if (answer != QLatin1String("y") && answer != tr("y") && answer != QLatin1String("yes")) {
                            m_err << tr("nothing written") << Qt::endl;
                            finish(exitcode::Failed);
                            return;
                        }
                        startRestore(differences);
                    });
    });
    return std::nullopt;
}

void LineCommands::startRestore(const QList<ParameterDifference> &differences)
{
    // EEPROM-aware: only what differs is written, one entry at a time.
    for (const ParameterDifference &d : differences)
        m_pendingWrites << qMakePair(d.id, d.newValue);
    m_writesAsked = int(m_pendingWrites.size());
    connect(&bus(), &Bus::writeFinished, this, [this](int ticket, const WriteOutcome &outcome) {
        if (ticket != m_writeTicket)
            return;
        m_writeTicket = -1;
        const QString id = m_pendingWrites.takeFirst().first;
        (outcome.succeeded() ? m_out : m_err) << id << ": " << outcome.message << Qt::endl;
        if (outcome.succeeded())
            ++m_restored;
        else
            m_failed = true;
        restoreNext();
    });
    restoreNext();
}

std::optional<int> LineCommands::report(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("report"),
                         tr("Writes the commissioning report of a device, a document to sign: a title block (site, "
                            "cabinet, tag, engineer, date, device, line), identity, parameters with the manual's "
                            "defaults, live values, active alarms, today's writes and signature lines. FILE ending in "
                            ".pdf gives PDF (A4, numbered pages), else HTML."));
    addLineOptions(parser);
    parser.addOption({QStringLiteral("site"), tr("Site for the report's title block (the plant, the hall)."), tr("text")});
    parser.addOption({QStringLiteral("cabinet"), tr("Cabinet or panel the device is in."), tr("text")});
    parser.addOption({QStringLiteral("tag"), tr("The device's tag in the plant, e.g. TIC-101."), tr("text")});
    parser.addOption({QStringLiteral("engineer"), tr("Name of the commissioning engineer."), tr("name")});
    parser.addPositionalArgument(QStringLiteral("device"),
                                 tr("FAMILY@ADDRESS, e.g. ipc300@1; LINE/FAMILY@ADDRESS where there are several lines."));
    parser.addPositionalArgument(QStringLiteral("file"), tr("Report file (.pdf or .html)."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 2, 2))
        return stop;
    if (const auto stop = readStation(parser))
        return stop;
    Target target;
    if (!parseDevice(parser.positionalArguments().at(0), target))
        return 2;
    m_targets = {target};
    prepareLine(target.line);
    if (const auto stop = openLines(parser))
        return stop;
    const QString path = parser.positionalArguments().at(1);
    const ReportTitle title{parser.value(QStringLiteral("site")), parser.value(QStringLiteral("cabinet")),
                            parser.value(QStringLiteral("tag")), parser.value(QStringLiteral("engineer"))};
    identity().pass(claims(), [this, path, title] { startReport(path, title); }, [this](int code) { finish(code); });
    return std::nullopt;
}

void LineCommands::startReport(const QString &path, const ReportTitle &title)
{
    Target &target = m_targets.first();
    bus().setPolling(false);
    target.id = bus().addDevice(target.map, target.address);
    connect(&bus(), &Bus::pollCycleFinished, this, [this, path, title](DeviceId id, double) {
        const Target &t = m_targets.first();
        if (id != t.id)
            return;
        const DeviceStatistics *stats = bus().statistics(id);
        if (stats->responses == 0) {
            m_err << tr("%1 did not answer: no report written").arg(deviceName(*t.map, t.address)) << Qt::endl;
            finish(1);
            return;
        }
        CommissioningReport report(*t.map, t.address, [this, id](const QString &entry) { return bus().entryState(id, entry); });
        // The command line has no session: its writes of today stand in for one.
        // Read back from the newest to the first record before today, so that a large
        // log costs no more than its recent part.
        if (m_logFolder.isEmpty()) {
            m_err << tr("no report written: its writes of today are unknown: %1").arg(m_logFolderError) << Qt::endl;
            finish(exitcode::Failed);
            return;
        }
        EventLogReader audit(m_audit->path());
        const QString device = deviceName(*t.map, t.address);
        const QDateTime since = QDateTime(QDate::currentDate(), QTime(0, 0));
        QList<QJsonObject> writes;
        while (const std::optional<QJsonObject> r = audit.previous()) {
            const QDateTime time = QDateTime::fromString(r->value("time").toString(), Qt::ISODateWithMs);
            if (time.isValid() && time < since)
                break;
            if (r->value("device").toString() == device)
                writes.prepend(*r);
        }
        if (!audit.lastError().isEmpty()) {
            m_err << tr("no report written: its writes of today are unknown: %1").arg(audit.lastError()) << Qt::endl;
            finish(exitcode::Failed);
            return;
        }
        report.setWrites(writes, since);
        report.setTitle(title);
        report.setLine(bus().settings());
        report.setSoftware(QStringLiteral("jumoctl %1").arg(QStringLiteral(JUMO_VERSION)));
        QString error;
        const ReportWriter::Pages pages{tr("Commissioning report of %1").arg(device), report.pageHeader(), report.pageFooter()};
        if (!ReportWriter::write(report.html(), path, pages, &error)) {
            m_err << error << Qt::endl;
            finish(1);
            return;
        }
        m_out << tr("report of %1 written to %2").arg(device, path) << Qt::endl;
        finish(0);
    });
    bus().requestCycle(target.id);
}

QList<IdentityCheck::Claim> LineCommands::claims() const
{
    QList<IdentityCheck::Claim> out;
    for (const Target &t : m_targets)
        out << IdentityCheck::Claim{t.address, t.map};
    return out;
}

void LineCommands::restoreNext()
{
    if (m_interruptCode || stopIfOutputClosed())
        return;
    if (m_pendingWrites.isEmpty()) {
        m_out << tr("%n parameter(s) restored and verified", nullptr, m_restored) << Qt::endl;
        finish(m_failed ? 1 : 0);
        return;
    }
    m_writeTicket = bus().write(m_targets.first().id, m_pendingWrites.first().first, m_pendingWrites.first().second);
}

} // namespace jumo
