#include "devicetile.h"

#include "models/alarmbitsmodel.h"
#include "models/livevaluesmodel.h"
#include "models/valuetext.h"
#include "protocol/registermap.h"
#include "theme.h"

#include <QCoreApplication>
#include <QKeyEvent>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QVBoxLayout>

namespace jumo {

DeviceTile::DeviceTile(DeviceId device, const RegisterMap &map, quint8 address, LiveValuesModel *values,
                       AlarmBitsModel *alarms, QWidget *parent)
    : QFrame(parent), m_device(device), m_map(map), m_values(values), m_alarms(alarms), m_title(new QLabel(this)),
      m_state(new QLabel(this)), m_keyValues(new QLabel(this)), m_alarmLabel(new QLabel(this))
{
    setObjectName(QStringLiteral("tile_%1_%2").arg(map.family).arg(address));
    setFrameShape(QFrame::StyledPanel);
    setCursor(Qt::PointingHandCursor);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumWidth(260);
    m_title->setText(QStringLiteral("<b>%1</b><br>%2").arg(map.name.toHtmlEscaped(), tr("address %1").arg(address)));
    m_title->setWordWrap(true);
    m_state->setObjectName(QStringLiteral("deviceState"));
    m_keyValues->setObjectName(QStringLiteral("keyValues"));
    m_keyValues->setWordWrap(true);
    m_state->setWordWrap(true);
    m_alarmLabel->setWordWrap(true);
    m_alarmLabel->setObjectName(QStringLiteral("alarmCount"));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_state);
    layout->addWidget(m_keyValues);
    layout->addWidget(m_alarmLabel);
    layout->addStretch();
    connect(m_values, &QAbstractItemModel::dataChanged, this, &DeviceTile::refresh);
    connect(m_alarms, &AlarmBitsModel::activeAlarmsChanged, this, &DeviceTile::refresh);
    connect(m_alarms, &AlarmBitsModel::alarmsKnownChanged, this, &DeviceTile::refresh);
    refresh();
}

void DeviceTile::setCondition(const DeviceCondition &condition)
{
    m_condition = condition;
    refresh();
}

QString DeviceTile::valuesText() const
{
    return m_keyValues->text();
}

QString DeviceTile::stateText() const
{
    return m_stateText;
}

QString DeviceTile::alarmText() const
{
    return m_alarmLabel->text();
}

