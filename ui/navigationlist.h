// The window's page list: the fixed pages (overview, traffic, journal, audit log), then
// the devices, grouped under a row per line (its name and state) while there are several
// lines. Rows carry the device or line they stand for, never a position to count on.
#pragma once

#include "bus/bus.h"

#include <QListWidget>

namespace jumo {

class StationLine;

class NavigationList : public QListWidget
{
    Q_OBJECT

public:
    struct Device
    {
        DeviceId id;
        QString text;
    };
    struct Group
    {
        StationLine *line;
        QList<Device> devices;
    };

    NavigationList(const QStringList &pages, QWidget *parent = nullptr);

    int pageCount() const { return m_pages; }
    // Makes the line and device rows again; the row shown stays chosen.
    void setGroups(const QList<Group> &groups, bool headers);
    DeviceId deviceAt(int row) const;
    // The line of a line's row or of a device's row, nullptr for a page.
    StationLine *lineAt(int row) const;
    bool isLineRow(int row) const;
    int rowOf(DeviceId id) const;
    int rowOfLine(const StationLine *line) const;
    // The row of the n-th device (1-based), -1 when there are fewer.
    int deviceRow(int n) const;
    // The line's row says its name and state in words, with an icon of its shape.
    void updateLine(StationLine *line);

private:
    int m_pages;
};

} // namespace jumo
