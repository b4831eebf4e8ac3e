#include "ledindicator.h"

#include <QPainter>

namespace jumo {

LedIndicator::LedIndicator(const QString &label, Kind kind, QWidget *parent)
    : QWidget(parent), m_label(label), m_kind(kind)
{
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
}

void LedIndicator::setState(bool on, bool current)
{
    if (on == m_on && current == m_current)
        return;
    m_on = on;
    m_current = current;
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
    QColor on = m_kind == Kind::Alarm ? QColor(220, 30, 30) : m_kind == Kind::Warning ? QColor(240, 170, 0) : QColor(40, 170, 60);
    QColor fill = m_on ? on : palette().color(QPalette::Window).darker(115);
    if (!m_current)
        fill = fill.lighter(150);   // not current: pale, and the tooltip says why
    p.setPen(QPen(palette().color(QPalette::Mid), 1));
    p.setBrush(fill);
    p.drawEllipse(lamp);
    p.setPen(m_current ? palette().color(QPalette::WindowText) : palette().color(QPalette::Disabled, QPalette::WindowText));
    QFont f = font();
    f.setBold(m_on && m_kind != Kind::Status);
    p.setFont(f);
    p.drawText(QRect(lamp.right() + 6, 0, width() - lamp.right() - 6, height()), Qt::AlignVCenter | Qt::AlignLeft,
               m_label);
}

} // namespace jumo