void DeviceTile::refresh()
{
    if (!isVisible()) {
        m_dirty = true;   // caught up in showEvent()
        return;
    }
    m_dirty = false;
    // Each key value as the live table shows it: no number when unknown, marked when stale.
    QStringList lines;
    for (const QString &id : m_map.overview) {
        const int row = m_values->rowOf(id);
        if (row < 0)
            continue;
        const RegisterEntry *e = m_map.entry(id);
        const QModelIndex index = m_values->index(row, LiveValuesModel::ValueColumn);
        const auto validity = Validity(index.data(LiveValuesModel::ValidityRole).toInt());
        QString value = index.data(LiveValuesModel::ValueWithUnitRole).toString();
        if (validity == Validity::Stale)
            value += QLatin1Char(' ') + tr("(stale)");
        lines << QStringLiteral("%1: %2").arg(QCoreApplication::translate("jumo::maps", e->label.toUtf8().constData()),
                                              value);
    }
    const QString text = lines.join(QLatin1Char('\n'));
    if (m_keyValues->text() != text)
        m_keyValues->setText(text);

    const QString state = conditionText(m_condition);
    // Colour from the theme, and a border of its own per state, so the state reads
    // without colour too (and the state is written out in words above the values).
    std::optional<Theme::Role> role;
    QString border = QStringLiteral("1px solid");
    switch (m_condition.state) {
    case DeviceCondition::State::Online:
        break;
    case DeviceCondition::State::Offline:
    case DeviceCondition::State::LineLost:
        role = Theme::Role::TileOffline;
        border = QStringLiteral("2px dashed");
        break;
    case DeviceCondition::State::Disconnected:
    case DeviceCondition::State::Identifying:
        role = Theme::Role::TileIdle;
        border = QStringLiteral("1px dotted");
        break;
    case DeviceCondition::State::WrongDevice:
        role = Theme::Role::TileWrongDevice;
        border = QStringLiteral("4px double");
        break;
    }
    const int alarms = m_alarms->activeAlarms();
    const bool known = m_alarms->alarmsKnown() && m_condition.isOnline();
    const bool stale = known && m_alarms->alarmsStale();
    const QString alarmText = alarmsText(m_condition, *m_alarms);
    // Green only for a live "no alarm".
    if (!role) {
        if (alarms && known) {
            role = Theme::Role::TileAlarm;
            border = QStringLiteral("3px solid");
        } else if (!known || stale) {
            role = Theme::Role::TileUncertain;
            border = QStringLiteral("2px dotted");
        } else {
            role = Theme::Role::TileOk;
        }
    }
    QColor edge = Theme::color(Theme::Role::TileText);
    if (Theme::current() != Theme::Kind::HighContrast && border.startsWith(QLatin1Char('1')))
        edge.setAlpha(90);
    const QString stateHtml = m_condition.isOnline() ? state.toHtmlEscaped()
                                                     : QStringLiteral("<b>%1</b>").arg(state.toHtmlEscaped());
    m_stateText = state;
    if (m_state->text() != stateHtml)
        m_state->setText(stateHtml);
    m_state->setToolTip(m_condition.detail);
    if (m_alarmLabel->text() != alarmText)
        m_alarmLabel->setText(alarmText);
    // An unanswering device's values are greyed as well as blanked.
    m_keyValues->setEnabled(m_condition.isOnline());
    const QString sheet = QStringLiteral("jumo--DeviceTile { background: %1; border: %2 rgba(%3, %4, %5, %6); } "
                                         "QLabel:!disabled { color: %7; }")
                                  .arg(Theme::color(*role).name(), border)
                                  .arg(edge.red())
                                  .arg(edge.green())
                                  .arg(edge.blue())
                                  .arg(edge.alpha())
                                  .arg(Theme::color(Theme::Role::TileText).name());
    if (styleSheet() != sheet)   // re-styling is costly: only when the colour changes
        setStyleSheet(sheet);
}

QString DeviceTile::conditionText(const DeviceCondition &condition)
{
    const QString since = condition.since.isValid() ? QLocale().toString(condition.since.time(), QStringLiteral("HH:mm:ss"))
                                                    : QString();
    switch (condition.state) {
    case DeviceCondition::State::Online:
        return tr("Online");
    case DeviceCondition::State::Offline:
        return tr("Not answering since %1").arg(since);
    case DeviceCondition::State::LineLost:
        return tr("Line lost since %1").arg(since);
    case DeviceCondition::State::Disconnected:
        return tr("Line disconnected");
    case DeviceCondition::State::Identifying:
        return tr("Checking identity");
    case DeviceCondition::State::WrongDevice:
        return tr("Wrong device since %1").arg(since);
    }
    return {};
}

QString DeviceTile::alarmsText(const DeviceCondition &condition, const AlarmBitsModel &alarms)
{
    // "No alarm" only when every alarm word is known; otherwise nobody can say.
    const bool known = alarms.alarmsKnown() && condition.isOnline();
    QString text = known ? tr("%n active alarm(s)", nullptr, alarms.activeAlarms()) : tr("Alarms unknown");
    if (known && alarms.alarmsStale())
        text += QLatin1Char(' ') + tr("(stale)");
    return text;
}

void DeviceTile::mouseReleaseEvent(QMouseEvent *event)
{
    QFrame::mouseReleaseEvent(event);
    emit activated(m_device);
}

void DeviceTile::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_Return:
    case Qt::Key_Enter:
    case Qt::Key_Space:
        emit activated(m_device);
        return;
    default:
        QFrame::keyPressEvent(event);
    }
}

void DeviceTile::paintEvent(QPaintEvent *event)
{
    QFrame::paintEvent(event);
    if (!hasFocus())
        return;
    // The tile with the keyboard focus has a frame in the highlight colour inside its
    // border, plain to see across a room (the style's own focus mark is faint).
    QPainter painter(this);
    painter.setPen(QPen(palette().color(QPalette::Highlight), 3));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(QRectF(rect()).adjusted(2.5, 2.5, -2.5, -2.5));
}

void DeviceTile::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_dirty)
        refresh();
}

} // namespace jumo
