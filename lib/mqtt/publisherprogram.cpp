#include "mqtt/publisherprogram.h"

#include "bus/bus.h"
#include "bus/pollselection.h"
#include "jumoversion.h"
#include "protocol/familyregistry.h"
#include "protocol/printable.h"

#include <QCommandLineParser>
#include <QFileInfo>
#include <QLoggingCategory>

#include <algorithm>

Q_DECLARE_LOGGING_CATEGORY(lcMqtt)

namespace jumo {

PublisherProgram::PublisherProgram(QTextStream &out, QTextStream &err, QObject *parent)
    : QObject(parent), m_out(out), m_err(err)
{
    m_retry.setInterval(5000);
    connect(&m_retry, &QTimer::timeout, this, &PublisherProgram::retryClosedLines);
}

PublisherProgram::~PublisherProgram()
{
    // The publisher holds connections to the buses: it goes first.
    m_publisher.reset();
}

std::optional<int> PublisherProgram::run(const QStringList &arguments)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
            tr("Publishes the devices of a station's lines to an MQTT broker: identity, values with their validity "
               "and status, alarm bits, line state. Owns the lines and only reads them."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption({QStringLiteral("broker"),
                      tr("Broker (required): mqtt://[USER@]HOST[:PORT], or mqtts://... for TLS (port 8883)."),
                      tr("url")});
    parser.addOption({QStringLiteral("name"), tr("The station's name in the topics (default: the host name)."),
                      tr("station")});
    parser.addOption({QStringLiteral("prefix"), tr("First topic level(s) (default jumo)."), tr("prefix"),
                      QStringLiteral("jumo")});
    parser.addOption({QStringLiteral("username"), tr("User name at the broker (instead of the one in --broker)."),
                      tr("user")});
    parser.addOption({QStringLiteral("password-file"),
                      tr("File whose first line is the broker password (else JUMO_MQTT_PASSWORD; never on the "
                         "command line, where every user could read it)."),
                      tr("file")});
    parser.addOption({QStringLiteral("tls-ca"), tr("TLS: the CA certificate that signed the broker's (default: the "
                                                   "system's)."),
                      tr("file")});
    parser.addOption({QStringLiteral("tls-cert"), tr("TLS: a client certificate (with --tls-key)."), tr("file")});
    parser.addOption({QStringLiteral("tls-key"), tr("TLS: the client certificate's key."), tr("file")});
    parser.addOption({QStringLiteral("station"),
                      tr("Station file (JSON: its name, lines and devices; see README, 'Station files')."), tr("file")});
    parser.addOption({QStringLiteral("line"),
                      tr("A line: ADDRESS[,name=NAME][,baud=N][,format=8N1][,timeout=MS][,min-response=MS][,retries=N] "
                         "(repeat for more lines)."),
                      tr("spec")});
    parser.addOption({QStringLiteral("port"), tr("Serial port of a station of one line (instead of --line)."),
                      tr("path")});
    parser.addOption({QStringLiteral("baud"),
                      tr("Baud rate of --port and of --line specs without one: 4800, 9600, 19200 or 38400 (default 9600)."),
                      tr("rate"),
                      QStringLiteral("9600")});
    parser.addOption({QStringLiteral("format"), tr("Data format: 8N1, 8E1, 8O1 or 8N2 (default 8N1)."), tr("format"),
                      QStringLiteral("8N1")});
    parser.addOption({QStringLiteral("retries"), tr("Retries after a lost reply (default 2)."), tr("n"),
                      QStringLiteral("2")});
    parser.addOption({QStringLiteral("device"),
                      tr("A device, FAMILY@ADDRESS, or LINE/FAMILY@ADDRESS with several lines (repeat for more)."),
                      tr("device")});
    parser.addOption({QStringLiteral("poll"),
                      tr("What the devices of a family poll and publish, instead of every readable entry: "
                         "FAMILY:ENTRY[,ENTRY...], where 'faceplate' stands for what the overview faceplate shows "
                         "and 'alarms' for every bit field with alarm bits (repeat for more families)."),
                      tr("family:entries")});
    parser.addOption({QStringLiteral("heartbeat"), tr("Heartbeat interval in ms (default 1000)."), tr("ms"),
                      QStringLiteral("1000")});
    parser.addOption({QStringLiteral("take-over"),
                      tr("Start even when a station of this name is online at the broker: that publisher stops "
                         "(without it, this one refuses to start, exit code 2).")});

    QStringList withProgram = arguments;
    withProgram.prepend(QStringLiteral("jumo-publisher"));
    if (!parser.parse(withProgram)) {
        m_err << parser.errorText() << Qt::endl;
        return 2;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        m_out << parser.helpText();
        return 0;
    }
    if (parser.isSet(QStringLiteral("version"))) {
        m_out << "jumo-publisher " << JUMO_VERSION << Qt::endl;
        return 0;
    }
    if (!parser.positionalArguments().isEmpty()) {
        m_err << tr("unexpected argument '%1'").arg(parser.positionalArguments().constFirst()) << Qt::endl;
        return 2;
    }

    // The broker.
    if (!parser.isSet(QStringLiteral("broker"))) {
        m_err << tr("--broker is required, e.g. --broker mqtt://localhost") << Qt::endl;
        return 2;
    }
    QString error;
    const std::optional<MqttSettings> broker = MqttSettings::fromOptions(
            {parser.value(QStringLiteral("broker")), parser.value(QStringLiteral("username")),
             parser.value(QStringLiteral("password-file")), parser.value(QStringLiteral("tls-ca")),
             parser.value(QStringLiteral("tls-cert")), parser.value(QStringLiteral("tls-key"))},
            &error);
    if (!broker) {
        m_err << error << Qt::endl;
        return 2;
    }

    const QString prefix = parser.value(QStringLiteral("prefix"));
    if (!TopicScheme::isValidPrefix(prefix)) {
        m_err << tr("'%1' cannot be a topic prefix: one or more levels joined by '/', without '+', '#' or control "
                    "characters, not starting with '$'")
                         .arg(printable(prefix))
              << Qt::endl;
        return 2;
    }
    bool ok = false;
    const int heartbeat = parser.value(QStringLiteral("heartbeat")).toInt(&ok);
    if (!ok || heartbeat < 100 || heartbeat > 60000) {
        m_err << tr("--heartbeat must be 100..60000 ms") << Qt::endl;
        return 2;
    }

    // The lines: a station file, --line specs, or one --port.
    const bool byStation = parser.isSet(QStringLiteral("station"));
    const bool byLines = parser.isSet(QStringLiteral("line"));
    const bool byPort = parser.isSet(QStringLiteral("port"));
    if (int(byStation) + int(byLines) + int(byPort) != 1) {
        m_err << tr("give the lines by one of --station FILE, --line SPEC (once per line) or --port PATH") << Qt::endl;
        return 2;
    }
    BusSettings defaults;
    const int baud = parser.value(QStringLiteral("baud")).toInt(&ok);
    const std::optional<LineFormat> format = LineFormat::parse(ok ? baud : 0, parser.value(QStringLiteral("format")));
    if (!format) {
        m_err << tr("unsupported baud rate or data format: %1 %2")
                         .arg(parser.value(QStringLiteral("baud")), parser.value(QStringLiteral("format")))
              << Qt::endl;
        return 2;
    }
    defaults.format = *format;
    defaults.retries = parser.value(QStringLiteral("retries")).toInt(&ok);
    if (!ok || defaults.retries < 0 || defaults.retries > 10) {
        m_err << tr("--retries must be 0..10") << Qt::endl;
        return 2;
    }

    m_registry = std::make_unique<FamilyRegistry>(FamilyRegistry::loadDefault());
    for (const QString &e : m_registry->errors())
        m_err << tr("refused map file: %1").arg(e) << Qt::endl;
    for (const QString &text : parser.values(QStringLiteral("poll"))) {
        const std::optional<PollSelection> selection = PollSelection::parse(text, *m_registry, &error);
        if (!selection) {
            m_err << tr("--poll %1: %2").arg(text, error) << Qt::endl;
            return 2;
        }
        if (m_poll.contains(selection->family)) {
            m_err << tr("--poll names %1 twice: give its entries in one").arg(selection->family) << Qt::endl;
            return 2;
        }
        m_poll.insert(selection->family, selection->entries);
    }
    std::optional<StationConfig> config;
    if (byStation) {
        if (parser.isSet(QStringLiteral("device"))) {
            m_err << tr("a station file lists its devices: --device goes with --line or --port") << Qt::endl;
            return 2;
        }
        config = StationConfig::load(parser.value(QStringLiteral("station")), *m_registry, &error);
    } else {
        QList<LineConfig> lines;
        if (byPort) {
            LineConfig line;
            line.settings = defaults;
            line.settings.portName = parser.value(QStringLiteral("port"));
            // A path is a path: Qt would put /dev/ in front of a relative one.
            if (line.settings.portName.contains(QLatin1Char('/')) && !line.settings.portName.startsWith(QLatin1Char('/'))
                && !line.settings.portName.contains(QLatin1String("://")))
                line.settings.portName = QFileInfo(line.settings.portName).absoluteFilePath();
            lines << line;
        }
        for (const QString &spec : parser.values(QStringLiteral("line"))) {
            const std::optional<LineConfig> line = StationConfig::parseLineSpec(spec, defaults, &error);
            if (!line) {
                m_err << error << Qt::endl;
                return 2;
            }
            lines << *line;
        }
        config = StationConfig::fromLines(lines, &error);
        for (const QString &text : parser.values(QStringLiteral("device"))) {
            if (!config)
                break;
            const std::optional<StationDevice> device = config->resolveDevice(text, *m_registry, &error);
            if (!device) {
                config.reset();
                break;
            }
            QList<DeviceSpec> &devices = config->lines[device->line].devices;
            if (devices.contains(device->device)) {
                error = tr("%1 is named twice").arg(text);
                config.reset();
                break;
            }
            devices << device->device;
        }
    }
    if (!config) {
        m_err << error << Qt::endl;
        return 2;
    }
    const QList<StationDevice> devices = config->devices();
    for (auto it = m_poll.cbegin(); it != m_poll.cend(); ++it) {
        if (std::none_of(devices.cbegin(), devices.cend(),
                         [&](const StationDevice &d) { return d.device.family == it.key(); }))
            m_err << tr("--poll %1: no device of the station is a %1").arg(it.key()) << Qt::endl;
    }
    if (devices.isEmpty()) {
        m_err << tr("name at least one device: --device FAMILY@ADDRESS (LINE/FAMILY@ADDRESS with several lines)")
              << Qt::endl;
        return 2;
    }
    const QString station = parser.isSet(QStringLiteral("name")) ? parser.value(QStringLiteral("name")) : config->name;
    if (!TopicScheme::isTopicLevel(station)) {
        m_err << tr("'%1' cannot be a station name: it is one topic level, without '/', '+' and '#'").arg(station)
              << Qt::endl;
        return 2;
    }

    m_publisher = std::make_unique<StationPublisher>(*broker, prefix, station);
    m_publisher->setHeartbeatInterval(heartbeat);
    connect(m_publisher.get(), &StationPublisher::stopped, this, [this] { emit finished(m_stopExitCode); });
    connect(m_publisher.get(), &StationPublisher::takenOver, this, [this, station] {
        m_err << tr("another publisher took over station %1 (--take-over): stopped").arg(station) << Qt::endl;
        emit finished(nameTakenExitCode);
    });
    m_lineConfigs = config->lines;
    m_takeOver = parser.isSet(QStringLiteral("take-over"));
    // Nothing is opened or published before the name is known to be free: a second
    // publisher of one name would poll the same line and clear the other's devices.
    m_nameCheck = std::make_unique<NameCheck>(*broker, TopicScheme(prefix), station);
    connect(m_nameCheck.get(), &NameCheck::finished, this, [this, station](bool online) {
        m_nameCheck.release()->deleteLater();
        if (online && !m_takeOver) {
            m_err << tr("a station named %1 is online at %2: give this one another --name, or --take-over to "
                        "replace it")
                             .arg(station, m_publisher->client().settings().url())
                  << Qt::endl;
            emit finished(nameTakenExitCode);
            return;
        }
        if (online)
            qCWarning(lcMqtt).noquote() << "taking over station" << station << "from the publisher online under its name";
        begin();
    });
    m_nameCheck->start();
    return std::nullopt;
}

void PublisherProgram::begin()
{
    if (const std::optional<int> code = openLines(m_lineConfigs)) {
        emit finished(*code);
        return;
    }
    QString error;
    if (!m_publisher->start(&error)) {
        m_err << error << Qt::endl;
        emit finished(1);
    }
}

std::optional<int> PublisherProgram::openLines(const QList<LineConfig> &lines)
{
    for (const LineConfig &spec : lines) {
        auto bus = std::make_unique<Bus>();
        BusSettings settings = spec.settings;
        // The publisher never writes: its buses refuse every write before the line.
        settings.readOnly = true;
        bus->setSettings(settings);
        bus->setIdentityCheck(m_registry->families());
        for (const DeviceSpec &device : spec.devices) {
            const auto map = m_registry->family(device.family);
            if (!map)
                return 2;   // StationConfig checked the family
            const DeviceId id = bus->addDevice(map, device.address);
            // The station cannot know what its viewers show: the faceplate counts as
            // shown, as on the HMI's overview.
            if (m_poll.contains(device.family))
                bus->setPollEntries(id, m_poll.value(device.family));
            else
                bus->shownEntries()->setShown(this, id, map->faceplateEntries(false));
        }
        if (!bus->open()) {
            // A service keeps trying: the adapter may be plugged in later.
            qCWarning(lcMqtt).noquote() << spec.name << bus->lastError() << "- trying again every"
                                        << m_retry.interval() / 1000 << "s";
            m_retry.start();
        }
        bus->setPolling(true);
        m_publisher->addLine(spec.name, bus.get());
        m_buses.push_back(std::move(bus));
    }
    return std::nullopt;
}

void PublisherProgram::retryClosedLines()
{
    bool waiting = false;
    for (const auto &bus : m_buses) {
        if (bus->state() == LineState::Disconnected && !bus->open())
            waiting = true;
    }
    if (!waiting)
        m_retry.stop();
}

void PublisherProgram::stop(int exitCode)
{
    if (m_stopping)
        return;
    m_stopping = true;
    m_stopExitCode = exitCode;
    m_retry.stop();
    if (m_nameCheck) {
        // Still checking the name: nothing was opened or published.
        m_nameCheck.reset();
        emit finished(exitCode);
        return;
    }
    if (!m_publisher) {
        emit finished(exitCode);
        return;
    }
    qCInfo(lcMqtt).noquote() << "stopping";
    m_publisher->stop();
}

} // namespace jumo
