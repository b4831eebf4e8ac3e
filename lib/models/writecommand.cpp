#include "models/writecommand.h"

#include "protocol/valueformat.h"

namespace jumo {

WriteCommand::WriteCommand(Bus *bus, DeviceId device, const QString &entryId, QObject *parent)
    : QObject(parent), m_bus(bus), m_device(device), m_entryId(entryId)
{
    connect(m_bus, &Bus::writeFinished, this, [this](int ticket, const WriteOutcome &outcome) {
        if (ticket != m_ticket)
            return;
        m_ticket = -1;
        const bool readBack = outcome.result == WriteOutcome::Result::Confirmed && outcome.readBack.isOk();
        m_readBack = readBack ? outcome.readBack : DecodedValue{};
        m_readBackMs = readBack ? m_bus->clockMs() : -1;
        const std::shared_ptr<const RegisterMap> map = m_bus->deviceMap(m_device);
        setState(stateOf(outcome), messageOf(outcome, map ? map->entry(m_entryId) : nullptr, m_bitsDescription));
    });
}

QString WriteCommand::messageOf(const WriteOutcome &outcome, const RegisterEntry *entry, const QString &bitsDescription)
{
    switch (outcome.result) {
    case WriteOutcome::Result::Confirmed:
        if (!bitsDescription.isEmpty())
            return tr("confirmed by read-back: %1").arg(bitsDescription);
        if (entry && outcome.readBack.isOk())
            return tr("confirmed by read-back: %1").arg(ValueFormat::withUnit(outcome.readBack, *entry));
        break;
    case WriteOutcome::Result::Mismatch:
        if (!bitsDescription.isEmpty())
            return tr("written, but the device does not report %1").arg(bitsDescription);
        if (entry && outcome.readBack.status != ValueStatus::DecodeError)
            return tr("written, but the device reads back %1").arg(ValueFormat::withUnit(outcome.readBack, *entry));
        break;
    default:
        break;
    }
    return outcome.message;
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

const DecodedValue *WriteCommand::newerReadBack() const
{
    if (m_readBackMs < 0)
        return nullptr;
    const EntryState *state = m_bus->entryState(m_device, m_entryId);
    return state && state->hasValue() && state->goodMs > m_readBackMs ? nullptr : &m_readBack;
}

void WriteCommand::write(const QString &value, const QString &shown)
{
    m_bitsDescription.clear();
    setState(State::Pending, tr("Writing %1...").arg(shown.isEmpty() ? value : shown));
    m_ticket = m_bus->write(m_device, m_entryId, value);
}

void WriteCommand::writeBits(const QHash<QString, bool> &bits, const QString &description)
{
    m_bitsDescription = description;
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
