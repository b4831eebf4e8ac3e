#include "protocol/csv.h"
#include "linecommands.h"

#include "bus/lineaddress.h"

#include "commissioning/parametertransfer.h"

#include "broadcastgate.h"
#include "commandparser.h"
#include "prompt.h"
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
#include "systemsettings.h"

#include <QDateTime>
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

} // namespace

LineCommands::LineCommands(const FamilyRegistry &registry, QTextStream &out, QTextStream &err, QObject *parent)
    : QObject(parent), m_registry(registry), m_out(out), m_err(err)
{
    // Writes from the command line are audited like the HMI's, in the same log.
    m_audit = new EventLog(EventLog::defaultFolder() + QStringLiteral("/write-audit.jsonl"), this);
    // Rotated as the HMI rotates it: the same settings.
    m_audit->setRotation(EventLog::Rotation::fromSettings(QSettings(QStringLiteral("jumo"), QStringLiteral("jumo-hmi"))));
    new WriteAudit(&m_bus, m_audit, this);
    connect(m_audit, &EventLog::writeFailed, this, [this](const QString &message) {
        m_err << tr("the audit log did not take a record: %1").arg(message) << Qt::endl;
        m_auditFailed = true;
    });
    m_identity = new IdentityGate(m_bus, m_registry, m_err, this);
    m_broadcast = new BroadcastGate(m_bus, m_registry, m_err, this);
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
                      tr("The line (required): a serial port (its /dev/serial/by-id name, which 'jumoctl ports' lists, "
                         "or /dev/ttyUSB0, say), tcp://HOST[:PORT] for a Modbus TCP gateway (port 502 by default; the "
                         "device address is the unit id) or rtu+tcp://HOST:PORT for raw RTU through a serial device "
                         "server."),
                      tr("address")});
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
                      tr("Never write to the line (control-room mode; the system configuration can set it for "
                         "everyone).")});
    parser.addOption({QStringLiteral("verbose"),
                      tr("Show Qt's Modbus messages (CRC errors, timeouts, frames) on stderr.")});
}

std::optional<int> LineCommands::openLine(CommandParser &parser)
{
    BusSettings settings;
    settings.portName = parser.value(QStringLiteral("port"));
    if (settings.portName.isEmpty()) {
        m_err << tr("--port is required") << Qt::endl;
        return 2;
    }
    QString addressError;
    const std::optional<LineAddress> address = LineAddress::parse(settings.portName, &addressError);
    if (!address) {
        m_err << addressError << Qt::endl;
        return 2;
    }
    // A path is a path: Qt would put /dev/ in front of a relative one ("line/master").
    if (!address->isNetwork() && settings.portName.contains(QLatin1Char('/'))
        && !settings.portName.startsWith(QLatin1Char('/')))
        settings.portName = QFileInfo(settings.portName).absoluteFilePath();
    bool ok = false;
    const int baud = parser.value(QStringLiteral("baud")).toInt(&ok);
    const std::optional<LineFormat> format = LineFormat::parse(ok ? baud : 0, parser.value(QStringLiteral("format")));
    if (!format) {
        m_err << tr("unsupported baud rate or data format: %1 %2")
                         .arg(parser.value(QStringLiteral("baud")), parser.value(QStringLiteral("format")))
              << Qt::endl;
        return 2;
    }
    settings.format = *format;
    if (parser.isSet(QStringLiteral("timeout"))) {
        settings.timeoutMs = parser.value(QStringLiteral("timeout")).toInt(&ok);
        if (!ok || settings.timeoutMs < 10 || settings.timeoutMs > 60000) {
            m_err << tr("--timeout must be 10..60000 ms") << Qt::endl;
            return 2;
        }
    }
    settings.minimumResponseTimeMs = parser.value(QStringLiteral("min-response")).toInt(&ok);
    if (!ok || settings.minimumResponseTimeMs < 0 || settings.minimumResponseTimeMs > 500) {
        m_err << tr("--min-response must be 0..500 ms") << Qt::endl;
        return 2;
    }
    settings.retries = parser.value(QStringLiteral("retries")).toInt(&ok);
    if (!ok || settings.retries < 0 || settings.retries > 10) {
        m_err << tr("--retries must be 0..10") << Qt::endl;
        return 2;
    }
    showModbusLogging(parser.isSet(QStringLiteral("verbose")));
    // As in the HMI: the system configuration can make every tool read-only.
    settings.readOnly = parser.isSet(QStringLiteral("read-only")) || SystemSettings::readOnly();
    m_identity->configure(parser);
    m_bus.setSettings(settings);
    if (!m_bus.open()) {
        m_err << m_bus.lastError() << Qt::endl;
        return 1;
    }
    connect(&m_bus, &Bus::lineError, this, [this](const QString &message) {
        m_err << message << Qt::endl;
        m_failed = true;
        finish(1);
    });
    return std::nullopt;
}

