// jumoctl: the command-line tool. Everything but wiring lives in the jumocli library.
#include "commandlinetool.h"
#include "quitonsignal.h"
#include "translations.h"

#include <QCoreApplication>
#include <QTextStream>

#include <cstdio>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("jumoctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(JUMO_VERSION));
    QCoreApplication::setOrganizationName(QStringLiteral("jumo"));
    jumo::installTranslations(app);
    jumo::quitOnTerminationSignals();   // monitor runs until stopped

    QTextStream out(stdout);
    QTextStream err(stderr);
    jumo::CommandLineTool tool(out, err);
    if (const std::optional<int> code = tool.run(app.arguments().mid(1)))
        return *code;
    QObject::connect(&tool, &jumo::CommandLineTool::finished, &app, &QCoreApplication::exit);
    return app.exec();
}
