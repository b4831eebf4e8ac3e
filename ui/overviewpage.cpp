#include "overviewpage.h"

#include <QEvent>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <QGridLayout>
#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>

namespace jumo {

namespace {
constexpr int spacing = 6;
constexpr int margin = 6;
// Faceplates grow on a large screen in steps of a quarter, to twice their size at most:
// beyond that a control room reads them from across the room no better. They keep their
// own size up to the room a 1600x1000 page gives them and grow with what is beyond, so
// four devices on a desk's screen do not turn into posters.
constexpr double scaleStep = 0.25;
constexpr double largestScale = 2.0;
constexpr int ownSizeWidth = 1600;
constexpr int ownSizeHeight = 1000;
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

void OverviewPage::addGroup(QWidget *header)
{
    header->setParent(m_inner);
    header->setVisible(m_headersShown);
    m_groups << Group{header, {}};
    relayout(true);
}

void OverviewPage::removeGroup(QWidget *header)
{
    for (qsizetype i = 0; i < m_groups.size(); ++i) {
        if (m_groups[i].header == header) {
            for (DeviceTile *tile : std::as_const(m_groups[i].tiles))
                delete tile;
            m_groups.removeAt(i);
            break;
        }
    }
    delete header;
    relayout(true);
}

void OverviewPage::setHeadersShown(bool shown)
{
    if (shown == m_headersShown)
        return;
    m_headersShown = shown;
    relayout(true);
}

void OverviewPage::showGroup(QWidget *header)
{
    if (header && header->isVisible())
        m_scroll->ensureWidgetVisible(header, 0, margin);
}

void OverviewPage::addTile(DeviceTile *tile, QWidget *group)
{
    auto it = std::find_if(m_groups.begin(), m_groups.end(), [group](const Group &g) { return g.header == group; });
    if (it == m_groups.end()) {
        m_groups.prepend(Group{group, {}});
        it = m_groups.begin();
    }
    it->tiles << tile;
    relayout(true);
}

void OverviewPage::removeTile(DeviceTile *tile)
{
    for (Group &g : m_groups)
        g.tiles.removeAll(tile);
    delete tile;
    relayout(true);
}

void OverviewPage::setGroupTiles(QWidget *group, const QList<DeviceTile *> &tiles)
{
    for (Group &g : m_groups) {
        if (g.header == group && g.tiles != tiles && QSet<DeviceTile *>(g.tiles.cbegin(), g.tiles.cend())
                    == QSet<DeviceTile *>(tiles.cbegin(), tiles.cend())) {
            g.tiles = tiles;
            relayout(true);
        }
    }
}

void OverviewPage::setGroupOrder(const QList<QWidget *> &headers)
{
    QList<Group> ordered;
    for (QWidget *header : headers) {
        const auto it = std::find_if(m_groups.cbegin(), m_groups.cend(), [header](const Group &g) { return g.header == header; });
        if (it != m_groups.cend())
            ordered << *it;
    }
    // Groups not named keep their place after the named ones.
    for (const Group &g : std::as_const(m_groups)) {
        if (!headers.contains(g.header))
            ordered << g;
    }
    const bool same = std::equal(ordered.cbegin(), ordered.cend(), m_groups.cbegin(), m_groups.cend(),
                                 [](const Group &a, const Group &b) { return a.header == b.header; });
    if (same)
        return;
    m_groups = ordered;
    relayout(true);
}

QList<DeviceTile *> OverviewPage::tiles() const
{
    QList<DeviceTile *> all;
    for (const Group &g : m_groups)
        all << g.tiles;
    return all;
}

int OverviewPage::headerHeight(const Group &group) const
{
    return m_headersShown && group.header ? group.header->sizeHint().height() : 0;
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

int OverviewPage::columnsFor(DeviceTile::Density density, double scale, int width) const
{
    const QList<DeviceTile *> all = tiles();
    if (all.isEmpty())
        return 1;
    const int tileWidth = all.first()->sizeHintFor(density, scale).width();
    return std::max(1, (width - 2 * margin + spacing) / (tileWidth + spacing));
}

int OverviewPage::heightFor(DeviceTile::Density density, double scale, int columns) const
{
    // Rows are as high as their highest faceplate; a shown header is a row of its own.
    int height = 2 * margin;
    bool first = true;
    for (const Group &g : m_groups) {
        if (const int header = headerHeight(g)) {
            height += header + (first ? 0 : spacing);
            first = false;
        }
        const QList<DeviceTile *> &tiles = g.tiles;
        for (qsizetype start = 0; start < tiles.size(); start += columns) {
            int row = 0;
            for (qsizetype i = start; i < std::min(tiles.size(), start + columns); ++i)
                row = std::max(row, tiles[i]->sizeHintFor(density, scale).height());
            height += row + (first ? 0 : spacing);
            first = false;
        }
    }
    return height;
}

void OverviewPage::relayout(bool force)
{
    const int width = m_scroll->viewport()->width();
    const int height = m_scroll->viewport()->height();
    // Comfortable while everything fits without scrolling, else compact; comfortable ones
    // as large as the room allows without scrolling.
    DeviceTile::Density density = DeviceTile::Density::Comfortable;
    double scale = 1;
    auto fits = [this, width, height](DeviceTile::Density d, double s) {
        return heightFor(d, s, columnsFor(d, s, width)) <= height;
    };
    if (m_alwaysCompact || !fits(density, 1)) {
        density = DeviceTile::Density::Compact;
    } else {
        const double room = std::min({largestScale, double(width) / ownSizeWidth, double(height) / ownSizeHeight});
        for (double s = std::floor(room / scaleStep) * scaleStep; s > 1; s -= scaleStep) {
            if (fits(density, s)) {
                scale = s;
                break;
            }
        }
    }
    const int columns = columnsFor(density, scale, width);
    if (!force && density == m_density && columns == m_columns && scale == m_scale)
        return;
    m_density = density;
    m_scale = scale;
    m_columns = columns;
    while (m_grid->count())
        delete m_grid->takeAt(0);
    for (int c = 0; c < m_grid->columnCount(); ++c)
        m_grid->setColumnStretch(c, 0);
    for (int r = 0; r < m_grid->rowCount(); ++r)
        m_grid->setRowStretch(r, 0);
    int row = 0;
    for (const Group &g : std::as_const(m_groups)) {
        if (g.header) {
            g.header->setVisible(m_headersShown);
            if (m_headersShown)
                m_grid->addWidget(g.header, row++, 0, 1, columns);
        }
        for (qsizetype i = 0; i < g.tiles.size(); ++i) {
            g.tiles[i]->setDensity(density);
            g.tiles[i]->setScale(scale);
        }
        for (qsizetype start = 0; start < g.tiles.size(); start += columns) {
            // The faceplates of a row are as high as its highest: a row reads as one line
            // of boxes, whichever kinds of device it holds.
            const qsizetype end = std::min(g.tiles.size(), start + columns);
            int rowHeight = 0;
            for (qsizetype i = start; i < end; ++i)
                rowHeight = std::max(rowHeight, g.tiles[i]->sizeHint().height());
            for (qsizetype i = start; i < end; ++i) {
                g.tiles[i]->setFixedHeight(rowHeight);
                m_grid->addWidget(g.tiles[i], row + int(i) / columns, int(i) % columns, Qt::AlignTop);
            }
        }
        row += int(g.tiles.size() + columns - 1) / columns;
    }
    for (int c = 0; c < columns; ++c)
        m_grid->setColumnStretch(c, 1);
    m_grid->setRowStretch(row, 1);
}

} // namespace jumo
