// jumo-sim: simulated JUMO devices on a serial line (or on a pseudo-terminal pair it
// makes itself), served from the same register maps as the HMI and jumoctl.
#include "protocol/familyregistry.h"
#include "sim/ptypair.h"
#include "quitonsignal.h"
#include "sim/simulatorline.h"
#include "sim/simulatorserver.h"
#include "protocol/translations.h"
#include "jumoversion.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QHostAddress>
#include <QTextStream>

#include <cstdio>
#include <memory>

namespace {

// "[HOST:]PORT" -> address and port; a bare port listens on every interface.
bool parseListen(const QString &text, QHostAddress *address, quint16 *port)
{
    const qsizetype colon = text.lastIndexOf(QLatin1Char(':'));
    QString host = colon >= 0 ? text.left(colon) : QString();
    if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
        host = host.mid(1, host.size() - 2);
    bool ok = false;
    const uint value = text.mid(colon + 1).toUInt(&ok);
    if (!ok || value > 65535)
        return false;
    *port = quint16(value);
    if (host.isEmpty() || host == QLatin1String("*")) {
        *address = QHostAddress::Any;
        return true;
    }
    if (host == QLatin1String("localhost")) {
        *address = QHostAddress::LocalHost;
        return true;
    }
    return address->setAddress(host);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("jumo-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(JUMO_VERSION));
    jumo::installTranslations(app);
    jumo::quitOnTerminationSignals();
    QTextStream out(stdout);
    QTextStream err(stderr);

    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
            "main", "Simulated JUMO devices on a serial line, or behind TCP as a Modbus TCP gateway or a serial "
                    "device server. DEVICE is FAMILY@ADDRESS, e.g. ipc300@1."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption({QStringLiteral("port"), QCoreApplication::translate("main", "Serial port to serve."),
                      QStringLiteral("path")});
    parser.addOption({QStringLiteral("pty"),
                      QCoreApplication::translate("main", "Make a pseudo-terminal pair in this folder (needs socat); "
                                                          "clients connect to FOLDER/master."),
                      QStringLiteral("folder")});
    parser.addOption({QStringLiteral("tcp"),
                      QCoreApplication::translate("main", "Be a Modbus TCP gateway listening on [HOST:]PORT (port 0: "
                                                          "any free one); clients connect to tcp://HOST:PORT."),
                      QStringLiteral("[host:]port")});
    parser.addOption({QStringLiteral("rtu-tcp"),
                      QCoreApplication::translate("main", "Be a serial device server (raw RTU frames over TCP) listening "
                                                          "on [HOST:]PORT; clients connect to rtu+tcp://HOST:PORT."),
                      QStringLiteral("[host:]port")});
    parser.addOption({QStringLiteral("baud"), QCoreApplication::translate("main", "Baud rate (default 9600)."),
                      QStringLiteral("rate"), QStringLiteral("9600")});
    parser.addOption({QStringLiteral("format"), QCoreApplication::translate("main", "Data format (default 8N1)."),
                      QStringLiteral("format"), QStringLiteral("8N1")});
    parser.addOption({QStringLiteral("delay"),
                      QCoreApplication::translate("main", "Processing delay before each reply in ms (default 2)."),
                      QStringLiteral("ms"), QStringLiteral("2")});
    parser.addOption({QStringLiteral("min-response"),
                      QCoreApplication::translate("main", "Minimum response time in ms (default 0)."),
                      QStringLiteral("ms"), QStringLiteral("0")});
    parser.addOption({QStringLiteral("pace"),
                      QCoreApplication::translate("main", "Delay replies by their wire time at the baud rate.")});
    parser.addPositionalArgument(QStringLiteral("device"), QCoreApplication::translate("main", "Devices to simulate."),
                                 QStringLiteral("device..."));
    parser.process(app);

    const std::optional<jumo::LineFormat> format =
            jumo::LineFormat::parse(parser.value(QStringLiteral("baud")).toInt(), parser.value(QStringLiteral("format")));
    if (!format) {
        err << QCoreApplication::translate("main", "unsupported baud rate or data format") << Qt::endl;
        return 2;
    }
    const int places = int(parser.isSet(QStringLiteral("port"))) + int(parser.isSet(QStringLiteral("pty")))
            + int(parser.isSet(QStringLiteral("tcp"))) + int(parser.isSet(QStringLiteral("rtu-tcp")));
    if (places != 1) {
        err << QCoreApplication::translate("main", "give exactly one of --port, --pty, --tcp and --rtu-tcp") << Qt::endl;
        return 2;
    }
    const jumo::FamilyRegistry registry = jumo::FamilyRegistry::loadDefault();
    for (const QString &e : registry.errors())
        err << QCoreApplication::translate("main", "refused map file: %1").arg(e) << Qt::endl;
    bool delayOk = false;
    bool minResponseOk = false;
    const int delay = parser.value(QStringLiteral("delay")).toInt(&delayOk);
    const int minResponse = parser.value(QStringLiteral("min-response")).toInt(&minResponseOk);
    if (!delayOk || delay < 0 || delay > 10000 || !minResponseOk || minResponse < 0 || minResponse > 500) {
        err << QCoreApplication::translate("main", "--delay must be 0..10000 ms and --min-response 0..500 ms") << Qt::endl;
        return 2;
    }
    jumo::SimulatorLine line;
    line.setProcessingDelayMs(delay);
    line.setMinimumResponseTimeMs(minResponse);
    line.setPacing(parser.isSet(QStringLiteral("pace")));
    line.setTickInterval(100);
    if (parser.positionalArguments().isEmpty()) {
        err << QCoreApplication::translate("main", "name at least one device, e.g. ipc300@1") << Qt::endl;
        return 2;
    }
    for (const QString &device : parser.positionalArguments()) {
        const auto map = registry.family(device.section(QLatin1Char('@'), 0, 0));
        bool ok = false;
        const int address = device.section(QLatin1Char('@'), 1).toInt(&ok);
        if (!map || !ok || address < 1 || address > 255) {
            err << QCoreApplication::translate("main", "'%1' is not FAMILY@ADDRESS with a known family").arg(device)
                << Qt::endl;
            return 2;
        }
        if (!map->protocol.supports(format->baudRate, format->formatName())) {
            // A real one would never answer: a simulated line must not pass where a real fails.
            QStringList bauds;
            for (int baud : map->protocol.baudRates)
                bauds << QString::number(baud);
            err << QCoreApplication::translate("main", "'%1': %2 devices cannot be set to %3 baud %4 (they support %5 baud, %6)")
                            .arg(device, map->shortName)
                            .arg(format->baudRate)
                            .arg(format->formatName(), bauds.join(QStringLiteral(", ")),
                                 map->protocol.dataFormats.join(QStringLiteral(", ")))
                << Qt::endl;
            return 2;
        }
        line.addDevice(map, quint8(address));
    }

    auto serve = [&](const QString &port) {
        QString error;
        if (!line.open(port, *format, &error)) {
            err << QCoreApplication::translate("main", "cannot open %1: %2").arg(port, error) << Qt::endl;
            QCoreApplication::exit(1);
            return;
        }
        out << QCoreApplication::translate("main", "serving %n device(s) on %1", nullptr, int(line.devices().size()))
                        .arg(port)
            << Qt::endl;
    };
    jumo::PtyPair pty;
    std::unique_ptr<jumo::SimulatorServer> server;
    if (parser.isSet(QStringLiteral("tcp")) || parser.isSet(QStringLiteral("rtu-tcp"))) {
        const bool gateway = parser.isSet(QStringLiteral("tcp"));
        const QString listen = parser.value(gateway ? QStringLiteral("tcp") : QStringLiteral("rtu-tcp"));
        QHostAddress address;
        quint16 port = 0;
        if (!parseListen(listen, &address, &port)) {
            err << QCoreApplication::translate("main", "'%1' is not [HOST:]PORT").arg(listen) << Qt::endl;
            return 2;
        }
        line.setFormat(*format);
        server = std::make_unique<jumo::SimulatorServer>(
                &line, gateway ? jumo::SimulatorServer::Mode::ModbusTcp : jumo::SimulatorServer::Mode::RtuOverTcp);
        QString error;
        if (!server->listen(address, port, &error)) {
            err << QCoreApplication::translate("main", "cannot listen on %1: %2").arg(listen, error) << Qt::endl;
            return 1;
        }
        QString host = address == QHostAddress::Any ? QStringLiteral("127.0.0.1") : address.toString();
        if (host.contains(QLatin1Char(':')))
            host = QStringLiteral("[%1]").arg(host);
        const QString url = QStringLiteral("%1://%2:%3")
                                    .arg(gateway ? QStringLiteral("tcp") : QStringLiteral("rtu+tcp"), host)
                                    .arg(server->port());
        out << QCoreApplication::translate("main", "serving %n device(s) on %1", nullptr, int(line.devices().size()))
                        .arg(url)
            << Qt::endl;
        out << QCoreApplication::translate("main", "connect to %1").arg(url) << Qt::endl;
    } else if (parser.isSet(QStringLiteral("pty"))) {
        QObject::connect(&pty, &jumo::PtyPair::ready, &app, [&] {
            // The devices answer only a client at the line's own settings, as real ones do.
            QString error;
            if (!line.watchClientEnd(pty.masterEnd(), &error))
                err << QCoreApplication::translate("main", "warning: the devices answer at any settings: cannot watch %1: %2")
                                .arg(pty.masterEnd(), error)
                    << Qt::endl;
            serve(pty.deviceEnd());
            out << QCoreApplication::translate("main", "connect to %1").arg(pty.masterEnd()) << Qt::endl;
        });
        QObject::connect(&pty, &jumo::PtyPair::failed, &app, [&](const QString &reason) {
            err << reason << Qt::endl;
            QCoreApplication::exit(1);
        });
        // Absolute: Qt takes a relative port name as one under /dev.
        pty.start(QFileInfo(parser.value(QStringLiteral("pty"))).absoluteFilePath());
    } else {
        serve(parser.value(QStringLiteral("port")));
        if (!line.isOpen())
            return 1;
    }
    return app.exec();
}
