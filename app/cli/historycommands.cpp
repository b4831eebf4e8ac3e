#include "historycommands.h"

#include "bus/stationconfig.h"
#include "commandparser.h"
#include "exitcodes.h"
#include "history/historyreader.h"
#include "historyjsonwriter.h"
#include "logs/eventlog.h"
#include "protocol/csv.h"
#include "protocol/familyregistry.h"
#include "protocol/localtime.h"
#include "protocol/printable.h"
#include "protocol/valuecodec.h"
#include "quitonsignal.h"

#include <QJsonObject>
#include <QRegularExpression>
#include <QSet>

#include <cmath>
#include <csignal>

namespace jumo {

namespace {

QString isoTime(qint64 ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs);
}

// For text and CSV: a device text's control characters as \xHH (JSON escapes its own).
QString valueText(const HistoryPoint &p, double number)
{
    if (!p.text.isEmpty())
        return printable(p.text);
    return std::isnan(number) ? QString() : ValueCodec::formatFloat(number);
}

QJsonValue jsonNumber(double number)
{
    return std::isnan(number) ? QJsonValue() : QJsonValue(number);
}

// Whether the device text names this device: "ipc300@1", "line1/ipc300@1" or
// "hall-3/line1/ipc300@1".
bool names(const HistoryKey &key, const QString &device)
{
    return key.device == device || key.line + QLatin1Char('/') + key.device == device || key.name() == device;
}

} // namespace

HistoryCommands::HistoryCommands(const FamilyRegistry &registry, QTextStream &out, QTextStream &err)
    : m_registry(registry), m_out(out), m_err(err)
{
}

std::optional<QDateTime> HistoryCommands::parseTime(const QString &text, const QDateTime &now, QString *error,
                                                    QString *note)
{
    if (text == QLatin1String("now"))
        return now;
    static const QRegularExpression relative(QStringLiteral("^-(\\d{1,9})([smhd])$"));
    if (const QRegularExpressionMatch m = relative.match(text); m.hasMatch()) {
        const qint64 count = m.captured(1).toLongLong();
        const QChar unit = m.captured(2).at(0);
        const qint64 seconds = unit == QLatin1Char('s') ? 1 : unit == QLatin1Char('m') ? 60 : unit == QLatin1Char('h') ? 3600 : 86400;
        return now.addSecs(-count * seconds);
    }
    const QDateTime parsed = QDateTime::fromString(text, Qt::ISODateWithMs);
    if (parsed.isValid() && parsed.timeSpec() != Qt::LocalTime)
        return parsed;   // it names its offset or Z
    // A local time: its fields (read as if UTC, so that a time the clocks skip is still
    // read), then the instants the local clocks showed them.
    QDateTime fields = QDateTime::fromString(text + QLatin1Char('Z'), Qt::ISODateWithMs);
    if (!fields.isValid()) {
        const QDate date = QDate::fromString(text, Qt::ISODate);
        if (date.isValid())
            fields = QDateTime(date, QTime(0, 0), Qt::UTC);
    }
    if (!fields.isValid()) {
        if (error)
            *error = tr("'%1' is no time").arg(text);
        return std::nullopt;
    }
    const QTimeZone zone = QTimeZone::systemTimeZone();
    const QList<QDateTime> instants = LocalTime::instants(fields.date(), fields.time(), zone);
    if (instants.isEmpty()) {
        const int before = zone.offsetFromUtc(fields.addDays(-1));
        if (error)
            *error = tr("%1 does not exist in local time (%2): the clocks skip it; give it with its offset, such as "
                        "%3, or in UTC, such as %4")
                             .arg(text, QString::fromUtf8(zone.id()), text + LocalTime::offsetText(before),
                                  fields.addSecs(-before).toString(Qt::ISODate));
        return std::nullopt;
    }
    if (instants.size() > 1 && note) {
        *note = tr("%1 is twice in local time (%2), the clocks go back: taken as the first, %3; the second is %4")
                        .arg(text, QString::fromUtf8(zone.id()),
                             text + LocalTime::offsetText(int(instants.first().secsTo(fields))),
                             text + LocalTime::offsetText(int(instants.last().secsTo(fields))));
    }
    return instants.first();
}

QString HistoryCommands::signalSummary(int signal, const QString &done)
{
    return tr("jumoctl history: %1").arg(jumo::signalSummary(signal, done));
}

