#include "models/writecommand.h"

namespace jumo {

WriteCommand::WriteCommand(Bus *bus, DeviceId device, const QString &entryId, QObject *parent)
    : QObject(parent), m_bus(bus), m_device(device), m_entryId(entryId)
{
    connect(m_bus, &Bus::writeFinished, this, [this](int ticket, const WriteOutcome &outcome) {
        if (ticket != m_ticket)
            return;
        m_ticket = -1;
        setState(outcome.succeeded() ? State::Confirmed : State::Refused, outcome.message);
    });
}

void WriteCommand::write(const QString &value)
{
    setState(State::Pending, tr("Writing %1...").arg(value));
    m_ticket = m_bus->write(m_device, m_entryId, value);
}

void WriteCommand::setState(State state, const QString &message)
{
    m_state = state;
    m_message = message;
    emit stateChanged(state, message);
}

} // namespace jumo
