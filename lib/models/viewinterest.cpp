#include "models/viewinterest.h"

namespace jumo {

ViewInterest::ViewInterest(const DeviceSource *source, DeviceId device, QObject *parent)
    : QObject(parent), m_source(source), m_device(device)
{
}

ViewInterest::~ViewInterest()
{
    for (const QObject *view : std::as_const(m_views))
        tell(view, {});
}

void ViewInterest::tell(const QObject *view, const QStringList &entryIds)
{
    if (ShownEntries *shown = m_source ? m_source->shownEntries() : nullptr)
        shown->setShown(view, m_device, entryIds);
}

void ViewInterest::setShown(const QObject *view, bool shown, const QStringList &entryIds)
{
    if (!view)
        return;
    if (shown && !entryIds.isEmpty()) {
        if (!m_views.contains(view)) {
            m_views.insert(view);
            connect(view, &QObject::destroyed, this, [this, view] {
                m_views.remove(view);
                tell(view, {});
            });
        }
        tell(view, entryIds);
        return;
    }
    if (m_views.remove(view))
        disconnect(view, &QObject::destroyed, this, nullptr);
    tell(view, {});
}

} // namespace jumo
