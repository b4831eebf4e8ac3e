#include "reportwriter.h"

#include "protocol/filesaver.h"

#include <QAbstractTextDocumentLayout>
#include <QBuffer>
#include <QFontMetricsF>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFrame>
#include <QTextTable>

#include <algorithm>

namespace jumo {

namespace {

// A table of at most this many rows is never split; a longer one keeps its header and
// the first rows with its heading.
constexpr int smallTableRows = 8;
constexpr int rowsWithHeading = 2;

qreal bottomOf(QAbstractTextDocumentLayout *layout, const QTextTable *table, int row)
{
    qreal bottom = 0;
    for (int column = 0; column < table->columns(); ++column) {
        const QTextTableCell cell = table->cellAt(row, column);
        if (!cell.isValid())
            continue;
        const QTextBlock last = cell.lastCursorPosition().block();
        bottom = std::max(bottom, layout->blockBoundingRect(last).bottom());
    }
    return bottom;
}

} // namespace

void ReportWriter::keepTogether(QTextDocument &document, qreal pageHeight)
{
    const auto pageOf = [pageHeight](qreal y) { return int(y / pageHeight); };
    const qreal fits = pageHeight * 0.9;
    // One move at a time, from the top: each moves what follows it.
    for (int pass = 0; pass < 500; ++pass) {
        QAbstractTextDocumentLayout *layout = document.documentLayout();
        bool moved = false;
        const auto breakBefore = [&](const QTextBlock &block, QTextFrame *frame) {
            if (block.isValid()) {
                QTextBlockFormat format;
                format.setPageBreakPolicy(QTextFormat::PageBreak_AlwaysBefore);
                QTextCursor(block).mergeBlockFormat(format);
            } else {
                QTextFrameFormat format = frame->frameFormat();
                format.setPageBreakPolicy(QTextFormat::PageBreak_AlwaysBefore);
                frame->setFrameFormat(format);
            }
            // Laid out again as a whole: after a change Qt lays out only as far as it is
            // asked, and what lies beyond would be measured (and painted) from no layout.
            document.markContentsDirty(0, document.characterCount());
            moved = true;
        };
        // Keeps the text from one of the starts (tried in turn, the earliest first) to
        // bottom on one page, where that fits; false when it cannot.
        const auto keep = [&](const QList<QTextBlock> &starts, qreal bottom) {
            for (const QTextBlock &start : starts) {
                if (!start.isValid())
                    continue;
                const qreal top = layout->blockBoundingRect(start).top();
                if (pageOf(top) == pageOf(bottom - 0.5))
                    return true;
                if (bottom - top < fits) {
                    breakBefore(start, nullptr);
                    return true;
                }
            }
            return false;
        };
        QTextBlock runStart;      // the first text after the previous table: headings, notes
        QTextBlock lastHeading;   // the last heading since
        bool headingHasText = false;
        for (QTextFrame::iterator it = document.rootFrame()->begin(); !it.atEnd() && !moved; ++it) {
            if (QTextFrame *frame = it.currentFrame()) {
                auto *table = qobject_cast<QTextTable *>(frame);
                if (table && table->rows() > 0) {
                    const int header = table->format().headerRowCount();
                    const int kept = table->rows() <= smallTableRows ? table->rows()
                                                                     : std::min(table->rows(), header + rowsWithHeading);
                    const qreal bottom = bottomOf(layout, table, kept - 1);
                    const qreal top = layout->frameBoundingRect(frame).top();
                    if (!keep({runStart, lastHeading}, bottom) && pageOf(top) != pageOf(bottom - 0.5) && bottom - top < fits)
                        breakBefore(QTextBlock(), frame);
                }
                runStart = lastHeading = QTextBlock();
                continue;
            }
            const QTextBlock block = it.currentBlock();
            if (block.text().trimmed().isEmpty())
                continue;   // the empty blocks between frames
            if (!runStart.isValid())
                runStart = block;
            if (block.blockFormat().headingLevel() > 0) {
                lastHeading = block;
                headingHasText = false;
            } else if (lastHeading.isValid() && !headingHasText) {
                // A heading never ends a page without the text it heads.
                headingHasText = true;
                keep({lastHeading}, layout->blockBoundingRect(block).bottom());
            }
        }
        if (!moved)
            return;
    }
}

QByteArray ReportWriter::pdf(const QString &html, const Pages &pages, int *pageCount)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter pdf(&buffer);
        pdf.setPageSize(QPageSize(QPageSize::A4));
        pdf.setPageMargins(QMarginsF(15, 12, 15, 12), QPageLayout::Millimeter);
        pdf.setResolution(300);
        pdf.setTitle(pages.title);
        pdf.setCreator(QStringLiteral("JUMO HMI"));

