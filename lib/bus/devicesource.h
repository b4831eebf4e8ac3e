// What models and views read about the devices of one line, whoever feeds it: the Bus
// that polls them, or a mirror of what a station publishes. It has no write path: only
// the Bus writes, so a view given nothing but a DeviceSource cannot change a device.
#pragma once

#include "bus/entrystate.h"
#include "protocol/registermap.h"

#include <QDateTime>
#include <QObject>
#include <QStringList>

#include <memory>

namespace jumo {

using DeviceId = int;

enum class LineState { Disconnected, Connected, Lost };

// Whether a device can be heard, and since when (wall-clock time, for people).
struct DeviceCondition
{
    // Identifying: the device answers and is being checked to be of its family;
    // WrongDevice: a device of another family answers (detail names it).
    enum class State { Online, Offline, LineLost, Disconnected, Identifying, WrongDevice };
    State state = State::Disconnected;
    QDateTime since;
    QString detail;

    bool isOnline() const { return state == State::Online; }
};

// What the views of a line show, so the line reads it sooner: a Bus reads the entries a
// view shows sooner while it shows them (a setting as a live value, a live value ahead of
// the other live values). A mirror of a station has no line to hurry.
class ShownEntries
{
public:
    virtual ~ShownEntries() = default;
    // What this view shows of the device from now on (empty: nothing any more).
    virtual void setShown(const void *view, DeviceId device, const QStringList &entryIds) = 0;
};

class DeviceSource : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;

    virtual QList<DeviceId> devices() const = 0;
    virtual std::shared_ptr<const RegisterMap> deviceMap(DeviceId id) const = 0;
    virtual quint8 deviceAddress(DeviceId id) const = 0;
    // "ipc300@1", the name of a device in logs and messages.
    virtual QString deviceName(DeviceId id) const = 0;
    // Null for an unknown device or entry.
    virtual const EntryState *entryState(DeviceId id, const QString &entryId) const = 0;
    virtual DeviceCondition condition(DeviceId id) const = 0;
    virtual LineState state() const = 0;
    // The monotonic clock of EntryState times.
    virtual qint64 clockMs() const = 0;
    // Where views say what they show (null: nothing to hurry).
    virtual ShownEntries *shownEntries() const { return nullptr; }

signals:
    // Values or validity of these entries changed (one signal per poll block).
    void entriesUpdated(jumo::DeviceId id, const QStringList &entryIds);
    // Online, offline, line lost, disconnected: communication with the device changed.
    void conditionChanged(jumo::DeviceId id, const jumo::DeviceCondition &condition);
    void stateChanged(jumo::LineState state);
};

} // namespace jumo
