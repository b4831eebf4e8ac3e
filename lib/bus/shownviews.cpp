#include "bus/shownviews.h"

namespace jumo {

void ShownViews::setShown(const void *view, DeviceId device, const QStringList &entryIds)
{
    const QSet<QString> before = shown(device);
    QHash<const void *, QStringList> &views = m_shown[device];
    if (entryIds.isEmpty())
        views.remove(view);
    else
        views.insert(view, entryIds);
    if (views.isEmpty())
        m_shown.remove(device);
    const QSet<QString> after = shown(device);
    if (after != before && m_changed)
        m_changed(device, after);
}

QSet<QString> ShownViews::shown(DeviceId device) const
{
    QSet<QString> ids;
    for (const QStringList &entries : m_shown.value(device))
        ids.unite(QSet<QString>(entries.cbegin(), entries.cend()));
    return ids;
}

} // namespace jumo
