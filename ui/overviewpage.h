// The control-room overview: one tile per device with its key values and alarm count,
// the view an operator leaves open all day.
#pragma once

#include <QWidget>

class QGridLayout;

namespace jumo {

class DeviceTile;

class OverviewPage : public QWidget
{
    Q_OBJECT

public:
    explicit OverviewPage(QWidget *parent = nullptr);

    void addTile(DeviceTile *tile);
    void removeTile(DeviceTile *tile);

private:
    void relayout();

    QGridLayout *m_grid;
    QList<DeviceTile *> m_tiles;
};

} // namespace jumo
