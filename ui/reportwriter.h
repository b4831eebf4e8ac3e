// Writes an HTML report to a file as HTML or, for a .pdf name, as PDF (A4), through
// QTextDocument: needs a QGuiApplication (offscreen is enough).
#pragma once

#include <QString>

namespace jumo {

bool writeReport(const QString &html, const QString &path, QString *error);

} // namespace jumo
