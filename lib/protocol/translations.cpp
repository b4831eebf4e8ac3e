#include "protocol/translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QPointer>
#include <QTranslator>

#include <iterator>

namespace jumo {

namespace {

// The translators installed here, so a change of language replaces them.
QList<QPointer<QTranslator>> &installed()
{
    static QList<QPointer<QTranslator>> translators;
    return translators;
}

} // namespace

QList<QtMessage> qtMessages()
{
    // What QModbusRtuSerialClient says when its serial port fails (the words are Qt's:
    // a translation is found by them), of a request that got no answer and of one cut
    // short by a closing port.
    static const QtMessage messages[] = {
            {"QModbusDevice", QT_TRANSLATE_NOOP("QModbusDevice", "Referenced serial device does not exist.")},
            {"QModbusDevice", QT_TRANSLATE_NOOP("QModbusDevice", "Cannot open serial device due to permissions.")},
            {"QModbusDevice", QT_TRANSLATE_NOOP("QModbusDevice", "Cannot open serial device.")},
            {"QModbusDevice", QT_TRANSLATE_NOOP("QModbusDevice", "Write error.")},
            {"QModbusDevice", QT_TRANSLATE_NOOP("QModbusDevice", "Read error.")},
            {"QModbusDevice", QT_TRANSLATE_NOOP("QModbusDevice", "Resource error.")},
            {"QModbusDevice", QT_TRANSLATE_NOOP("QModbusDevice", "Device operation is not supported error.")},
            {"QModbusDevice", QT_TRANSLATE_NOOP("QModbusDevice", "Timeout error.")},
            {"QModbusDevice", QT_TRANSLATE_NOOP("QModbusDevice", "Unknown error.")},
            {"QModbusClient", QT_TRANSLATE_NOOP("QModbusClient", "Request timeout.")},
            {"QModbusClient", QT_TRANSLATE_NOOP("QModbusClient", "Reply aborted due to connection closure.")},
    };
    return QList<QtMessage>(std::begin(messages), std::end(messages));
}

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
