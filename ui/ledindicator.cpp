#include "ledindicator.h"

#include "theme.h"

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
    const QColor lit = Theme::color(m_kind == Kind::Alarm     ? Theme::Role::LedAlarm
                                    : m_kind == Kind::Warning ? Theme::Role::LedWarning
                                                              : Theme::Role::LedStatus);
    const QColor window = palette().color(QPalette::Window);
    QColor fill = on ? lit : (Theme::isDark() ? window.lighter(140) : window.darker(115));
    if (m_stale)
        fill = Theme::isDark() ? fill.darker(160) : fill.lighter(150);   // stale: pale, and the tooltip says why
    // Without colour an LED that is on still differs: a heavy outline and a light centre.
    p.setPen(on ? QPen(palette().color(QPalette::WindowText), 2) : QPen(palette().color(QPalette::Mid), 1));
    p.setBrush(fill);
    p.drawEllipse(on ? QRectF(lamp).adjusted(1, 1, -1, -1) : QRectF(lamp));
    if (on) {
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(255, 255, 255, 190));
        const double r = d / 5.0;
        p.drawEllipse(QPointF(lamp.center()) + QPointF(-r * 0.6, -r * 0.6), r, r);
    }
}

} // namespace jumo
