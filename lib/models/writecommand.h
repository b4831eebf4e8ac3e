// One write the user asks for, and what became of it: pending, confirmed by read-back,
// accepted without one, or refused with the reason. Controls show its state.
#pragma once

#include "bus/bus.h"

#include <QObject>

namespace jumo {

class WriteCommand : public QObject
{
    Q_OBJECT

public:
    enum class State { Idle, Pending, Confirmed, Refused };
    Q_ENUM(State)

    WriteCommand(Bus *bus, DeviceId device, const QString &entryId, QObject *parent = nullptr);

    void write(const QString &value);
    State state() const { return m_state; }
    QString message() const { return m_message; }
    QString entryId() const { return m_entryId; }

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
