// jumo-hmi: the desktop HMI. Until the device pages land it opens the register map browser.
#include "familyregistry.h"
#include "registermapbrowser.h"
#include "translations.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QMessageBox>

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("jumo-hmi"));
    QApplication::setApplicationVersion(QStringLiteral(JUMO_VERSION));
    QApplication::setOrganizationName(QStringLiteral("jumo"));
    jumo::installTranslations(app);

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "JUMO commissioning and monitoring HMI."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption({QStringLiteral("demo"),
                      QApplication::translate("main", "Start on the built-in simulated bus (one device of each family).")});
    parser.addOption({QStringLiteral("read-only"),
                      QApplication::translate("main", "Control-room mode: nothing is ever written to the devices.")});
    parser.process(app);

    const jumo::FamilyRegistry registry = jumo::FamilyRegistry::loadDefault();
    jumo::RegisterMapBrowser browser(registry);
    browser.show();
    if (!registry.errors().isEmpty())
        QMessageBox::warning(&browser, QApplication::translate("main", "Map files refused"),
                             registry.errors().join(QLatin1Char('\n')));
    return app.exec();
}
