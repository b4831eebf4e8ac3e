// What carries requests to the devices of one line: a serial port through Qt's Modbus
// client, a Modbus TCP gateway or raw RTU over TCP in production, a scripted fake in unit tests. One request at a time; the
// scheduler above decides what goes next and when.
#pragma once

#include "bus/modbusrequest.h"

#include <QObject>

namespace jumo {

class Transport : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;

    // Opens the port; false with the reason in *error when it cannot.
    virtual bool open(QString *error) = 0;
    // Closes the port; a request under way finishes as LineDown first.
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    // An open() that returned true may still be connecting (a TCP line): opened() or
    // lost() follows. Requests sent meanwhile wait for the connection.
    virtual bool isConnecting() const { return false; }
    // Sends one request. finished() follows exactly once, never from inside this call.
    virtual void send(const ModbusRequest &request) = 0;
    // The silence the transport keeps before each request (the RTU frame gap).
    virtual double interFrameDelayMs() const = 0;

signals:
    void finished(const jumo::ModbusResult &result);
    // A connection that was still being made stands now.
    void opened();
    // The port went away (an unplugged adapter, a closed pty): the transport is closed.
    void lost(const QString &reason);
};

} // namespace jumo
