// A simulated RS-485 line: several SimulatedDevices behind one serial port (or behind a
// SimulatorServer's TCP connections). It frames the master's requests, dispatches them
// by slave address, answers with the configured timing (processing delay, minimum
// response time, optional pacing at the baud rate) and can inject faults.
#pragma once

#include "protocol/lineformat.h"
#include "sim/clientend.h"
#include "sim/simulateddevice.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QQueue>
#include <QSerialPort>
#include <QTimer>

#include <memory>

namespace jumo {

enum class FaultMode { None, Drop, Late, StrayByte, BadCrc, Exception, Dead };

struct Fault
{
    FaultMode mode = FaultMode::None;
    int remaining = -1;    // requests left; -1 = until cleared
    int lateMs = 0;        // Late: extra delay
    int exceptionCode = 0; // Exception
};

class SimulatorLine : public QObject
{
    Q_OBJECT

public:
    explicit SimulatorLine(QObject *parent = nullptr);
    ~SimulatorLine() override;

    SimulatedDevice *addDevice(std::shared_ptr<const RegisterMap> map, quint8 address);
    // The device at this address leaves the line (unplugged, or swapped for another).
    void removeDevice(quint8 address);
    QList<SimulatedDevice *> devices() const { return m_devices; }
    SimulatedDevice *device(quint8 address) const;

    bool open(const QString &portName, const LineFormat &format, QString *error = nullptr);
    void close();
    bool isOpen() const;

    // Timing of the replies.
    void setProcessingDelayMs(int ms) { m_processingDelayMs = ms; }
    void setMinimumResponseTimeMs(int ms) { m_minimumResponseTimeMs = ms; }
    // Delays each reply by the wire time of request and reply at the baud rate, so a
    // pty line behaves like a real one.
    void setPacing(bool on) { m_pacing = on; }
    // Advances every device's model this often (ms); 0 stops the simulation clock.
    void setTickInterval(int ms);

    void setFault(quint8 address, const Fault &fault);

    // How the line answers one request frame (address .. CRC) received now: the reply
    // frame as it goes on the wire (empty: nobody answers) and how long after now.
    struct Answer
    {
        QByteArray frame;
        qint64 delayMs = 0;
    };
    Answer answer(const QByteArray &frame);
    // Writes bytes to a device (the port, a TCP connection) delayMs from now, in due
    // order with every other reply; dropped if the device is gone by then.
    void sendLater(QIODevice *to, const QByteArray &bytes, qint64 delayMs);
    const LineFormat &format() const { return m_format; }
    // The line's format without a port of its own (served through a SimulatorServer).
    void setFormat(const LineFormat &format) { m_format = format; }
    // The client's end of the pty pair: a request sent at other settings than the line's
    // goes unanswered, as on a real line (see ClientEnd for what a pty can tell). Before
    // the client opens it.
    bool watchClientEnd(const QString &path, QString *error = nullptr) { return m_clientEnd.open(path, error); }

    // What went over the line, for tests: every complete request frame received.
    int requestsReceived() const { return m_requestsReceived; }
    int writeRequestsReceived() const { return m_writeRequestsReceived; }
    int crcErrorsReceived() const { return m_crcErrors; }
    // Requests sent at settings the devices do not understand (watchClientEnd()).
    int misunderstoodRequests() const { return m_misunderstood; }

signals:
    void requestReceived(const QByteArray &frame);
    void replySent(const QByteArray &frame);

private:
    void onReadyRead();
    void processBuffer();
    void handleFrame(const QByteArray &frame);
    void sendNext();
    void tick();

    struct PendingReply
    {
        QByteArray bytes;
        qint64 dueMs = 0;
        QPointer<QIODevice> to;
    };

    QSerialPort m_port;
    LineFormat m_format;
    ClientEnd m_clientEnd;
    int m_misunderstood = 0;
    QList<SimulatedDevice *> m_devices;
    QHash<quint8, Fault> m_faults;
    QByteArray m_buffer;
    QTimer m_silenceTimer;   // ends a frame whose length cannot be told from its head
    QTimer m_replyTimer;
    QTimer m_tickTimer;
    QElapsedTimer m_clock;
    qint64 m_lastTickMs = 0;
    QQueue<PendingReply> m_replies;
    int m_processingDelayMs = 2;
    int m_minimumResponseTimeMs = 0;
    bool m_pacing = false;
    int m_requestsReceived = 0;
    int m_writeRequestsReceived = 0;
    int m_crcErrors = 0;
};

} // namespace jumo
