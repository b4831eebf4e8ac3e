// One simulated JUMO device: the registers of its family's map, Modbus request handling
// with the map's access rules and the family's limits, and a small physical model.
#pragma once

#include "protocol/registermap.h"
#include "protocol/valuecodec.h"

#include <QByteArray>
#include <QHash>
#include <QObject>
#include <QRandomGenerator>

#include <memory>

namespace jumo {

class SimulatedDevice : public QObject
{
    Q_OBJECT

public:
    SimulatedDevice(std::shared_ptr<const RegisterMap> map, quint8 address, QObject *parent = nullptr);

    quint8 address() const { return m_address; }
    const RegisterMap &map() const { return *m_map; }
    std::shared_ptr<const RegisterMap> mapPointer() const { return m_map; }

    // Handles one request PDU (function code + data) and returns the response PDU, an
    // exception PDU (function | 0x80, code), or an empty array for a broadcast.
    QByteArray process(const QByteArray &pdu, bool broadcast);

    // Advances the physical model by the given time.
    void advance(double seconds);

    // Direct access for tests and the demo, bypassing the access rules.
    bool setNumber(const QString &id, double value);
    bool setText(const QString &id, const QString &text);
    double number(const QString &id) const;
    quint16 word(quint16 address) const { return m_words.value(address); }
    // Sets raw words at defined addresses; returns false if any address is undefined.
    bool setWords(quint16 address, const QList<quint16> &words);
    // Switches a bit ("entry.bit") or a bool entry, and the state's other word where the map
    // links two (a bool word and a bit of a status word report one state).
    bool setFlag(const QString &reference, bool on);
    bool flag(const QString &reference) const;
    // Makes a float read as a device error value ("input unplugged"); Ok clears it.
    bool forceStatus(const QString &id, ValueStatus status);

    bool manualMode() const { return m_manual; }
    bool tuning() const { return m_tuning; }

signals:
    void registersWritten(quint16 start, quint16 count);

private:
    bool setOneFlag(const QString &reference, bool on);
    QByteArray exception(quint8 function, quint8 code) const;
    QByteArray readRegisters(quint8 function, quint16 start, quint16 count) const;
    QByteArray writeRegisters(quint8 function, quint16 start, const QList<quint16> &values, bool broadcast);
    void afterWrite(quint16 start, quint16 count);
    void applyCommands(const RegisterEntry &entry, quint16 value);
    void storeWords(const RegisterEntry &entry, const QList<quint16> &words);
    void advancePowerController(double seconds);
    void advanceProcessController(double seconds);
    void updateLimits();
    double bound(const QString &role) const;
    void setBound(const QString &role, double value);
    double noise(double amplitude);

    std::shared_ptr<const RegisterMap> m_map;
    quint8 m_address;
    QHash<quint16, quint16> m_words;         // every defined word
    QHash<QString, ValueStatus> m_forced;    // floats that read as error values
    QHash<QString, double> m_overrides;      // RAM overrides written by the master
    QRandomGenerator m_random;
    bool m_manual = false;
    bool m_tuning = false;
    bool m_controllerOff = false;
    double m_tuningSeconds = 0;
};

} // namespace jumo
