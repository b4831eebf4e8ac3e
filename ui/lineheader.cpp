#include "lineheader.h"

#include "elidedlabel.h"
#include "stationline.h"
#include "theme.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>

namespace jumo {

LineHeader::LineHeader(StationLine *line, QWidget *parent)
    : QFrame(parent), m_line(line), m_lineName(line->name()), m_name(new QLabel(this)),
      m_address(new ElidedLabel(this)), m_state(new ElidedLabel(this))
{
    build();
    connect(line, &StationLine::stateChanged, this, &LineHeader::refresh);
    connect(line, &StationLine::changed, this, &LineHeader::refresh);
    refresh();
}

LineHeader::LineHeader(const QString &name, QWidget *parent)
    : QFrame(parent), m_lineName(name), m_name(new QLabel(this)), m_address(new ElidedLabel(this)),
      m_state(new ElidedLabel(this))
{
    build();
    display(QString(), 0, LineState::Disconnected, tr("Disconnected"));
}

void LineHeader::build()
{
    setObjectName(QStringLiteral("lineHeader_") + m_lineName);
    m_name->setObjectName(QStringLiteral("lineName"));
    m_address->setObjectName(QStringLiteral("lineAddress"));
    m_state->setObjectName(QStringLiteral("lineHeaderState"));
    QFont bold = m_name->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.15);
    m_name->setFont(bold);
    QFont stateFont = m_state->font();
    stateFont.setBold(true);
    m_state->setFont(stateFont);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 3, 8, 3);
    layout->setSpacing(12);
    layout->addWidget(m_name);
    layout->addWidget(m_address, 1);
    layout->addWidget(m_state, 2);
    setCursor(Qt::PointingHandCursor);
}

QString LineHeader::stateText() const
{
    return m_state->fullText();
}

void LineHeader::refresh()
{
    if (!m_line)
        return;
    m_lineName = m_line->name();
    display(m_line->settings().portName, int(m_line->bus()->devices().size()), m_line->state(), m_line->stateText());
}

void LineHeader::display(const QString &address, int devices, LineState state, const QString &stateText)
{
    setObjectName(QStringLiteral("lineHeader_") + m_lineName);
    m_name->setText(m_lineName);
    m_address->setFullText(tr("%1, devices: %2").arg(address).arg(devices));
    // A mark that says the state without its colour: a filled dot, a cross, a ring.
    QString mark;
    Theme::Role band = Theme::Role::NeutralBanner;
    Theme::Role text = Theme::Role::NeutralBannerText;
    switch (state) {
    case LineState::Connected:
        mark = QStringLiteral("\u25CF ");
        band = Theme::Role::TileOk;
        text = Theme::Role::TileText;
        break;
    case LineState::Lost:
        mark = QStringLiteral("\u2716 ");
        band = Theme::Role::ErrorBanner;
        text = Theme::Role::ErrorBannerText;
        break;
    case LineState::Disconnected:
        mark = QStringLiteral("\u25CB ");
        break;
    }
    m_state->setFullText(mark + stateText);
    setToolTip(QStringLiteral("%1\n%2\n%3").arg(m_lineName, address, stateText));
    setStyleSheet(QStringLiteral("jumo--LineHeader { background: %1; border-radius: 3px }"
                                 " QLabel { color: %2; background: transparent }")
                          .arg(Theme::color(band).name(), Theme::color(text).name()));
}

void LineHeader::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && rect().contains(event->position().toPoint()))
        emit activated(m_line);
    QFrame::mouseReleaseEvent(event);
}

} // namespace jumo
