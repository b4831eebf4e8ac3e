#include "stationcommands.h"

#include "bus/stationconfig.h"
#include "commandparser.h"
#include "exitcodes.h"
#include "protocol/familyregistry.h"

namespace jumo {

StationCommands::StationCommands(const FamilyRegistry &registry, QTextStream &out, QTextStream &err)
    : m_registry(registry), m_out(out), m_err(err)
{
}

int StationCommands::station(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("station"),
                         tr("Checks a station file and lists its lines and devices as the line commands take them "
                            "(--station FILE). Every problem is named with the line and the key; no line is opened."));
    parser.addOption({QStringLiteral("check"), tr("Only check: one line of summary when the file is good.")});
    parser.addOption({QStringLiteral("json"), tr("Print the station as its file would be written, every default "
                                                 "filled in.")});
    parser.addPositionalArgument(QStringLiteral("file"), tr("Station file (JSON)."));
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 1, 1))
        return *stop;
    const QString path = parser.positionalArguments().constFirst();
    QString error;
    const std::optional<StationConfig> station = StationConfig::load(path, m_registry, &error);
    if (!station) {
        m_err << error << Qt::endl;
        return exitcode::Usage;
    }
    const QString summary = tr("%n line(s)", nullptr, int(station->lines.size())) + QStringLiteral(", ")
            + tr("%n device(s)", nullptr, int(station->devices().size()));
    if (parser.isSet(QStringLiteral("check"))) {
        m_out << tr("%1: a good station file (%2)").arg(path, summary) << Qt::endl;
        return exitcode::Ok;
    }
    if (parser.isSet(QStringLiteral("json"))) {
        m_out << QString::fromUtf8(station->toJson());
        return exitcode::Ok;
    }
    m_out << tr("station %1: %2").arg(station->name, summary) << Qt::endl;
    for (qsizetype i = 0; i < station->lines.size(); ++i) {
        const LineConfig &line = station->lines[i];
        const BusSettings &s = line.settings;
        QStringList settings{QStringLiteral("%1 %2").arg(s.format.baudRate).arg(s.format.formatName())};
        settings << (s.timeoutMs > 0 ? tr("timeout %1 ms").arg(s.timeoutMs) : tr("timeout from the families"));
        if (s.minimumResponseTimeMs > 0)
            settings << tr("minimum response %1 ms").arg(s.minimumResponseTimeMs);
        settings << tr("%n retry(s)", nullptr, s.retries);
        if (s.readOnly)
            settings << tr("read-only");
        m_out << tr("line %1: %2 (%3)").arg(line.name, s.portName, settings.join(QStringLiteral(", "))) << Qt::endl;
        if (line.devices.isEmpty())
            m_out << "  " << tr("no devices listed") << Qt::endl;
        for (const DeviceSpec &device : line.devices)
            m_out << "  " << station->deviceName(i, device) << '\t' << m_registry.family(device.family)->name
                  << Qt::endl;
    }
    return exitcode::Ok;
}

} // namespace jumo
