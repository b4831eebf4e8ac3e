// jumo-publisher: owns a station's lines and publishes their devices to an MQTT broker.
// Everything but wiring lives in lib/mqtt (PublisherProgram).
#include "exitcodes.h"
#include "jumoversion.h"
#include "mqtt/publisherprogram.h"
#include "outputcheck.h"
#include "protocol/translations.h"
#include "quitonsignal.h"

#include <QCoreApplication>
#include <QTextStream>
#include <QTimer>

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
    // Each ends it with "stopped" published. SIGTERM (systemd) and SIGINT are the stops
    // asked for: exit code 0. SIGHUP (a closed terminal) ends it with 129 and a log whose
    // reader has gone (... 2>&1 | head) with 141, as they end jumoctl, so that a service
    // manager starts it again. libmosquitto ignores SIGPIPE for the whole process (its
    // writes to a broker's socket would raise it), so the log's reader is looked for
    // once a second; a SIGPIPE that comes before is taken only when that reader is gone.
    const auto logClosed = [&out, &err] { return jumo::OutputCheck::closed(err) || jumo::OutputCheck::closed(out); };
    jumo::onTerminationSignals([&program, logClosed](int signal) {
        if (signal == SIGHUP)
            program.stop(jumo::exitcode::HungUp);
        else if (signal != SIGPIPE)
            program.stop();
        else if (logClosed())
            program.stop(jumo::exitcode::OutputClosed);
    });
    QTimer logWatch;
    QObject::connect(&logWatch, &QTimer::timeout, &program, [&program, logClosed] {
        if (logClosed())
            program.stop(jumo::exitcode::OutputClosed);
    });
    logWatch.start(1000);
    if (const std::optional<int> code = program.run(app.arguments().mid(1)))
        return *code;
    QObject::connect(&program, &jumo::PublisherProgram::finished, &app, &QCoreApplication::exit);
    return app.exec();
}
