#include "overviewpage.h"

#include "devicetile.h"

#include <QGridLayout>
#include <QScrollArea>
#include <QVBoxLayout>

namespace jumo {

OverviewPage::OverviewPage(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("overview"));
    auto *inner = new QWidget;
    m_grid = new QGridLayout(inner);
    auto *scroll = new QScrollArea(this);
    scroll->setWidget(inner);
    scroll->setWidgetResizable(true);
    // Tab goes from tile to tile (the area scrolls to the one with the focus), not to the
    // scroll area itself.
    scroll->setFocusPolicy(Qt::NoFocus);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);
}

void OverviewPage::addTile(DeviceTile *tile)
{
    m_tiles << tile;
    relayout();
}

void OverviewPage::removeTile(DeviceTile *tile)
{
    m_tiles.removeAll(tile);
    delete tile;
    relayout();
}

void OverviewPage::relayout()
{
    const int columns = 3;
    for (int i = 0; i < m_tiles.size(); ++i)
        m_grid->addWidget(m_tiles[i], i / columns, i % columns, Qt::AlignTop);
    m_grid->setRowStretch(int(m_tiles.size()) / columns + 1, 1);
}

} // namespace jumo
