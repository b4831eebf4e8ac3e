// What the views of one model show of its device, told to the line the values come from:
// the line reads those entries sooner while they are on screen. A view that is hidden or
// destroyed shows nothing any more; so does every view when this goes.
#pragma once

#include "bus/devicesource.h"

#include <QObject>
#include <QPointer>
#include <QSet>

namespace jumo {

class ViewInterest : public QObject
{
    Q_OBJECT

public:
    ViewInterest(const DeviceSource *source, DeviceId device, QObject *parent = nullptr);
    ~ViewInterest() override;

    // This view shows these entries now (shown), or nothing any more.
    void setShown(const QObject *view, bool shown, const QStringList &entryIds);

private:
    void tell(const QObject *view, const QStringList &entryIds);

    QPointer<const DeviceSource> m_source;
    DeviceId m_device;
    QSet<const QObject *> m_views;
};

} // namespace jumo
