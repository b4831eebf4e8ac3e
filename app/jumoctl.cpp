// jumoctl: the command-line tool. Everything but wiring lives in the jumocli library.
#include "commandlinetool.h"
#include "quitonsignal.h"
#include "protocol/translations.h"
#include "jumoversion.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QTextStream>

#include <cstdio>
#include <memory>

int main(int argc, char *argv[])
{
    // Reports need QtGui for PDF (fonts, layout); everything else runs without it.
    const bool report = argc > 1 && qstrcmp(argv[1], "report") == 0;
    if (report && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    std::unique_ptr<QCoreApplication> application(report ? new QGuiApplication(argc, argv)
                                                         : new QCoreApplication(argc, argv));
    QCoreApplication &app = *application;
    QCoreApplication::setApplicationName(QStringLiteral("jumoctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(JUMO_VERSION));
    QCoreApplication::setOrganizationName(QStringLiteral("jumo"));
    jumo::installTranslations(app);
    QTextStream out(stdout);
    QTextStream err(stderr);
    jumo::CommandLineTool tool(out, err);
    // Ctrl-C, SIGTERM, SIGHUP and a closed output (SIGPIPE) end a command with 130, 143,
    // 129 or 141 and what it got done.
    jumo::onTerminationSignals([&tool](int signal) { tool.interrupt(signal); });
    if (const std::optional<int> code = tool.run(app.arguments().mid(1)))
        return *code;
    QObject::connect(&tool, &jumo::CommandLineTool::finished, &app, &QCoreApplication::exit);
    return app.exec();
}
