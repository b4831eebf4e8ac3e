// Loads the application's translation for a locale from the resources compiled into the
// library (German today), together with Qt's own strings.
#pragma once

#include <QLocale>

class QCoreApplication;

namespace jumo {

// Installs the translation for the locale on the application; returns whether one was
// found (English needs none).
bool installTranslations(QCoreApplication &app, const QLocale &locale = QLocale());

} // namespace jumo
