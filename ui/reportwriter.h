// Writes a report to a file: HTML as it is, or for a .pdf name a PDF on A4 pages laid out
// here, with a header and "Page n of m" on every page, headings kept with what follows
// and small tables kept whole. Needs a QGuiApplication (offscreen is enough).
#pragma once

#include <QCoreApplication>
#include <QString>

class QTextDocument;

namespace jumo {

class ReportWriter
{
    Q_DECLARE_TR_FUNCTIONS(jumo::ReportWriter)

public:
    struct Pages
    {
        QString title;    // the PDF's title
        QString header;   // the head of every page
        QString footer;   // the foot of every page, beside the page number
    };

    static bool write(const QString &html, const QString &path, const Pages &pages, QString *error);
    // The PDF itself, made in memory; pageCount: how many pages it has.
    static QByteArray pdf(const QString &html, const Pages &pages, int *pageCount = nullptr);
    // Moves a heading that would end a page to the next one with what it heads, and a
    // table of a few rows (a title block, the signatures) whole onto the next page
    // rather than splitting it; the document must be laid out in pages of pageHeight.
    static void keepTogether(QTextDocument &document, qreal pageHeight);
};

} // namespace jumo
