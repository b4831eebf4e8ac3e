// The control-room overview: one faceplate per device, as many columns as the width
// holds, grouped by line under a header per line (shown while there are several lines).
// It turns compact by itself when the comfortable faceplates would need scrolling
// (31 devices on a 1920x1080 screen), or always when the user asks for it; on a screen
// with room to spare the faceplates grow, up to twice their size.
#pragma once

#include "devicetile.h"

#include <QWidget>

class QGridLayout;
class QScrollArea;

namespace jumo {

class OverviewPage : public QWidget
{
    Q_OBJECT

public:
    explicit OverviewPage(QWidget *parent = nullptr);

    // A group's header (a line's); its faceplates follow it, groups in the order added.
    void addGroup(QWidget *header);
    // Deletes the header; the group's faceplates must be gone before.
    void removeGroup(QWidget *header);
    // Headers take a row each while shown (several lines), none while hidden.
    void setHeadersShown(bool shown);
    bool headersShown() const { return m_headersShown; }
    // Scrolls the group's header into view.
    void showGroup(QWidget *header);
    // Adds the faceplate at the end of the header's group (nullptr: a group without header).
    void addTile(DeviceTile *tile, QWidget *group = nullptr);
    // Deletes the faceplate.
    void removeTile(DeviceTile *tile);
    // The group's faceplates in this order (the same ones), and the groups in this order.
    void setGroupTiles(QWidget *group, const QList<DeviceTile *> &tiles);
    void setGroupOrder(const QList<QWidget *> &headers);
    // Every faceplate, in the order shown.
    QList<DeviceTile *> tiles() const;
    void setAlwaysCompact(bool compact);
    bool alwaysCompact() const { return m_alwaysCompact; }
    DeviceTile::Density density() const { return m_density; }
    int columns() const { return m_columns; }
    // How much larger than their own size the faceplates are drawn (1 to 2).
    double scale() const { return m_scale; }
    QScrollArea *scrollArea() const { return m_scroll; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    bool event(QEvent *event) override;

private:
    // Places the faceplates again when the density or the columns change (or always).
    void relayout(bool force = false);
    int columnsFor(DeviceTile::Density density, double scale, int width) const;
    int heightFor(DeviceTile::Density density, double scale, int columns) const;

    QScrollArea *m_scroll;
    QWidget *m_inner;
    QGridLayout *m_grid;
    struct Group
    {
        QWidget *header = nullptr;
        QList<DeviceTile *> tiles;
    };
    int headerHeight(const Group &group) const;

    QList<Group> m_groups;
    bool m_headersShown = false;
    bool m_alwaysCompact = false;
    DeviceTile::Density m_density = DeviceTile::Density::Comfortable;
    double m_scale = 1;
    int m_columns = 0;
};

} // namespace jumo
