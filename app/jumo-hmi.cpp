// jumo-hmi: the desktop HMI. Parses the command line and opens the main window.
#include "benchreport.h"
#include "protocol/familyregistry.h"
#include "bus/stationconfig.h"
#include "connectionbar.h"
#include "devicepage.h"
#include "mainwindow.h"
#include "logs/eventlog.h"
#include "modbuslogging.h"
#include "quitonsignal.h"
#include "systemsettings.h"
#include "protocol/translations.h"
#include "mqtt/topicscheme.h"
#include "remotewindow.h"
#include "jumoversion.h"

#include "theme.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTextStream>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>

#include <cstdio>
#include <memory>

#include <unistd.h>

namespace {

// The control-room viewer: nothing but the broker. Options that name a line or a device,
// or that would write, have no meaning here and are refused rather than ignored.
int runRemote(QApplication &app, const QCommandLineParser &parser, const jumo::FamilyRegistry &registry,
              const QString &theme)
{
    auto usage = [](const QString &message) {
        QTextStream(stderr) << QStringLiteral("jumo-hmi: ") << message << Qt::endl;
        return 2;
    };
    for (const char *option : {"demo", "port", "line", "station", "device", "no-identify", "show", "tab"}) {
        if (parser.isSet(QLatin1String(option)))
            return usage(QApplication::translate("main", "--%1 does not go with --remote: a remote view reads the "
                                                         "broker only")
                                 .arg(QLatin1String(option)));
    }
    QString error;
    const std::optional<jumo::MqttSettings> broker = jumo::MqttSettings::fromOptions(
            {parser.value(QStringLiteral("remote")), QString(), parser.value(QStringLiteral("password-file")),
             parser.value(QStringLiteral("tls-ca")), parser.value(QStringLiteral("tls-cert")),
             parser.value(QStringLiteral("tls-key"))},
            &error);
    if (!broker)
        return usage(error);
    if (!jumo::TopicScheme::isValidPrefix(parser.value(QStringLiteral("mqtt-prefix"))))
        return usage(QApplication::translate("main", "'%1' cannot be a topic prefix").arg(parser.value(QStringLiteral("mqtt-prefix"))));
    const QString kept = QSettings(QStringLiteral("jumo"), QStringLiteral("jumo-hmi")).value(QStringLiteral("theme")).toString();
    jumo::Theme::apply(jumo::Theme::fromName(theme.isEmpty() ? kept : theme).value_or(jumo::Theme::Kind::System));

    jumo::RemoteWindow::Options options;
    options.broker = *broker;
    options.station = parser.value(QStringLiteral("remote-station"));
    options.prefix = parser.value(QStringLiteral("mqtt-prefix"));
    jumo::RemoteWindow window(registry, options);
    if (!window.start(&error))
        return usage(error);
    window.resize(1280, 800);
    window.show();
    return app.exec();
}

// A real start needs a display. Without one Qt aborts (exit 134) with a paragraph about
// reinstalling; the user gets one sentence and exit code 1 instead. Qt's own messages of
// a failed start are held back, those of a start that worked are passed on.
QtMessageHandler qtHandler = nullptr;
bool openingDisplay = false;
QString noDisplaySentence;
QList<std::pair<QtMsgType, QString>> heldMessages;

void onQtMessage(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    if (!openingDisplay) {
        qtHandler(type, context, message);
        return;
    }
    if (type == QtFatalMsg && message.contains(QLatin1String("platform plugin"))) {
        std::fputs(qPrintable(noDisplaySentence + QLatin1Char('\n')), stderr);
        std::fflush(stderr);
        ::_exit(1);   // inside QApplication's constructor: nothing to clean up that exit() could
    }
    if (type == QtFatalMsg)
        qtHandler(type, context, message);
    heldMessages.append({type, message});
}

std::unique_ptr<QApplication> openDisplay(int &argc, char **argv)
{
    qtHandler = qInstallMessageHandler(onQtMessage);
    openingDisplay = true;
    auto app = std::make_unique<QApplication>(argc, argv);
    openingDisplay = false;
    qInstallMessageHandler(qtHandler);
    for (const auto &[type, message] : std::as_const(heldMessages))
        qtHandler(type, QMessageLogContext(), message);
    heldMessages.clear();
    return app;
}

// Settings that cannot be saved are lost when the HMI closes: said once, at the start.
QString unsavedSettingsProblem()
{
    QSettings settings(QStringLiteral("jumo"), QStringLiteral("jumo-hmi"));
    const QFileInfo file(settings.fileName());
    // QSettings replaces the file through a new one beside it: the folder must take it.
    if (settings.isWritable() && QFileInfo(file.absolutePath()).isWritable())
        return {};
    return QApplication::translate("main", "Settings cannot be saved (%1 is not writable): what is changed in this "
                                           "run is lost when it ends")
            .arg(file.absoluteFilePath());
}

void setIdentity()
{
    QCoreApplication::setApplicationName(QStringLiteral("jumo-hmi"));
    QCoreApplication::setApplicationVersion(QStringLiteral(JUMO_VERSION));
    QCoreApplication::setOrganizationName(QStringLiteral("jumo"));
}

// The one option list: read before QApplication (--help, --version) and after it.
void addOptions(QCommandLineParser &parser)
{
    parser.setApplicationDescription(QApplication::translate("main", "JUMO commissioning and monitoring HMI."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption({QStringLiteral("demo"),
                      QApplication::translate("main", "Start on the built-in simulated bus (one device of each family).")});
    parser.addOption({QStringLiteral("read-only"),
                      QApplication::translate("main", "Control-room mode: nothing is ever written to the devices.")});
    parser.addOption({QStringLiteral("show"),
                      QApplication::translate("main", "Open the page of this device, e.g. ipc300@1 (line2/ipc300@1 "
                                                      "with several lines)."),
                      QStringLiteral("device")});
    parser.addOption({QStringLiteral("tab"),
                      QApplication::translate("main", "With --show: open this tab of the device page (0 = live values)."),
                      QStringLiteral("index")});
    parser.addOption({QStringLiteral("port"),
                      QApplication::translate("main", "Connect to this line at start: a serial port, tcp://HOST[:PORT] "
                                                             "(a Modbus TCP gateway) or rtu+tcp://HOST:PORT (a serial "
                                                             "device server); with --baud, --format, --device."),
                      QStringLiteral("address")});
    parser.addOption({QStringLiteral("baud"), QApplication::translate("main", "Baud rate for --port (default 9600)."),
                      QStringLiteral("rate"), QStringLiteral("9600")});
    parser.addOption({QStringLiteral("format"), QApplication::translate("main", "Data format for --port (default 8N1)."),
                      QStringLiteral("format"), QStringLiteral("8N1")});
    parser.addOption({QStringLiteral("line"),
                      QApplication::translate("main", "A line of this run, repeatable: ADDRESS[,name=NAME][,baud=N]"
                                                      "[,format=8N1][,timeout=MS][,min-response=MS][,retries=N]"
                                                      "[,read-only]; ADDRESS is a serial port, tcp://HOST:PORT or "
                                                      "rtu+tcp://HOST:PORT. The lines kept in the settings are left "
                                                      "as they are."),
                      QStringLiteral("spec")});
    parser.addOption({QStringLiteral("station"),
                      QApplication::translate("main", "The lines and devices of this run from a station file "
                                                      "(JSON, see README); the kept lines are left as they are."),
                      QStringLiteral("file")});
    parser.addOption({QStringLiteral("device"),
                      QApplication::translate("main", "A device to monitor, e.g. ipc300@1, or line2/ipc300@1 with "
                                                      "several lines (repeatable)."),
                      QStringLiteral("device")});
    parser.addOption({QStringLiteral("no-identify"),
                      QApplication::translate("main", "Trust the named families without checking the devices' identity "
                                                      "registers (for devices that cannot report them); the write audit "
                                                      "log records it.")});
    parser.addOption({QStringLiteral("theme"),
                      QApplication::translate("main", "Colours for this run: system, light, dark or high-contrast "
                                                      "(default: the theme chosen in the View menu, else system)."),
                      QStringLiteral("name")});
    parser.addOption({QStringLiteral("remote"),
                      QApplication::translate("main", "Control-room viewer: show the stations that publish to this "
                                                      "MQTT broker (mqtt://[USER@]HOST[:PORT] or mqtts://...), with no "
                                                      "Modbus access and nothing that can write."),
                      QStringLiteral("url")});
    parser.addOption({QStringLiteral("remote-station"),
                      QApplication::translate("main", "With --remote: only this station (default: every station)."),
                      QStringLiteral("name")});
    parser.addOption({QStringLiteral("mqtt-prefix"),
                      QApplication::translate("main", "With --remote: the topic prefix (default jumo)."),
                      QStringLiteral("prefix"), QStringLiteral("jumo")});
    parser.addOption({QStringLiteral("password-file"),
                      QApplication::translate("main", "With --remote: a file whose first line is the broker password "
                                                      "(else JUMO_MQTT_PASSWORD; never on the command line)."),
                      QStringLiteral("file")});
    parser.addOption({QStringLiteral("tls-ca"),
                      QApplication::translate("main", "With --remote: the CA certificate that signed the broker's."),
                      QStringLiteral("file")});
    parser.addOption({QStringLiteral("tls-cert"),
                      QApplication::translate("main", "With --remote: a client certificate (with --tls-key)."),
                      QStringLiteral("file")});
    parser.addOption({QStringLiteral("tls-key"),
                      QApplication::translate("main", "With --remote: the client certificate's key."),
                      QStringLiteral("file")});
    parser.addOption({QStringLiteral("report-startup"),
                      QApplication::translate("main", "Print on stderr when the first live value arrives.")});
    // For the HMI benchmark only (tests/bench/bench_hmi.cpp): hidden from --help.
    QCommandLineOption faceplateAges(QStringLiteral("report-faceplate-ages"),
                                     QApplication::translate("main", "For benchmarks: print on stderr every second how "
                                                                     "many faceplates are on screen and how old the "
                                                                     "values they show are."));
    faceplateAges.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOption(faceplateAges);
    parser.addOption({QStringLiteral("verbose"),
                      QApplication::translate("main", "Show Qt's Modbus messages (CRC errors, timeouts, frames) on stderr.")});
}

} // namespace

int main(int argc, char *argv[])
{
    QElapsedTimer started;
    started.start();
    const auto language = [] {
        // Texts and numbers in one language: the one chosen in the Language menu, or the system's.
        const QString chosen = QSettings(QStringLiteral("jumo"), QStringLiteral("jumo-hmi")).value(QStringLiteral("language")).toString();
        return chosen.isEmpty() ? QLocale::system() : QLocale(chosen);
    };
    QCommandLineParser parser;
    {
        // --help and --version answer anywhere (over ssh, right after installing the
        // package): they are read before QApplication, which needs a display.
        QCoreApplication core(argc, argv);
        setIdentity();
        jumo::useLanguage(core, language());
        addOptions(parser);
        // Qt's own options (-platform, -style) are unknown here: only QApplication takes them.
        parser.parse(core.arguments());
        if (parser.isSet(QStringLiteral("help")) || parser.isSet(QStringLiteral("help-all"))
            || parser.isSet(QStringLiteral("version")))
            parser.process(core);   // prints, and exits with 0
        noDisplaySentence = QCoreApplication::translate("main", "jumo-hmi: no display to open the window on (DISPLAY or "
                                                                "WAYLAND_DISPLAY is not set or cannot be reached): start "
                                                                "it in a desktop session");
    }
    const std::unique_ptr<QApplication> application = openDisplay(argc, argv);
    QApplication &app = *application;
    setIdentity();
    QGuiApplication::setDesktopFileName(QStringLiteral(JUMO_APP_ID));   // the window's icon and name on Wayland
    jumo::useLanguage(app, language());
    jumo::quitOnTerminationSignals();   // SIGTERM closes the window properly, settings included
    parser.process(app);
    jumo::showModbusLogging(parser.isSet(QStringLiteral("verbose")));

    // Logs in the root folder, or none at all: without a home the HMI does not start.
    QString noLogs;
    if (jumo::EventLog::defaultFolder(&noLogs).isEmpty()) {
        QTextStream(stderr) << QStringLiteral("jumo-hmi: ") << noLogs << Qt::endl;
        return 1;
    }
    const jumo::FamilyRegistry registry = jumo::FamilyRegistry::loadDefault();
    jumo::MainWindow::Options options;
    options.demo = parser.isSet(QStringLiteral("demo"));
    options.readOnly = parser.isSet(QStringLiteral("read-only"));
    options.identify = !parser.isSet(QStringLiteral("no-identify"));
    options.theme = parser.value(QStringLiteral("theme"));
    // Given, it must name a theme: "--theme ''" is as wrong as "--theme purple".
    if (parser.isSet(QStringLiteral("theme")) && !jumo::Theme::fromName(options.theme)) {
        QTextStream(stderr) << QApplication::translate("main", "jumo-hmi: unknown theme '%1' (system, light, dark or "
                                                               "high-contrast)")
                                       .arg(options.theme)
                            << Qt::endl;
        return 2;
    }
    if (parser.isSet(QStringLiteral("remote")))
        return runRemote(app, parser, registry, options.theme);
    for (const char *option : {"remote-station", "password-file", "tls-ca", "tls-cert", "tls-key"}) {
        if (parser.isSet(QLatin1String(option))) {
            QTextStream(stderr) << QApplication::translate("main", "jumo-hmi: --%1 goes with --remote only")
                                           .arg(QLatin1String(option))
                                << Qt::endl;
            return 2;
        }
    }
    // What goes wrong at the start is said once, in the status bar and on stderr.
    QStringList notes = jumo::SystemSettings::warnings();
    // The administrator's read-only mode; the command line cannot lift it. Said on stderr
    // only: the window shows READ-ONLY.
    if (jumo::SystemSettings::readOnly()) {
        options.readOnly = true;
        QTextStream(stderr) << QStringLiteral("jumo-hmi: ")
                            << QApplication::translate("main", "read-only mode is set by the system configuration (%1): "
                                                               "nothing is written to the devices")
                                       .arg(jumo::SystemSettings::fileName())
                            << Qt::endl;
    }
    if (!options.demo) {   // the demo keeps nothing
        if (const QString unsaved = unsavedSettingsProblem(); !unsaved.isEmpty())
            notes << unsaved;
    }
    // --port, --line and --station make the station of this run, with the --device list.
    if (parser.isSet(QStringLiteral("port")) || parser.isSet(QStringLiteral("line"))
        || parser.isSet(QStringLiteral("station")) || parser.isSet(QStringLiteral("device"))) {
        auto usage = [](const QString &message) {
            QTextStream(stderr) << QStringLiteral("jumo-hmi: ") << message << Qt::endl;
            return 2;
        };
        if (options.demo || int(parser.isSet(QStringLiteral("port"))) + int(parser.isSet(QStringLiteral("line")))
                                    + int(parser.isSet(QStringLiteral("station"))) > 1)
            return usage(QApplication::translate("main", "give the lines one way: --port, --line (repeatable), "
                                                         "--station or --demo"));
        QString error;
        std::optional<jumo::StationConfig> station;
        if (parser.isSet(QStringLiteral("station"))) {
            station = jumo::StationConfig::load(parser.value(QStringLiteral("station")), registry, &error);
        } else {
            jumo::BusSettings defaults;
            const std::optional<jumo::LineFormat> format = jumo::LineFormat::parse(
                    parser.value(QStringLiteral("baud")).toInt(), parser.value(QStringLiteral("format")));
            if (!format)
                return usage(QApplication::translate("main", "--baud %1 --format %2: no line format of this "
                                                             "program (e.g. --baud 19200 --format 8E1)")
                                     .arg(parser.value(QStringLiteral("baud")), parser.value(QStringLiteral("format"))));
            defaults.format = *format;
            QList<jumo::LineConfig> lines;
            // --port is the one line of this run, as a --line without options would be:
            // the lines and devices kept in the settings are neither polled nor changed.
            if (parser.isSet(QStringLiteral("port"))) {
                jumo::LineConfig line;
                line.settings = defaults;
                line.settings.portName = parser.value(QStringLiteral("port"));
                lines << line;
            }
            for (const QString &spec : parser.values(QStringLiteral("line"))) {
                std::optional<jumo::LineConfig> line = jumo::StationConfig::parseLineSpec(spec, defaults, &error);
                if (!line)
                    return usage(error);
                lines << *line;
            }
            station = jumo::StationConfig::fromLines(lines, &error);
        }
        if (!station)
            return usage(error);
        if (station->lines.isEmpty() && !parser.isSet(QStringLiteral("station")))
            return usage(QApplication::translate("main", "--device needs the line it is on: --port, --line or --station"));
        if (station->lines.isEmpty())
            return usage(QApplication::translate("main", "the station has no lines"));
        for (const QString &text : parser.values(QStringLiteral("device"))) {
            const std::optional<jumo::StationDevice> device = station->resolveDevice(text, registry, &error);
            if (!device)
                return usage(error);
            QList<jumo::DeviceSpec> &devices = station->lines[device->line].devices;
            if (!devices.contains(device->device))
                devices << device->device;
        }
        // Checked again with the devices: two at one address on a line are refused, naming both.
        station = jumo::StationConfig::fromLines(station->lines, &error);
        if (!station)
            return usage(error);
        options.lines = station->lines;
    }
    jumo::MainWindow window(registry, options);
    if (!options.lines.isEmpty()) {
        for (const QString &failure : window.connectAllLines())
            QTextStream(stderr) << failure << Qt::endl;
    }
    for (const QString &note : std::as_const(notes))
        QTextStream(stderr) << QStringLiteral("jumo-hmi: ") << note << Qt::endl;
    if (!registry.errors().isEmpty())
        notes << QApplication::translate("main", "Map files refused: %1").arg(registry.errors().join(QStringLiteral("; ")));
    // For a minute: a message hides the line's state in the status bar while it shows.
    if (!notes.isEmpty())
        window.statusBar()->showMessage(notes.join(QStringLiteral("; ")), 60000);
    if (parser.isSet(QStringLiteral("report-startup"))) {
        QObject::connect(window.bus(), &jumo::Bus::entriesUpdated, &window, [started](jumo::DeviceId, const QStringList &ids) {
            static bool reported = false;
            if (!reported && !ids.isEmpty()) {
                reported = true;
                QTextStream(stderr) << "first live value after " << started.elapsed() << " ms" << Qt::endl;
            }
        });
    }
    if (parser.isSet(QStringLiteral("report-faceplate-ages")))
        jumo::BenchReport::faceplateAgesEverySecond(window);
    const QString show = parser.value(QStringLiteral("show"));
    auto showPage = [&window, show, tab = parser.value(QStringLiteral("tab")).toInt()] {
        bool ok = false;
        // "ipc300@1", or "line2/ipc300@1" for a device of that line.
        const QString line = show.contains(QLatin1Char('/')) ? show.section(QLatin1Char('/'), 0, 0) : QString();
        const QString device = show.section(QLatin1Char('/'), -1);
        const quint8 address = quint8(device.section(QLatin1Char('@'), 1).toInt(&ok));
        const QString family = device.section(QLatin1Char('@'), 0, 0);
        if (jumo::DevicePage *page = line.isEmpty() ? window.devicePage(family, address)
                                                    : window.devicePage(line, family, address)) {
            window.showDevice(page);
            page->tabs()->setCurrentIndex(tab);
        }
    };
    if (!show.isEmpty()) {
        QObject::connect(&window, &jumo::MainWindow::demoReady, &window, showPage);
        showPage();
    }
    window.show();
    return app.exec();
}
