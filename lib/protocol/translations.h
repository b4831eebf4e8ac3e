// Loads the application's translation for a locale from the resources compiled into the
// library (German today), together with Qt's own strings.
#pragma once

#include <QList>
#include <QLocale>

class QCoreApplication;

namespace jumo {

// Installs the translation for the locale on the application, in place of one installed
// before; returns whether one was found (English needs none).
bool installTranslations(QCoreApplication &app, const QLocale &locale = QLocale());

// The HMI's language: its translation, and the locale numbers are written in, so a
// German HMI shows "91,9 V" on an English system too (QLocale::setDefault).
bool useLanguage(QCoreApplication &app, const QLocale &locale);

// Qt's own messages that reach our users word for word (a serial port that is pulled:
// "Resource error."), under Qt's contexts. They are listed for lupdate so that our own
// translation has them: Qt's translations (qtserialbus) are often not installed.
struct QtMessage
{
    const char *context;
    const char *source;
};
QList<QtMessage> qtMessages();

} // namespace jumo
