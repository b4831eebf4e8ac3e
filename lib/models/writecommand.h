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

    // The whole entry, its value as the codec takes it; shown as people read it ("25.0 °C",
    // "On"), the value itself when empty.
    void write(const QString &value, const QString &shown = QString());
    // Some bits of a bit field (bit id -> on); the others keep the device's state.
    // description names them as people do ("Output K1 on").
    void writeBits(const QHash<QString, bool> &bits, const QString &description);
    State state() const { return m_state; }
    QString message() const { return m_message; }
    QString entryId() const { return m_entryId; }
    bool isPending() const { return m_ticket >= 0; }
    // The value the last confirmed write read back, while no poll has read a newer one:
    // the device's value now, not the poll's of a moment before the write.
    const DecodedValue *newerReadBack() const;

    static State stateOf(const WriteOutcome &outcome);
    // What became of a write, for people: the read-back as the HMI shows values ("5000 W",
    // bits by their labels) where the bus's message has the codec's words or bit ids.
    static QString messageOf(const WriteOutcome &outcome, const RegisterEntry *entry, const QString &bitsDescription);

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
    QString m_bitsDescription;   // of the bit change under way, empty for a whole write
    DecodedValue m_readBack;
    qint64 m_readBackMs = -1;    // the bus's clock; -1 without a read-back
};

} // namespace jumo
