#include "devicetile.h"

#include "models/alarmbitsmodel.h"
#include "models/livevaluesmodel.h"
#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QLabel>
#include <QVBoxLayout>

namespace jumo {

DeviceTile::DeviceTile(const RegisterMap &map, quint8 address, LiveValuesModel *values, AlarmBitsModel *alarms,
                       QWidget *parent)
    : QFrame(parent), m_map(map), m_values(values), m_alarms(alarms), m_title(new QLabel(this)),
      m_keyValues(new QLabel(this)), m_alarmLabel(new QLabel(this))
{
    setObjectName(QStringLiteral("tile_%1_%2").arg(map.family).arg(address));
    setFrameShape(QFrame::StyledPanel);
    setCursor(Qt::PointingHandCursor);
    setMinimumWidth(260);
    m_title->setText(QStringLiteral("<b>%1</b><br>%2").arg(map.name.toHtmlEscaped(), tr("address %1").arg(address)));
    m_title->setWordWrap(true);
    m_keyValues->setObjectName(QStringLiteral("keyValues"));
    m_alarmLabel->setObjectName(QStringLiteral("alarmCount"));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_keyValues);
    layout->addWidget(m_alarmLabel);
    layout->addStretch();
    connect(m_values, &QAbstractItemModel::dataChanged, this, &DeviceTile::refresh);
    connect(m_alarms, &AlarmBitsModel::activeAlarmsChanged, this, &DeviceTile::refresh);
    refresh();
}

void DeviceTile::setOnline(bool online)
{
    m_online = online;
    refresh();
}

QString DeviceTile::valuesText() const
{
    return m_keyValues->text();
}

void DeviceTile::refresh()
{
    if (!isVisible()) {
        m_dirty = true;   // caught up in showEvent()
        return;
    }
    m_dirty = false;
    QStringList lines;
    for (const QString &id : m_map.overview) {
        const int row = m_values->rowOf(id);
        if (row < 0)
            continue;
        const RegisterEntry *e = m_map.entry(id);
        const QString value = m_values->index(row, LiveValuesModel::ValueColumn).data().toString();
        lines << QStringLiteral("%1: %2 %3")
                         .arg(QCoreApplication::translate("jumo::maps", e->label.toUtf8().constData()),
                              value.isEmpty() ? QStringLiteral("-") : value, e->unit);
    }
    const QString text = lines.join(QLatin1Char('\n'));
    if (m_keyValues->text() != text)
        m_keyValues->setText(text);
    const int alarms = m_alarms->activeAlarms();
    QString state = m_online ? tr("%n active alarm(s)", nullptr, alarms) : tr("not answering");
    if (m_alarmLabel->text() != state)
        m_alarmLabel->setText(state);
    const QString colour = !m_online ? QStringLiteral("#e0e0e0") : alarms ? QStringLiteral("#ffd8d8") : QStringLiteral("#e3f4e3");
    const QString sheet = QStringLiteral("jumo--DeviceTile { background: %1; }").arg(colour);
    if (styleSheet() != sheet)   // re-styling is costly: only when the colour changes
        setStyleSheet(sheet);
}

void DeviceTile::mouseReleaseEvent(QMouseEvent *event)
{
    QFrame::mouseReleaseEvent(event);
    emit activated();
}

void DeviceTile::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_dirty)
        refresh();
}

} // namespace jumo
