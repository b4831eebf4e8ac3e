// The connection of a line: opens its transport, notices when the port goes away (an
// unplugged adapter, a closed pty, a gateway's connection), and opens it again by itself
// while the user wants the line, until it is closed. A line lost stays lost until a new
// connection stands (a TCP connection is made asynchronously). The port name is a path opened anew each time, so a
// /dev/serial/by-id link leads to the ttyUSBn the adapter is after re-plugging.
#pragma once

#include "bus/bussettings.h"
#include "bus/clock.h"
#include "bus/devicesource.h"
#include "bus/transport.h"

#include <QObject>

#include <functional>
#include <memory>

namespace jumo {

class LineConnection : public QObject
{
    Q_OBJECT

public:
    using TransportFactory = std::function<std::unique_ptr<Transport>(const BusSettings &)>;

    LineConnection(Clock *clock, TransportFactory factory, QObject *parent = nullptr);
    ~LineConnection() override;

    void setSettings(const BusSettings &settings) { m_settings = settings; }
    // Opens the port; false with the reason in lastError() when it cannot.
    bool open();
    void close();
    LineState state() const { return m_state; }
    QString lastError() const { return m_lastError; }
    Transport *transport() const { return m_transport.get(); }

    // The serial transport for the settings' port and format.
    static std::unique_ptr<Transport> serialTransport(const BusSettings &settings);
    // The transport the settings' line address asks for: serial, Modbus TCP or RTU over
    // TCP (a bad address gives a transport whose open() says why).
    static std::unique_ptr<Transport> transportFor(const BusSettings &settings);

signals:
    void stateChanged(jumo::LineState state);
    // The port went away; the line keeps trying to come back.
    void lost(const QString &reason);
    void resultReady(const jumo::ModbusResult &result);

private:
    void setState(LineState state);
    void onLost(const QString &reason);
    void onOpened();
    void scheduleReconnect();
    void tryReconnect(quint64 generation);

    Clock *m_clock;
    TransportFactory m_factory;
    BusSettings m_settings;
    std::unique_ptr<Transport> m_transport;
    LineState m_state = LineState::Disconnected;
    QString m_lastError;
    quint64 m_generation = 0;   // reconnect calls of an earlier loss are void
};

} // namespace jumo