        QPainter painter(&pdf);
        const QRectF paper = pdf.pageLayout().paintRectPixels(pdf.resolution());
        const qreal width = paper.width();
        QFont small(QStringLiteral("sans-serif"), 8);
        small.setStyleHint(QFont::SansSerif);
        const QFontMetricsF metrics(small, &pdf);
        const qreal gap = 4.0 / 25.4 * pdf.resolution();   // 4 mm between header, body and footer
        const qreal headerHeight = metrics.height() + gap;
        const qreal footerHeight = metrics.height() + gap;
        const QSizeF body(width, paper.height() - headerHeight - footerHeight);

        // Laid out in the writer's pixels, as QTextDocument::print does, so that sizes
        // in points come out as points and every page is exactly one body high.
        QTextDocument document;
        document.documentLayout()->setPaintDevice(&pdf);
        QFont base(QStringLiteral("sans-serif"), 9);
        base.setStyleHint(QFont::SansSerif);
        document.setDefaultFont(base);
        document.setDocumentMargin(0);
        document.setHtml(html);
        document.setPageSize(body);
        keepTogether(document, body.height());
        const int count = document.pageCount();
        if (pageCount)
            *pageCount = count;

        const QPen rule(QColor(0x99, 0x99, 0x99), 0.3 / 25.4 * pdf.resolution());
        for (int page = 0; page < count; ++page) {
            if (page > 0)
                pdf.newPage();
            painter.save();
            painter.translate(0, headerHeight - page * body.height());
            document.drawContents(&painter, QRectF(QPointF(0, page * body.height()), body));
            painter.restore();

            painter.setFont(small);
            painter.setPen(Qt::black);
            const QString number = tr("Page %1 of %2").arg(page + 1).arg(count);
            const qreal numberWidth = metrics.horizontalAdvance(number);
            painter.drawText(QRectF(0, 0, width, metrics.height()), Qt::AlignLeft | Qt::AlignTop,
                             metrics.elidedText(pages.header, Qt::ElideRight, width));
            const qreal footerTop = paper.height() - metrics.height();
            painter.drawText(QRectF(0, footerTop, width, metrics.height()), Qt::AlignLeft | Qt::AlignTop,
                             metrics.elidedText(pages.footer, Qt::ElideRight, width - numberWidth - gap));
            painter.drawText(QRectF(0, footerTop, width, metrics.height()), Qt::AlignRight | Qt::AlignTop, number);
            painter.setPen(rule);
            painter.drawLine(QPointF(0, metrics.height() + gap / 3), QPointF(width, metrics.height() + gap / 3));
            painter.drawLine(QPointF(0, footerTop - gap / 3), QPointF(width, footerTop - gap / 3));
        }
        painter.end();
    }
    return buffer.data();
}

bool ReportWriter::write(const QString &html, const QString &path, const Pages &pages, QString *error)
{
    if (!path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive))
        return FileSaver::save(path, html.toUtf8(), error);
    // Made in memory and saved as a whole: QPdfWriter reports no errors, and a report
    // must not half-replace an earlier one.
    return FileSaver::save(path, pdf(html, pages), error);
}

} // namespace jumo
