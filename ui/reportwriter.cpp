#include "reportwriter.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextDocument>

namespace jumo {

bool writeReport(const QString &html, const QString &path, QString *error)
{
    if (path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive)) {
        QPdfWriter pdf(path);
        pdf.setPageSize(QPageSize(QPageSize::A4));
        pdf.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
        pdf.setTitle(QCoreApplication::translate("jumo::CommissioningReport", "Commissioning report"));
        pdf.setCreator(QStringLiteral("JUMO HMI"));
        pdf.setResolution(300);
        QTextDocument document;
        document.setHtml(html);
        document.print(&pdf);   // lays the text out in points on the writer's pages
        // QPdfWriter reports no errors: check that something was written.
        if (!QFile::exists(path) || QFileInfo(path).size() == 0) {
            if (error)
                *error = QCoreApplication::translate("jumo::CommissioningReport", "cannot write %1").arg(path);
            return false;
        }
        return true;
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(html.toUtf8()) < 0 || !file.commit()) {
        if (error)
            *error = QCoreApplication::translate("jumo::CommissioningReport", "cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace jumo