bool LineCommands::isDeviceName(const QString &text)
{
    static const QRegularExpression pattern(QRegularExpression::anchoredPattern(QStringLiteral("[a-z][a-z0-9_]*@[0-9]{1,3}")));
    return pattern.match(text).hasMatch();
}

bool LineCommands::parseDevice(const QString &text, Target &target)
{
    const QString family = text.section(QLatin1Char('@'), 0, 0);
    bool ok = false;
    const int address = text.section(QLatin1Char('@'), 1).toInt(&ok);
    target.map = m_registry.family(family);
    if (!target.map || !ok || !isDeviceName(text)) {
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
    m_interruptCode = signal == SIGTERM ? exitcode::Terminated : exitcode::Interrupted;
    m_interruptSummary = progressSummary();
    // Jobs stop asking; closing the line drops what has not gone out, and a write under
    // way ends as unknown. Their outcomes (and audit records) arrive from the event loop:
    // the command ends right after them.
    m_identity->cancel();
    m_broadcast->cancel();
    if (m_scanner)
        m_scanner->cancel();
    m_bus.close();
    QMetaObject::invokeMethod(this, [this] { finish(m_interruptCode); }, Qt::QueuedConnection);
}

QString LineCommands::progressSummary() const
{
    if (m_command == QLatin1String("scan"))
        return tr("%n device(s) found before the scan stopped", nullptr, int(m_targets.size()));
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

void LineCommands::finish(int code)
{
    if (m_finished)
        return;
    m_finished = true;
    if (m_interruptCode) {
        code = m_interruptCode;
        m_err << '\n'   // after a prompt or a progress line
              << (code == exitcode::Terminated ? tr("terminated: %1") : tr("interrupted: %1")).arg(m_interruptSummary)
              << Qt::endl;
    }
    if (m_auditFailed && code == exitcode::Ok)
        code = exitcode::Failed;
    m_out.flush();
    m_err.flush();
    m_bus.close();
    emit finished(code);
}

std::optional<int> LineCommands::scan(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("scan"), tr("Finds devices on the line and names their family."));
    addLineOptions(parser, false);
    parser.addOption({QStringLiteral("from"), tr("First address (default 1)."), tr("address"), QStringLiteral("1")});
    parser.addOption({QStringLiteral("to"), tr("Last address (default 247)."), tr("address"), QStringLiteral("247")});
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 0, 0))
        return stop;
    bool okFrom = false;
    bool okTo = false;
    const int from = parser.value(QStringLiteral("from")).toInt(&okFrom);
    const int to = parser.value(QStringLiteral("to")).toInt(&okTo);
    if (!okFrom || !okTo || from < 1 || to > 255 || from > to) {
        m_err << tr("--from and --to must be addresses 1..255, from <= to") << Qt::endl;
        return 2;
    }
    if (const auto stop = openLine(parser))
        return stop;
    m_scanner = std::make_unique<DeviceScanner>(m_bus, m_registry.families());
    connect(m_scanner.get(), &DeviceScanner::progress, this, [this](int address, int done, int total) {
        m_err << '\r' << tr("scanning address %1 (%2 of %3)").arg(address).arg(done + 1).arg(total) << Qt::flush;
    });
    connect(m_scanner.get(), &DeviceScanner::found, this, [this](int address, std::shared_ptr<const RegisterMap> map) {
        m_err << '\r' << QString(40, QLatin1Char(' ')) << '\r';
        if (address == map->protocol.alwaysAnswersAddress) {
            // Every device of the family answers there, whatever its own address.
            m_err << tr("address %1 answers as %2, which every %2 does whatever its own address: not listed")
                             .arg(address)
                             .arg(map->family)
                  << Qt::endl;
            return;
        }
        m_out << deviceName(*map, quint8(address)) << '\t' << map->name << Qt::endl;
        m_targets << Target{map, quint8(address), 0, 0};
    });
    connect(m_scanner.get(), &DeviceScanner::unknownDevice, this, [this](int address) {
        m_err << '\r' << tr("address %1 answers, but matches no known family").arg(address) << Qt::endl;
    });
    connect(m_scanner.get(), &Job::finished, this, [this] {
        m_err << '\r' << tr("%n device(s) found", nullptr, int(m_targets.size())) << QString(20, QLatin1Char(' '))
              << Qt::endl;
        finish(m_targets.isEmpty() ? 1 : 0);
    });
    m_scanner->start(from, to);
    return std::nullopt;
}

