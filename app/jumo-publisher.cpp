// jumo-publisher: owns a station's lines and publishes their devices to an MQTT broker.
// Everything but wiring lives in lib/mqtt (PublisherProgram).
#include "jumoversion.h"
#include "mqtt/publisherprogram.h"
#include "protocol/translations.h"
#include "quitonsignal.h"

#include <QCoreApplication>
#include <QTextStream>

#include <csignal>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("jumo-publisher"));
    QCoreApplication::setApplicationVersion(QStringLiteral(JUMO_VERSION));
    jumo::installTranslations(app);
    QTextStream out(stdout);
    QTextStream err(stderr);
    jumo::PublisherProgram program(out, err);
    // SIGTERM (systemd), SIGINT and SIGHUP (a closed terminal): "stopped" is published,
    // then the program ends. A closed socket is an error to handle, not a signal that ends it.
    jumo::onTerminationSignals([&program](int) { program.stop(); });
    std::signal(SIGPIPE, SIG_IGN);
    if (const std::optional<int> code = program.run(app.arguments().mid(1)))
        return *code;
    QObject::connect(&program, &jumo::PublisherProgram::finished, &app, &QCoreApplication::exit);
    return app.exec();
}
