// jumo-hmi: the desktop HMI. Parses the command line and opens the main window.
#include "protocol/familyregistry.h"
#include "connectionbar.h"
#include "devicepage.h"
#include "mainwindow.h"
#include "modbuslogging.h"
#include "quitonsignal.h"
#include "protocol/translations.h"
#include "jumoversion.h"

#include "theme.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QTextStream>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>

int main(int argc, char *argv[])
{
    QElapsedTimer started;
    started.start();
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("jumo-hmi"));
    QApplication::setApplicationVersion(QStringLiteral(JUMO_VERSION));
    QApplication::setOrganizationName(QStringLiteral("jumo"));
    QGuiApplication::setDesktopFileName(QStringLiteral(JUMO_APP_ID));   // the window's icon and name on Wayland
    const QString language = QSettings(QStringLiteral("jumo"), QStringLiteral("jumo-hmi")).value(QStringLiteral("language")).toString();
    // Texts and numbers in one language: the one chosen in the Language menu, or the system's.
    jumo::useLanguage(app, language.isEmpty() ? QLocale::system() : QLocale(language));
    jumo::quitOnTerminationSignals();   // SIGTERM closes the window properly, settings included

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "JUMO commissioning and monitoring HMI."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption({QStringLiteral("demo"),
                      QApplication::translate("main", "Start on the built-in simulated bus (one device of each family).")});
    parser.addOption({QStringLiteral("read-only"),
                      QApplication::translate("main", "Control-room mode: nothing is ever written to the devices.")});
    parser.addOption({QStringLiteral("show"),
                      QApplication::translate("main", "Open the page of this device, e.g. ipc300@1."),
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
    parser.addOption({QStringLiteral("device"),
                      QApplication::translate("main", "A device to monitor, e.g. ipc300@1 (repeatable)."),
                      QStringLiteral("device")});
    parser.addOption({QStringLiteral("no-identify"),
                      QApplication::translate("main", "Trust the named families without checking the devices' identity "
                                                      "registers (for devices that cannot report them); the write audit "
                                                      "log records it.")});
    parser.addOption({QStringLiteral("theme"),
                      QApplication::translate("main", "Colours for this run: system, light, dark or high-contrast "
                                                      "(default: the theme chosen in the View menu, else system)."),
                      QStringLiteral("name")});
    parser.addOption({QStringLiteral("report-startup"),
                      QApplication::translate("main", "Print on stderr when the first live value arrives.")});
    parser.addOption({QStringLiteral("verbose"),
                      QApplication::translate("main", "Show Qt's Modbus messages (CRC errors, timeouts, frames) on stderr.")});
    parser.process(app);
    jumo::showModbusLogging(parser.isSet(QStringLiteral("verbose")));

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
    jumo::MainWindow window(registry, options);
    if (!registry.errors().isEmpty())
        window.statusBar()->showMessage(QApplication::translate("main", "Map files refused: %1")
                                                .arg(registry.errors().join(QStringLiteral("; "))));
    if (parser.isSet(QStringLiteral("port"))) {
        window.connectionBar()->setSettings(parser.value(QStringLiteral("port")), parser.value(QStringLiteral("baud")).toInt(),
                                            parser.value(QStringLiteral("format")));
        for (const QString &device : parser.values(QStringLiteral("device"))) {
            bool ok = false;
            const int address = device.section(QLatin1Char('@'), 1).toInt(&ok);
            const auto map = registry.family(device.section(QLatin1Char('@'), 0, 0));
            if (!map || !ok || address < 1 || address > 255) {
                QTextStream(stderr) << QApplication::translate("main", "'%1' is not FAMILY@ADDRESS with a known family")
                                               .arg(device)
                                    << Qt::endl;
                return 2;
            }
            window.addDevice(map, quint8(address));
        }
        if (!window.connectLine())
            QTextStream(stderr) << window.bus()->lastError() << Qt::endl;
    }
    if (parser.isSet(QStringLiteral("report-startup"))) {
        QObject::connect(window.bus(), &jumo::Bus::entriesUpdated, &window, [started](jumo::DeviceId, const QStringList &ids) {
            static bool reported = false;
            if (!reported && !ids.isEmpty()) {
                reported = true;
                QTextStream(stderr) << "first live value after " << started.elapsed() << " ms" << Qt::endl;
            }
        });
    }
    const QString show = parser.value(QStringLiteral("show"));
    auto showPage = [&window, show, tab = parser.value(QStringLiteral("tab")).toInt()] {
        bool ok = false;
        const quint8 address = quint8(show.section(QLatin1Char('@'), 1).toInt(&ok));
        if (jumo::DevicePage *page = window.devicePage(show.section(QLatin1Char('@'), 0, 0), address)) {
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
