#include "devicestateicon.h"

#include "bus/bus.h"
#include "theme.h"

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
            p.setPen(QPen(Theme::color(Theme::Role::LedStatus).darker(160), unit));
            p.setBrush(Theme::color(Theme::Role::LedStatus));
            p.drawEllipse(dot);
            break;
        case Kind::Alarm:
            p.setPen(QPen(Theme::color(Theme::Role::LedAlarm).darker(160), unit));
            p.setBrush(Theme::color(Theme::Role::LedAlarm));
            p.drawEllipse(dot);
            p.setPen(Qt::white);
            p.drawText(dot, Qt::AlignCenter, QStringLiteral("!"));
            break;
        case Kind::Offline:
            // Grey as the theme's secondary text, so it stands out on a dark list too.
            p.setPen(QPen(Theme::color(Theme::Role::Hint).darker(140), unit));
            p.setBrush(Theme::color(Theme::Role::Hint));
            p.drawEllipse(dot);
            p.setPen(QPen(Qt::white, 1.6 * unit));
            p.drawLine(QPointF(5.5 * unit, 5.5 * unit), QPointF(10.5 * unit, 10.5 * unit));
            p.drawLine(QPointF(10.5 * unit, 5.5 * unit), QPointF(5.5 * unit, 10.5 * unit));
            break;
        case Kind::Unknown:
            p.setPen(QPen(Theme::color(Theme::Role::Hint), unit, Qt::DashLine));
            p.setBrush(Qt::NoBrush);
            p.drawEllipse(dot);
            p.setPen(Theme::color(Theme::Role::Hint));
            p.drawText(dot, Qt::AlignCenter, QStringLiteral("?"));
            break;
        }
        p.end();
        result.addPixmap(pixmap);
    }
    return result;
}

} // namespace jumo
