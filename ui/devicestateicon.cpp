#include "devicestateicon.h"

#include "bus/bus.h"

#include <QPainter>
#include <QPixmap>

namespace jumo {

DeviceStateIcon::Kind DeviceStateIcon::kindOf(const DeviceCondition &condition, int activeAlarms, bool alarmsKnown)
{
    switch (condition.state) {
    case DeviceCondition::State::Online:
        break;
    case DeviceCondition::State::Disconnected:
    case DeviceCondition::State::Identifying:
        return Kind::Unknown;
    case DeviceCondition::State::WrongDevice:
        return Kind::Alarm;   // nothing of it can be trusted: as loud as an alarm
    case DeviceCondition::State::Offline:
    case DeviceCondition::State::LineLost:
        return Kind::Offline;
    }
    if (!alarmsKnown)
        return Kind::Unknown;
    return activeAlarms > 0 ? Kind::Alarm : Kind::Online;
}

QIcon DeviceStateIcon::icon(Kind kind)
{
    QIcon result;
    for (const int size : {16, 32}) {
        QPixmap pixmap(size, size);
        pixmap.fill(Qt::transparent);
        QPainter p(&pixmap);
        p.setRenderHint(QPainter::Antialiasing);
        const qreal unit = size / 16.0;
        const QRectF dot(2 * unit, 2 * unit, 12 * unit, 12 * unit);
        QFont mark;
        mark.setPixelSize(int(10 * unit));
        mark.setBold(true);
        p.setFont(mark);
        switch (kind) {
        case Kind::Online:
            p.setPen(QPen(QColor(20, 110, 40), unit));
            p.setBrush(QColor(40, 170, 60));
            p.drawEllipse(dot);
            break;
        case Kind::Alarm:
            p.setPen(QPen(QColor(140, 0, 0), unit));
            p.setBrush(QColor(220, 30, 30));
            p.drawEllipse(dot);
            p.setPen(Qt::white);
            p.drawText(dot, Qt::AlignCenter, QStringLiteral("!"));
            break;
        case Kind::Offline:
            p.setPen(QPen(QColor(90, 90, 90), unit));
            p.setBrush(QColor(170, 170, 170));
            p.drawEllipse(dot);
            p.setPen(QPen(Qt::white, 1.6 * unit));
            p.drawLine(QPointF(5.5 * unit, 5.5 * unit), QPointF(10.5 * unit, 10.5 * unit));
            p.drawLine(QPointF(10.5 * unit, 5.5 * unit), QPointF(5.5 * unit, 10.5 * unit));
            break;
        case Kind::Unknown:
            p.setPen(QPen(QColor(120, 120, 120), unit, Qt::DashLine));
            p.setBrush(Qt::NoBrush);
            p.drawEllipse(dot);
            p.setPen(QColor(100, 100, 100));
            p.drawText(dot, Qt::AlignCenter, QStringLiteral("?"));
            break;
        }
        p.end();
        result.addPixmap(pixmap);
    }
    return result;
}

} // namespace jumo
