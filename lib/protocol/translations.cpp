#include "protocol/translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QPointer>
#include <QTranslator>

namespace jumo {

namespace {

// The translators installed here, so a change of language replaces them.
QList<QPointer<QTranslator>> &installed()
{
    static QList<QPointer<QTranslator>> translators;
    return translators;
}

} // namespace

bool installTranslations(QCoreApplication &app, const QLocale &locale)
{
    for (const QPointer<QTranslator> &t : std::as_const(installed())) {
        if (t) {
            QCoreApplication::removeTranslator(t);
            delete t;
        }
    }
    installed().clear();
    auto *own = new QTranslator(&app);
    if (!own->load(locale, QStringLiteral("jumo"), QStringLiteral("_"), QStringLiteral(":/i18n"))) {
        delete own;
        return false;
    }
    app.installTranslator(own);
    installed() << own;
    auto *qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"), QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        app.installTranslator(qt);
        installed() << qt;
    } else {
        delete qt;
    }
    return true;
}

bool useLanguage(QCoreApplication &app, const QLocale &locale)
{
    QLocale::setDefault(locale);
    return installTranslations(app, locale);
}

} // namespace jumo