int HistoryCommands::history(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("history"),
                         tr("Prints the recorded values of a device's entries from FROM to TO with their state and "
                            "validity: every sample kept, and one-minute rows (minimum, mean, maximum) where the "
                            "samples are thinned out. Reads the station's history (--station FILE: its file in the "
                            "log folder) or the database given by --db; no line is opened."));
    parser.addOption({QStringLiteral("station"), tr("The station file whose history is read."), tr("FILE")});
    parser.addOption({QStringLiteral("db"),
                      tr("The history: an SQLite file, or postgresql://[USER@]HOST[:PORT]/DATABASE (the password "
                         "from JUMO_HISTORY_PASSWORD or ~/.pgpass)."),
                      tr("URL")});
    parser.addOption({QStringLiteral("from"),
                      tr("Start: an ISO 8601 time (local unless it names its offset), 'now', or a time before now "
                         "such as -90s, -15m, -2h, -7d. Default: -1h. A local time the clocks skip is refused; of one "
                         "they show twice, the first is taken."),
                      tr("TIME"), QStringLiteral("-1h")});
    parser.addOption({QStringLiteral("to"), tr("End, as --from. Default: now."), tr("TIME"), QStringLiteral("now")});
    parser.addOption({QStringLiteral("csv"), tr("CSV: time,device,entry,value,unit,state,validity,resolution,"
                                                "minimum,mean,maximum.")});
    parser.addOption({QStringLiteral("json"), tr("One JSON document: the device, the span and each entry's records.")});
    parser.addPositionalArgument(QStringLiteral("device"),
                                 tr("The device: FAMILY@ADDRESS, LINE/FAMILY@ADDRESS or STATION/LINE/FAMILY@ADDRESS."));
    parser.addPositionalArgument(QStringLiteral("entry"), tr("Entries to print."), QStringLiteral("ENTRY..."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 2))
        return *stop;
    auto usage = [this](const QString &message) {
        m_err << tr("jumoctl history: %1").arg(message) << Qt::endl;
        return exitcode::Usage;
    };
    const bool csv = parser.isSet(QStringLiteral("csv"));
    const bool json = parser.isSet(QStringLiteral("json"));
    if (csv && json)
        return usage(tr("give at most one of --csv and --json"));
    if (parser.isSet(QStringLiteral("station")) == parser.isSet(QStringLiteral("db")))
        return usage(tr("give exactly one of --station FILE and --db URL"));

    const QDateTime now = QDateTime::currentDateTimeUtc();
    QString timeError;
    QString fromNote;
    QString toNote;
    const std::optional<QDateTime> from = parseTime(parser.value(QStringLiteral("from")), now, &timeError, &fromNote);
    if (!from)
        return usage(QStringLiteral("--from: ") + timeError);
    const std::optional<QDateTime> to = parseTime(parser.value(QStringLiteral("to")), now, &timeError, &toNote);
    if (!to)
        return usage(QStringLiteral("--to: ") + timeError);
    if (!fromNote.isEmpty())
        m_err << tr("jumoctl history: %1").arg(QStringLiteral("--from: ") + fromNote) << Qt::endl;
    if (!toNote.isEmpty())
        m_err << tr("jumoctl history: %1").arg(QStringLiteral("--to: ") + toNote) << Qt::endl;
    if (*to <= *from)
        return usage(tr("--to must be after --from"));

    HistoryLocation location;
    QString station;
    QString error;
    if (parser.isSet(QStringLiteral("station"))) {
        const std::optional<StationConfig> config = StationConfig::load(parser.value(QStringLiteral("station")), m_registry, &error);
        if (!config) {
            m_err << error << Qt::endl;
            return exitcode::Usage;
        }
        const QString folder = EventLog::defaultFolder(&error);
        if (folder.isEmpty()) {
            m_err << tr("jumoctl history: no log folder to find the history in: %1").arg(error) << Qt::endl;
            return exitcode::Failed;
        }
        station = config->name;
        location = HistoryLocation::file(HistoryLocation::defaultFile(folder, station));
    } else {
        const std::optional<HistoryLocation> parsed =
                HistoryLocation::fromOptions({parser.value(QStringLiteral("db")), {}, {}}, &error);
        if (!parsed)
            return usage(error);
        location = *parsed;
    }

    // A station's live history, or a copy: jumoctl leaves no file beside it.
    HistoryReader reader(location, HistoryDatabase::ReadAccess::FromOutside);
    // A file that is no history of ours, or a damaged one, is a wrong input (2); a history
    // that cannot be reached or read now is a failure (1).
    auto readFailed = [&] {
        m_out.flush();
        m_err << tr("jumoctl history: %1").arg(error) << Qt::endl;
        const HistoryDatabase::Fault fault = reader.fault();
        return fault == HistoryDatabase::Fault::NotAHistory || fault == HistoryDatabase::Fault::Damaged
                ? exitcode::Usage
                : exitcode::Failed;
    };
    std::optional<QList<HistorySeriesInfo>> series;
    {
        // Qt's connect to PostgreSQL (up to its 10 s timeout) and SQLite's wait for a lock
        // block and cannot be interrupted; nothing is read yet, so a signal ends it at once.
        const EndAtOnceOnSignals endAtOnce([&](int signal) {
            return signalSummary(signal, tr("nothing was read (opening %1)").arg(location.display()));
        });
        if (!reader.open(&error))
            return readFailed();
        series = reader.series(station, &error);
    }
    if (!series)
        return readFailed();
    const QString device = parser.positionalArguments().constFirst();
    QList<HistoryKey> keys;
    QSet<QString> devices;
    for (const HistorySeriesInfo &info : *series) {
        devices.insert(info.key.name());
        if (names(info.key, device) && !keys.contains(info.key))
            keys.append(info.key);
    }
    if (keys.isEmpty()) {
        QStringList recorded = devices.values();
        recorded.sort();
        m_err << tr("jumoctl history: nothing of %1 is recorded in %2").arg(device, location.display()) << Qt::endl;
        if (!recorded.isEmpty())
            m_err << tr("recorded devices: %1").arg(recorded.join(QStringLiteral(", "))) << Qt::endl;
        return exitcode::Failed;
    }
    if (keys.size() > 1) {
        QStringList named;
        for (const HistoryKey &k : std::as_const(keys))
            named << k.name();
        return usage(tr("%1 names several devices: %2").arg(device, named.join(QStringLiteral(", "))));
    }
    const HistoryKey key = keys.constFirst();
    const QStringList entries = parser.positionalArguments().mid(1);
    QHash<QString, HistorySeriesInfo> infos;
    for (const HistorySeriesInfo &info : *series) {
        if (info.key == key)
            infos.insert(info.entry, info);
    }
    for (const QString &entry : entries) {
        if (!infos.contains(entry)) {
            QStringList recorded = infos.keys();
            recorded.sort();
            return usage(tr("%1 is not recorded for %2 (recorded: %3)")
                                 .arg(entry, key.name(), recorded.join(QStringLiteral(", "))));
        }
    }

    const qint64 fromMs = from->toMSecsSinceEpoch();
    const qint64 toMs = to->toMSecsSinceEpoch();
    if (csv)
        m_out << "time,device,entry,value,unit,state,validity,resolution,minimum,mean,maximum\n";
    // JSON as it is read, like the others: a long history never waits whole in memory.
    HistoryJsonWriter jsonWriter(m_out);
    int printed = 0;
    if (json)
        jsonWriter.begin(key.name(), isoTime(fromMs), isoTime(toMs));
    for (const QString &entry : entries) {
        const QString unit = infos.value(entry).unit;
        if (json)
            jsonWriter.beginEntry(entry, unit);
        int unknownStates = 0;
        const bool ok = reader.records(
                key, entry, fromMs, toMs,
                [&](const HistoryRecord &r) {
                    // A signal stops it before the next record (the loop is not running).
                    if (pendingTerminationSignal() != 0)
                        return false;
                    ++printed;
                    const HistoryPoint &p = r.point;
                    unknownStates += p.state == SampleState::UnknownState;
                    const QString resolution = r.minute ? QStringLiteral("minute") : QStringLiteral("raw");
                    if (json) {
                        QJsonObject o{{"time", isoTime(p.timeMs)},
                                      {"state", sampleStateName(p.state)},
                                      {"validity", sampleValidityName(p.state)},
                                      {"resolution", resolution}};
                        o.insert("value", p.text.isEmpty() ? jsonNumber(p.value) : QJsonValue(p.text));
                        if (r.minute) {
                            o.insert("minimum", jsonNumber(p.minimum));
                            o.insert("mean", jsonNumber(p.mean));
                            o.insert("maximum", jsonNumber(p.maximum));
                        }
                        jsonWriter.record(o);
                    } else if (csv) {
                        m_out << isoTime(p.timeMs) << ',' << csvField(key.name()) << ',' << csvField(entry) << ','
                              << csvField(valueText(p, p.value)) << ',' << csvField(printable(unit)) << ','
                              << sampleStateName(p.state) << ',' << sampleValidityName(p.state) << ',' << resolution
                              << ',' << (r.minute ? valueText(p, p.minimum) : QString()) << ','
                              << (r.minute ? valueText(p, p.mean) : QString()) << ','
                              << (r.minute ? valueText(p, p.maximum) : QString()) << '\n';
                    } else {
                        const QString value = valueText(p, p.value);
                        // With the offset: the hour the clocks repeat in autumn reads twice alike without it.
                        m_out << LocalTime::withOffset(p.timeMs) << "  " << entry << "  "
                              << (value.isEmpty()  ? QStringLiteral("-")
                                  : unit.isEmpty() ? value
                                                   : value + QLatin1Char(' ') + printable(unit))
                              << "  " << sampleStateName(p.state);
                        if (r.minute)
                            m_out << "  " << tr("(minute: %1 to %2, mean %3)")
                                                     .arg(valueText(p, p.minimum), valueText(p, p.maximum),
                                                          valueText(p, p.mean));
                        m_out << '\n';
                    }
                    return m_out.status() == QTextStream::Ok;
                },
                &error);
        if (!ok)
            return readFailed();
        if (const int signal = pendingTerminationSignal(); signal != 0) {
            m_out.flush();
            m_err << signalSummary(signal, tr("%n record(s) printed", nullptr, printed)) << Qt::endl;
            return 128 + signal;
        }
        if (unknownStates > 0) {
            // A newer version's state, or a hand-made file's: shown, never taken for ok.
            m_err << tr("jumoctl history: %1: %n record(s) with a state this version does not know, shown as "
                        "unknown_state (validity unknown)",
                        nullptr, unknownStates)
                             .arg(entry)
                  << Qt::endl;
        }
        if (json)
            jsonWriter.endEntry();
    }
    if (json)
        jsonWriter.end();
    m_out.flush();
    return exitcode::Ok;
}

} // namespace jumo
