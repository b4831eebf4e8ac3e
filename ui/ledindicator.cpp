#include "ledindicator.h"

#include <QPainter>

#include <algorithm>

namespace jumo {

LedIndicator::LedIndicator(const QString &label, Kind kind, QWidget *parent)
    : QWidget(parent), m_label(label), m_kind(kind)
{
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
}

void LedIndicator::setState(State state, bool stale)
{
    if (state == m_state && stale == m_stale)
        return;
    m_state = state;
    m_stale = stale;
    update();
}

QSize LedIndicator::sizeHint() const
{
    const QFontMetrics fm(font());
    return {fm.height() + 8 + fm.horizontalAdvance(m_label), fm.height() + 6};
}

void LedIndicator::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const int d = fontMetrics().height() - 2;
    const QRect lamp(2, (height() - d) / 2, d, d);
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
    } else {
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
    const bool current = m_state != State::Unknown && !m_stale;
    p.setPen(current ? palette().color(QPalette::WindowText) : palette().color(QPalette::Disabled, QPalette::WindowText));
    QFont f = font();
    f.setBold(on && m_kind != Kind::Status);
    f.setItalic(!current);
    p.setFont(f);
    p.drawText(QRect(lamp.right() + 6, 0, width() - lamp.right() - 6, height()), Qt::AlignVCenter | Qt::AlignLeft,
               m_label);
}

} // namespace jumo
