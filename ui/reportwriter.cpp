#include "reportwriter.h"

#include "protocol/filesaver.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QTextDocument>

namespace jumo {

bool writeReport(const QString &html, const QString &path, QString *error)
{
    if (!path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive))
        return FileSaver::save(path, html.toUtf8(), error);
    // The PDF is made in memory and saved as a whole: QPdfWriter reports no errors, and a
    // report must not half-replace an earlier one.
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter pdf(&buffer);
        pdf.setPageSize(QPageSize(QPageSize::A4));
        pdf.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
        pdf.setTitle(QCoreApplication::translate("jumo::CommissioningReport", "Commissioning report"));
        pdf.setCreator(QStringLiteral("JUMO HMI"));
        pdf.setResolution(300);
        QTextDocument document;
        document.setHtml(html);
        document.print(&pdf);   // lays the text out in points on the writer's pages
    }
    return FileSaver::save(path, buffer.data(), error);
}

} // namespace jumo
