// What the views of one line show, device by device and view by view: the union is what
// the scheduler reads sooner. A view that shows nothing any more is forgotten.
#pragma once

#include "bus/devicesource.h"

#include <QHash>
#include <QSet>

#include <functional>

namespace jumo {

class ShownViews final : public ShownEntries
{
public:
    // Called with a device and everything its views show now, whenever that changes.
    using Changed = std::function<void(DeviceId, const QSet<QString> &)>;

    explicit ShownViews(Changed changed) : m_changed(std::move(changed)) { }

    void setShown(const void *view, DeviceId device, const QStringList &entryIds) override;
    void forgetDevice(DeviceId device) { m_shown.remove(device); }
    QSet<QString> shown(DeviceId device) const;

private:
    QHash<DeviceId, QHash<const void *, QStringList>> m_shown;
    Changed m_changed;
};

} // namespace jumo
