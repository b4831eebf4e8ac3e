#include "navigationlist.h"

#include "devicestateicon.h"
#include "stationline.h"

namespace jumo {

namespace {
constexpr int DeviceRole = Qt::UserRole + 1;
constexpr int LineRole = Qt::UserRole + 2;
constexpr int LineRowRole = Qt::UserRole + 3;
}

NavigationList::NavigationList(const QStringList &pages, QWidget *parent)
    : QListWidget(parent), m_pages(int(pages.size()))
{
    for (const QString &page : pages) {
        auto *item = new QListWidgetItem(page, this);
        item->setToolTip(page);
    }
}

void NavigationList::setGroups(const QList<Group> &groups, bool headers)
{
    const DeviceId shownDevice = deviceAt(currentRow());
    StationLine *shownLine = isLineRow(currentRow()) ? lineAt(currentRow()) : nullptr;
    const int shownPage = currentRow() < m_pages ? currentRow() : -1;
    {
        const QSignalBlocker blocker(this);
        while (count() > m_pages)
            delete takeItem(count() - 1);
        for (const Group &g : groups) {
            if (headers) {
                auto *item = new QListWidgetItem(this);
                item->setData(LineRole, QVariant::fromValue<void *>(g.line));
                item->setData(LineRowRole, true);
                QFont bold = font();
                bold.setBold(true);
                item->setFont(bold);
                updateLine(g.line);
            }
            for (const Device &d : g.devices) {
                // Indented under their line's row while there are several lines.
                auto *item = new QListWidgetItem(headers ? QStringLiteral("   ") + d.text : d.text, this);
                item->setData(DeviceRole, d.id);
                item->setData(LineRole, QVariant::fromValue<void *>(g.line));
            }
        }
        int row = shownPage;
        if (shownDevice)
            row = rowOf(shownDevice);
        else if (shownLine)
            row = rowOfLine(shownLine);
        setCurrentRow(row >= 0 ? row : 0);
    }
    // The page shown goes when its row went.
    if ((shownDevice && rowOf(shownDevice) < 0) || (shownLine && rowOfLine(shownLine) < 0))
        emit currentRowChanged(currentRow());
}

DeviceId NavigationList::deviceAt(int row) const
{
    const QListWidgetItem *i = item(row);
    return i ? i->data(DeviceRole).value<DeviceId>() : 0;
}

StationLine *NavigationList::lineAt(int row) const
{
    const QListWidgetItem *i = item(row);
    return i ? static_cast<StationLine *>(i->data(LineRole).value<void *>()) : nullptr;
}

bool NavigationList::isLineRow(int row) const
{
    const QListWidgetItem *i = item(row);
    return i && i->data(LineRowRole).toBool();
}

int NavigationList::rowOf(DeviceId id) const
{
    for (int row = m_pages; row < count(); ++row) {
        if (deviceAt(row) == id)
            return row;
    }
    return -1;
}

int NavigationList::rowOfLine(const StationLine *line) const
{
    for (int row = m_pages; row < count(); ++row) {
        if (isLineRow(row) && lineAt(row) == line)
            return row;
    }
    return -1;
}

int NavigationList::deviceRow(int n) const
{
    for (int row = m_pages; row < count(); ++row) {
        if (deviceAt(row) && --n == 0)
            return row;
    }
    return -1;
}

void NavigationList::updateLine(StationLine *line)
{
    const int row = rowOfLine(line);
    QListWidgetItem *i = item(row);
    if (!i)
        return;
    DeviceStateIcon::Kind kind = DeviceStateIcon::Kind::Unknown;
    QString state;
    switch (line->state()) {
    case LineState::Connected:
        kind = DeviceStateIcon::Kind::Online;
        state = tr("connected");
        break;
    case LineState::Lost:
        kind = DeviceStateIcon::Kind::Offline;
        state = tr("lost");
        break;
    case LineState::Disconnected:
        state = tr("disconnected");
        break;
    }
    i->setText(tr("%1 (%2)").arg(line->name(), state));
    i->setIcon(DeviceStateIcon::icon(kind));
    i->setToolTip(QStringLiteral("%1\n%2\n%3").arg(line->name(), line->settings().portName, line->stateText()));
}

} // namespace jumo
