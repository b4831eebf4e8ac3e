#include "models/writecommand.h"

namespace jumo {

WriteCommand::WriteCommand(Bus *bus, DeviceId device, const QString &entryId, QObject *parent)
    : QObject(parent), m_bus(bus), m_device(device), m_entryId(entryId)
{
    connect(m_bus, &Bus::writeFinished, this, [this](int ticket, const WriteOutcome &outcome) {
        if (ticket != m_ticket)
            return;
        m_ticket = -1;
        setState(stateOf(outcome), outcome.message);
    });
}

WriteCommand::State WriteCommand::stateOf(const WriteOutcome &outcome)
{
    switch (outcome.result) {
    case WriteOutcome::Result::Confirmed:
    case WriteOutcome::Result::Accepted:
        return State::Confirmed;
    case WriteOutcome::Result::Unknown:
    case WriteOutcome::Result::Unverified:
        return State::Unknown;
    case WriteOutcome::Result::Mismatch:
    case WriteOutcome::Result::Refused:
    case WriteOutcome::Result::NotSent:
    case WriteOutcome::Result::ReadOnlyMode:
    case WriteOutcome::Result::Invalid:
        break;
    }
    return State::Refused;
}

void WriteCommand::write(const QString &value)
{
    setState(State::Pending, tr("Writing %1...").arg(value));
    m_ticket = m_bus->write(m_device, m_entryId, value);
}

void WriteCommand::writeBits(const QHash<QString, bool> &bits, const QString &description)
{
    setState(State::Pending, tr("Writing %1...").arg(description));
    m_ticket = m_bus->writeBits(m_device, m_entryId, bits);
}

void WriteCommand::setState(State state, const QString &message)
{
    m_state = state;
    m_message = message;
    emit stateChanged(state, message);
}

} // namespace jumo
