// The control-room overview: one faceplate per device, as many columns as the width
// holds. It turns compact by itself when the comfortable faceplates would need scrolling
// (31 devices on a 1920x1080 screen), or always when the user asks for it.
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

    void addTile(DeviceTile *tile);
    void removeTile(DeviceTile *tile);
    void setAlwaysCompact(bool compact);
    bool alwaysCompact() const { return m_alwaysCompact; }
    DeviceTile::Density density() const { return m_density; }
    int columns() const { return m_columns; }
    QScrollArea *scrollArea() const { return m_scroll; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    bool event(QEvent *event) override;

private:
    // Places the faceplates again when the density or the columns change (or always).
    void relayout(bool force = false);
    int columnsFor(DeviceTile::Density density, int width) const;
    int heightFor(DeviceTile::Density density, int columns) const;

    QScrollArea *m_scroll;
    QWidget *m_inner;
    QGridLayout *m_grid;
    QList<DeviceTile *> m_tiles;
    bool m_alwaysCompact = false;
    DeviceTile::Density m_density = DeviceTile::Density::Comfortable;
    int m_columns = 0;
};

} // namespace jumo
