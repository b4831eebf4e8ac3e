#include "overviewpage.h"

#include <QEvent>

#include <algorithm>
#include <QGridLayout>
#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>

namespace jumo {

namespace {
constexpr int spacing = 6;
constexpr int margin = 6;
}

OverviewPage::OverviewPage(QWidget *parent)
    : QWidget(parent), m_scroll(new QScrollArea(this)), m_inner(new QWidget), m_grid(new QGridLayout(m_inner))
{
    setObjectName(QStringLiteral("overview"));
    m_grid->setSpacing(spacing);
    m_grid->setContentsMargins(margin, margin, margin, margin);
    m_scroll->setWidget(m_inner);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    // Faceplates take the width given; the page never scrolls sideways.
    m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // Tab goes from tile to tile (the area scrolls to the one with the focus), not to the
    // scroll area itself.
    m_scroll->setFocusPolicy(Qt::NoFocus);
    // The columns follow the viewport's width (it changes after this page's resize).
    m_scroll->viewport()->installEventFilter(this);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_scroll);
}

void OverviewPage::addTile(DeviceTile *tile)
{
    m_tiles << tile;
    relayout(true);
}

void OverviewPage::removeTile(DeviceTile *tile)
{
    m_tiles.removeAll(tile);
    delete tile;
    relayout(true);
}

void OverviewPage::setAlwaysCompact(bool compact)
{
    m_alwaysCompact = compact;
    relayout();
}

bool OverviewPage::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_scroll->viewport() && event->type() == QEvent::Resize)
        relayout();
    return QWidget::eventFilter(watched, event);
}

bool OverviewPage::event(QEvent *event)
{
    if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange)
        relayout();
    return QWidget::event(event);
}

int OverviewPage::columnsFor(DeviceTile::Density density, int width) const
{
    if (m_tiles.isEmpty())
        return 1;
    const int tileWidth = m_tiles.first()->sizeHintFor(density).width();
    return std::max(1, (width - 2 * margin + spacing) / (tileWidth + spacing));
}

int OverviewPage::heightFor(DeviceTile::Density density, int columns) const
{
    // Rows are as high as their highest faceplate.
    int height = 2 * margin;
    for (qsizetype first = 0; first < m_tiles.size(); first += columns) {
        int row = 0;
        for (qsizetype i = first; i < std::min(m_tiles.size(), first + columns); ++i)
            row = std::max(row, m_tiles[i]->sizeHintFor(density).height());
        height += row + (first ? spacing : 0);
    }
    return height;
}

void OverviewPage::relayout(bool force)
{
    const int width = m_scroll->viewport()->width();
    const int height = m_scroll->viewport()->height();
    // Comfortable while everything fits without scrolling, else compact.
    DeviceTile::Density density = DeviceTile::Density::Comfortable;
    if (m_alwaysCompact || heightFor(density, columnsFor(density, width)) > height)
        density = DeviceTile::Density::Compact;
    const int columns = columnsFor(density, width);
    if (!force && density == m_density && columns == m_columns)
        return;
    m_density = density;
    m_columns = columns;
    while (m_grid->count())
        delete m_grid->takeAt(0);
    for (int c = 0; c < m_grid->columnCount(); ++c)
        m_grid->setColumnStretch(c, 0);
    for (int r = 0; r < m_grid->rowCount(); ++r)
        m_grid->setRowStretch(r, 0);
    for (qsizetype i = 0; i < m_tiles.size(); ++i) {
        m_tiles[i]->setDensity(density);
        m_grid->addWidget(m_tiles[i], int(i) / columns, int(i) % columns, Qt::AlignTop);
    }
    for (int c = 0; c < columns; ++c)
        m_grid->setColumnStretch(c, 1);
    m_grid->setRowStretch(int(m_tiles.size() + columns - 1) / columns, 1);
}

} // namespace jumo
