// One write the user asks for, and what became of it: pending, confirmed by read-back or
// acknowledged, refused with the reason, or unknown (the answer was lost, or the
// read-back could not be made): then only the device can tell. Controls show its state.
#pragma once

#include "bus/bus.h"

#include <QObject>

namespace jumo {

class WriteCommand : public QObject
{
    Q_OBJECT

public:
    enum class State { Idle, Pending, Confirmed, Refused, Unknown };
    Q_ENUM(State)

    WriteCommand(Bus *bus, DeviceId device, const QString &entryId, QObject *parent = nullptr);

    // The whole entry, its value as text.
    void write(const QString &value);
    // Some bits of a bit field (bit id -> on); the others keep the device's state.
    void writeBits(const QHash<QString, bool> &bits, const QString &description);
    State state() const { return m_state; }
    QString message() const { return m_message; }
    QString entryId() const { return m_entryId; }
    bool isPending() const { return m_ticket >= 0; }

    static State stateOf(const WriteOutcome &outcome);

signals:
    void stateChanged(jumo::WriteCommand::State state, const QString &message);

private:
    void setState(State state, const QString &message);

    Bus *m_bus;
    DeviceId m_device;
    QString m_entryId;
    int m_ticket = -1;
    State m_state = State::Idle;
    QString m_message;
};

} // namespace jumo
