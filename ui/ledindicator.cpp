#include "ledindicator.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>

#include <algorithm>

namespace jumo {

LedIndicator::LedIndicator(const QString &label, Kind kind, QWidget *parent)
    : QWidget(parent), m_label(label), m_kind(kind), m_text(new QLabel(label, this))
{
    m_text->setObjectName(QStringLiteral("ledLabel"));
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::PlainText);
    m_text->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    auto *layout = new QHBoxLayout(this);
    // The lamp is painted in the left margin, level with the first line of the label.
    layout->setContentsMargins(lampSize() + 8, 2, 0, 2);
    layout->addWidget(m_text, 1);
    updateText();
}

int LedIndicator::lampSize() const
{
    return fontMetrics().height() - 2;
}

QSize LedIndicator::sizeHint() const
{
    // Measured in bold: the label turns bold while an alarm is on, and must not wrap then.
    QFont bold = font();
    bold.setBold(true);
    const QMargins m = layout()->contentsMargins();
    const QFontMetrics fm(bold);
    return {m.left() + fm.horizontalAdvance(m_label) + m.right() + 2, m.top() + fm.height() + m.bottom()};
}

void LedIndicator::setState(State state, bool stale)
{
    if (state == m_state && stale == m_stale)
        return;
    m_state = state;
    m_stale = stale;
    updateText();
    update();
}

void LedIndicator::updateText()
{
    const bool current = m_state != State::Unknown && !m_stale;
    QFont f = font();
    f.setBold(m_state == State::On && m_kind != Kind::Status);
    f.setItalic(!current);
    m_text->setFont(f);
    m_text->setForegroundRole(current ? QPalette::WindowText : QPalette::PlaceholderText);
}

void LedIndicator::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const int d = lampSize();
    const int firstLine = m_text->fontMetrics().height();
    const QRect lamp(2, m_text->geometry().top() + (firstLine - d) / 2, d, d);
    const bool on = m_state == State::On;
    if (m_state == State::Unknown) {
        // Neither on nor off: a hollow, dashed lamp with a question mark.
        p.setPen(QPen(palette().color(QPalette::Mid), 1, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(lamp);
        QFont mark = font();
        mark.setPixelSize(std::max(6, d - 4));
        mark.setBold(true);
        p.setFont(mark);
        p.setPen(palette().color(QPalette::Disabled, QPalette::WindowText));
        p.drawText(lamp, Qt::AlignCenter, QStringLiteral("?"));
        return;
    }
    const QColor lit = m_kind == Kind::Alarm ? QColor(220, 30, 30)
            : m_kind == Kind::Warning        ? QColor(240, 170, 0)
                                             : QColor(40, 170, 60);
    QColor fill = on ? lit : palette().color(QPalette::Window).darker(115);
    if (m_stale)
        fill = fill.lighter(150);   // stale: pale, and the tooltip says why
    p.setPen(QPen(palette().color(QPalette::Mid), 1));
    p.setBrush(fill);
    p.drawEllipse(lamp);
}

} // namespace jumo