void LineCommands::printValues(const Target &target, const QStringList &ids)
{
    if (m_json) {
        QJsonArray array;
        for (const QString &id : ids) {
            const RegisterEntry *e = target.map->entry(id);
            const EntryState *s = m_bus.entryState(target.id, id);
            if (isFailure(s))
                m_failed = true;
            array.append(QJsonObject{{"family", target.map->family},
                                     {"address", int(target.address)},
                                     {"id", id},
                                     {"label", e->label},
                                     {"register", formatAddress(e->address)},
                                     {"value", s ? jsonValue(*s) : QJsonValue()},
                                     {"unit", e->unit},
                                     {"status", s ? s->statusName() : QStringLiteral("timeout")}});
        }
        m_out << QJsonDocument(array).toJson(QJsonDocument::Indented);
        return;
    }
    for (const QString &id : ids) {
        const RegisterEntry *e = target.map->entry(id);
        const EntryState *s = m_bus.entryState(target.id, id);
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
        m_out << formatAddress(e->address) << "  " << id << " = " << shown << "  [" << (s ? s->statusName() : QStringLiteral("timeout"))
              << ']' << Qt::endl;
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
    parser.addPositionalArgument(QStringLiteral("device"), tr("FAMILY@ADDRESS, e.g. ipc300@1."));
    if (!dump)
        parser.addPositionalArgument(QStringLiteral("id"), tr("Entry ids."), QStringLiteral("id..."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, dump ? 1 : 2, dump ? 1 : -1))
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
    if (const auto stop = openLine(parser))
        return stop;
    m_targets = {target};
    m_ids = ids;
    m_identity->pass(claims(), [this, dump] { readOnce(dump); }, [this](int code) { finish(code); },
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
    m_bus.setPolling(false);
    target.id = m_bus.addDevice(target.map, target.address);
    m_bus.setPollEntries(target.id, dump ? QStringList() : m_ids);
    connect(&m_bus, &Bus::pollCycleFinished, this, [this](DeviceId id, double) {
        if (id != m_targets.first().id)
            return;
        printValues(m_targets.first(), m_ids);
        if (m_failed)
            m_err << tr("some entries could not be read") << Qt::endl;
        finish(m_failed ? 1 : 0);
    });
    m_bus.requestCycle(target.id);
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
    parser.addPositionalArgument(QStringLiteral("device"), tr("FAMILY@ADDRESS, or FAMILY@0 for a broadcast."));
    parser.addPositionalArgument(QStringLiteral("assignment"),
                                 tr("ID=VALUE, e.g. input_setpoint=42.5, or ID.BIT=0|1, e.g. "
                                    "binary_signal_write.digital_output=1."),
                                 QStringLiteral("id=value|id.bit=0|1..."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 2))
        return stop;
    QStringList args = parser.positionalArguments();
    const QString deviceText = args.takeFirst();
    Target target;
    const bool broadcast = deviceText.endsWith(QLatin1String("@0"));
    if (broadcast) {
        target.map = m_registry.family(deviceText.chopped(2));
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
    m_assignments = *assignments;
    if (broadcast) {
        if (const auto stop = m_broadcast->configure(parser, target.map, verifyAddresses))
            return stop;
    }
    if (const QString note = readOnlyNote(parser); !note.isEmpty())
        m_err << note << Qt::endl;
    if (const auto stop = openLine(parser))
        return stop;
    m_identity->recordSkipsIn(m_audit);
    if (broadcast)
        m_broadcast->pass(
                *m_identity, m_audit,
                [this, target](const QList<quint8> &readBack) { startWrites(target, true, readBack); },
                [this](int code) { finish(code); });
    else
        m_identity->pass({{target.address, target.map}}, [this, target] { startWrites(target, false, {}); },
                         [this](int code) { finish(code); });
    return std::nullopt;
}

void LineCommands::startWrites(Target target, bool broadcast, const QList<quint8> &verifyAddresses)
{
    m_writesAsked = int(m_assignments.size());
    m_bus.setPolling(false);
    if (broadcast) {
        // The bus reads a broadcast back from every device of the family it knows.
        for (quint8 address : std::as_const(verifyAddresses))
            m_bus.addDevice(target.map, address);
        target.address = 0;
    } else {
        target.id = m_bus.addDevice(target.map, target.address);
    }
    m_targets = {target};
    connect(&m_bus, &Bus::writeFinished, this, [this](int ticket, const WriteOutcome &outcome) {
        if (ticket != m_writeTicket)
            return;
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
    m_bus.setPollEntries(target.id, readable);
    connect(&m_bus, &Bus::pollCycleFinished, this, [this](DeviceId, double) { writeNext(); },
            Qt::SingleShotConnection);
    m_bus.requestCycle(target.id);
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
    const EntryState *old = m_targets.first().address ? m_bus.entryState(m_targets.first().id, id) : nullptr;
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
    if (m_interruptCode)
        return;
    if (m_assignments.isEmpty()) {
        // An unknown outcome outweighs a failure: the device has to be looked at.
        finish(m_uncertain ? exitcode::Uncertain : m_failed ? 1 : 0);
        return;
    }
    const Target &target = m_targets.first();
    const WriteAssignment &next = m_assignments.first();
    if (next.isBitChange())
        m_writeTicket = m_bus.writeBits(target.id, next.entryId, next.bits);
    else
        m_writeTicket = target.address == 0 ? m_bus.writeBroadcast(target.map->family, next.entryId, next.value)
                                            : m_bus.write(target.id, next.entryId, next.value);
}

QString LineCommands::readOnlyNote(const CommandParser &parser) const
{
    if (SystemSettings::readOnly())
        return tr("read-only mode is set by the system configuration (%1): nothing is written to the devices")
                .arg(SystemSettings::fileName());
    if (parser.isSet(QStringLiteral("read-only")))
        return tr("read-only mode (--read-only): nothing is written to the devices");
    return {};
}

std::optional<int> LineCommands::monitor(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("monitor"), tr("Polls devices continuously and prints every poll cycle."));
    addLineOptions(parser);
    parser.addOption({QStringLiteral("interval"), tr("Poll interval per device in ms (default 0: as fast as the line allows)."),
                      tr("ms"), QStringLiteral("0")});
    parser.addOption({QStringLiteral("cycles"), tr("Stop after this many cycles of every device (default: run until stopped)."),
                      tr("n"), QStringLiteral("0")});
    parser.addOption({QStringLiteral("ids"), tr("Comma-separated entry ids to poll (default: all readable entries)."),
                      tr("ids")});
    parser.addOption({QStringLiteral("jsonl"), tr("One JSON object per completed poll cycle of a device.")});
    parser.addOption({QStringLiteral("csv"), tr("CSV rows: time,device,id,value,unit,status.")});
    parser.addPositionalArgument(QStringLiteral("device"), tr("FAMILY@ADDRESS."), QStringLiteral("device..."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 1))
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
    const QStringList ids = parser.value(QStringLiteral("ids")).split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString &text : parser.positionalArguments()) {
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
    }
    if (const auto stop = openLine(parser))
        return stop;
    m_identity->pass(claims(), [this, ids, interval] { startMonitor(ids, interval); }, [this](int code) { finish(code); });
    return std::nullopt;
}

void LineCommands::startMonitor(const QStringList &ids, int interval)
{
    if (m_csv)
        m_out << "time,device,id,value,unit,status" << Qt::endl;
    for (Target &target : m_targets) {
        target.id = m_bus.addDevice(target.map, target.address);
        m_bus.setPollEntries(target.id, ids);
        m_bus.setPollInterval(target.id, interval);
    }
    connect(&m_bus, &Bus::pollCycleFinished, this, [this, ids](DeviceId id, double cycleMs) {
        auto target = std::find_if(m_targets.begin(), m_targets.end(), [id](const Target &t) { return t.id == id; });
        if (target == m_targets.end())
            return;
        QStringList entryIds = ids;
        if (entryIds.isEmpty()) {
            for (const RegisterEntry &e : target->map->entries()) {
                if (e.isReadable() && e.alias.isEmpty())
                    entryIds << e.id;
            }
        }
        const QString time = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
        const QString device = deviceName(*target->map, target->address);
        if (m_json) {
            QJsonObject values;
            QJsonObject status;
            for (const QString &e : std::as_const(entryIds)) {
                const EntryState *s = m_bus.entryState(id, e);
                values.insert(e, s ? jsonValue(*s) : QJsonValue());
                status.insert(e, s ? s->statusName() : QStringLiteral("timeout"));
                m_failed |= isFailure(s);
            }
            m_out << QJsonDocument(QJsonObject{{"time", time}, {"device", device}, {"cycle_ms", cycleMs},
                                               {"values", values}, {"status", status}})
                             .toJson(QJsonDocument::Compact)
                  << Qt::endl;
        } else {
            for (const QString &e : std::as_const(entryIds)) {
                const EntryState *s = m_bus.entryState(id, e);
                const RegisterEntry *entry = target->map->entry(e);
                const QString value = csvField(s && s->isCurrent() && s->value.isOk() ? s->value.display : QString());
                m_out << time << ',' << device << ',' << e << ',' << value << ',' << entry->unit << ','
                      << (s ? s->statusName() : QStringLiteral("timeout")) << '\n';
                m_failed |= isFailure(s);
            }
            m_out.flush();
        }
        // Polling on into output that goes nowhere would only hide the failure.
        const auto *output = qobject_cast<const QFileDevice *>(m_out.device());
        if (m_out.status() == QTextStream::WriteFailed || (output && output->error() != QFileDevice::NoError)) {
            finish(exitcode::Failed);
            return;
        }
        ++target->cycles;
        if (m_cyclesWanted > 0
            && std::all_of(m_targets.cbegin(), m_targets.cend(), [this](const Target &t) { return t.cycles >= m_cyclesWanted; }))
            finish(m_failed ? 1 : 0);
    });
}

void LineCommands::readParameters(const std::function<void(const ParameterSet &, const QStringList &)> &done)
{
    m_identity->pass(claims(), [this, done] { readParametersNow(done); }, [this](int code) { finish(code); });
}

void LineCommands::readParametersNow(const std::function<void(const ParameterSet &, const QStringList &)> &done)
{
    Target &target = m_targets.first();
    QStringList ids = ParameterSet::parameterIds(*target.map) + target.map->identity;
    if (target.map->entry(QStringLiteral("software_version")))
        ids << QStringLiteral("software_version");
    ids.removeDuplicates();
    m_bus.setPolling(false);
    target.id = m_bus.addDevice(target.map, target.address);
    m_bus.setPollEntries(target.id, ids);
    auto *transfer = new ParameterTransfer(&m_bus, target.id, this);
    connect(transfer, &ParameterTransfer::readFinished, this,
            [this, done](const ParameterSet &set, const QStringList &failed) {
                QStringList reasons;
                for (const QString &id : failed) {
                    const EntryState *s = m_bus.entryState(m_targets.first().id, id);
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
                                            : tr("Compares a device with a parameter file, or two files."));
    addLineOptions(parser);
    if (restore)
        parser.addOption({QStringLiteral("yes"), tr("Write without asking.")});
    parser.addPositionalArgument(QStringLiteral("device"), command == QLatin1String("diff")
                                                                   ? tr("FAMILY@ADDRESS, or a first parameter file.")
                                                                   : tr("FAMILY@ADDRESS, e.g. ipc300@1."));
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

    Target target;
    if (!parseDevice(first, target))
        return 2;
    std::optional<ParameterSet> file;
    if (!backup) {
        file = load(path);
        if (!file)
            return 2;
        if (file->family != target.map->family) {
            m_err << tr("refused: %1").arg(file->incompatibility(*target.map, QString())) << Qt::endl;
            return 1;
        }
    }
    if (const QString note = restore ? readOnlyNote(parser) : QString(); !note.isEmpty()) {
        m_err << note << Qt::endl << tr("read-only mode: nothing would be restored") << Qt::endl;
        return 1;
    }
    if (const auto stop = openLine(parser))
        return stop;
    m_targets = {target};
    if (restore)
        m_identity->recordSkipsIn(m_audit);
    const bool yes = restore && parser.isSet(QStringLiteral("yes"));
    readParameters([this, backup, restore, path, file, yes, first](const ParameterSet &device, const QStringList &failed) {
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
            finish(1);
            return;
        }
        const QList<ParameterDifference> shown = device.differences(*file, map);
        printDifferences(shown, first, path);
        if (!restore) {
            finish(shown.isEmpty() ? 0 : 1);
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
    connect(&m_bus, &Bus::writeFinished, this, [this](int ticket, const WriteOutcome &outcome) {
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
    parser.addPositionalArgument(QStringLiteral("device"), tr("FAMILY@ADDRESS, e.g. ipc300@1."));
    parser.addPositionalArgument(QStringLiteral("file"), tr("Report file (.pdf or .html)."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 2, 2))
        return stop;
    Target target;
    if (!parseDevice(parser.positionalArguments().at(0), target))
        return 2;
    if (const auto stop = openLine(parser))
        return stop;
    const QString path = parser.positionalArguments().at(1);
    const ReportTitle title{parser.value(QStringLiteral("site")), parser.value(QStringLiteral("cabinet")),
                            parser.value(QStringLiteral("tag")), parser.value(QStringLiteral("engineer"))};
    m_targets = {target};
    m_identity->pass(claims(), [this, path, title] { startReport(path, title); }, [this](int code) { finish(code); });
    return std::nullopt;
}

void LineCommands::startReport(const QString &path, const ReportTitle &title)
{
    Target &target = m_targets.first();
    m_bus.setPolling(false);
    target.id = m_bus.addDevice(target.map, target.address);
    connect(&m_bus, &Bus::pollCycleFinished, this, [this, path, title](DeviceId id, double) {
        const Target &t = m_targets.first();
        if (id != t.id)
            return;
        const DeviceStatistics *stats = m_bus.statistics(id);
        if (stats->responses == 0) {
            m_err << tr("%1 did not answer: no report written").arg(deviceName(*t.map, t.address)) << Qt::endl;
            finish(1);
            return;
        }
        CommissioningReport report(*t.map, t.address, [this, id](const QString &entry) { return m_bus.entryState(id, entry); });
        // The command line has no session: its writes of today stand in for one.
        // Read back from the newest to the first record before today, so that a large
        // log costs no more than its recent part.
        EventLogReader audit(EventLog::defaultFolder() + QStringLiteral("/write-audit.jsonl"));
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
        report.setLine(m_bus.settings());
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
    m_bus.requestCycle(target.id);
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
    if (m_interruptCode)
        return;
    if (m_pendingWrites.isEmpty()) {
        m_out << tr("%n parameter(s) restored and verified", nullptr, m_restored) << Qt::endl;
        finish(m_failed ? 1 : 0);
        return;
    }
    m_writeTicket = m_bus.write(m_targets.first().id, m_pendingWrites.first().first, m_pendingWrites.first().second);
}

} // namespace jumo
