#include "sim/simulatorline.h"

#include "protocol/rtuframe.h"

#include <QLoggingCategory>

#include <algorithm>

Q_DECLARE_LOGGING_CATEGORY(lcSim)

namespace jumo {

SimulatorLine::SimulatorLine(QObject *parent) : QObject(parent)
{
    m_silenceTimer.setSingleShot(true);
    m_silenceTimer.setInterval(20);
    m_replyTimer.setSingleShot(true);
    m_replyTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_port, &QSerialPort::readyRead, this, &SimulatorLine::onReadyRead);
    connect(&m_silenceTimer, &QTimer::timeout, this, [this] {
        // Bytes whose frame length cannot be told (unknown function code, or a
        // fragment): after a silence they are taken as one frame.
        if (!m_buffer.isEmpty()) {
            const QByteArray frame = m_buffer;
            m_buffer.clear();
            handleFrame(frame);
        }
    });
    connect(&m_replyTimer, &QTimer::timeout, this, &SimulatorLine::sendNext);
    connect(&m_tickTimer, &QTimer::timeout, this, &SimulatorLine::tick);
    m_clock.start();
}

SimulatorLine::~SimulatorLine()
{
    close();
}

SimulatedDevice *SimulatorLine::addDevice(std::shared_ptr<const RegisterMap> map, quint8 address)
{
    auto *device = new SimulatedDevice(std::move(map), address, this);
    m_devices << device;
    return device;
}

void SimulatorLine::removeDevice(quint8 address)
{
    if (SimulatedDevice *d = device(address)) {
        m_devices.removeOne(d);
        d->deleteLater();
    }
}

SimulatedDevice *SimulatorLine::device(quint8 address) const
{
    for (SimulatedDevice *d : m_devices) {
        if (d->address() == address)
            return d;
    }
    return nullptr;
}

bool SimulatorLine::open(const QString &portName, const LineFormat &format, QString *error)
{
    m_format = format;
    m_port.setPortName(portName);
    // Parity must be set before opening: a pty refuses changing it afterwards.
    m_port.setBaudRate(format.baudRate);
    m_port.setDataBits(QSerialPort::Data8);
    m_port.setParity(format.parity);
    m_port.setStopBits(format.stopBits);
    m_port.setFlowControl(QSerialPort::NoFlowControl);
    if (!m_port.open(QIODevice::ReadWrite)) {
        if (error)
            *error = m_port.errorString();
        return false;
    }
    m_lastTickMs = m_clock.elapsed();
    return true;
}

void SimulatorLine::close()
{
    m_replyTimer.stop();
    m_replies.clear();
    if (m_port.isOpen())
        m_port.close();
}

bool SimulatorLine::isOpen() const
{
    return m_port.isOpen();
}

void SimulatorLine::setTickInterval(int ms)
{
    if (ms <= 0) {
        m_tickTimer.stop();
        return;
    }
    m_lastTickMs = m_clock.elapsed();
    m_tickTimer.start(ms);
}

void SimulatorLine::tick()
{
    const qint64 now = m_clock.elapsed();
    const double seconds = (now - m_lastTickMs) / 1000.0;
    m_lastTickMs = now;
    for (SimulatedDevice *d : std::as_const(m_devices))
        d->advance(seconds);
}

void SimulatorLine::setFault(quint8 address, const Fault &fault)
{
    if (fault.mode == FaultMode::None)
        m_faults.remove(address);
    else
        m_faults.insert(address, fault);
}

void SimulatorLine::onReadyRead()
{
    m_buffer += m_port.readAll();
    processBuffer();
    if (!m_buffer.isEmpty())
        m_silenceTimer.start();
}

void SimulatorLine::processBuffer()
{
    while (!m_buffer.isEmpty()) {
        const std::optional<int> length = RtuFrame::expectedLength(m_buffer, RtuFrame::Direction::Request);
        if (!length || *length < 0 || m_buffer.size() < *length)
            return;   // wait for more bytes, or for the silence that ends an odd frame
        const QByteArray frame = m_buffer.left(*length);
        m_buffer.remove(0, *length);
        handleFrame(frame);
    }
}

void SimulatorLine::handleFrame(const QByteArray &frame)
{
    if (m_clientEnd.understands(m_format) == false) {
        // Sent at another baud rate or format: garbage to every device, which stays silent.
        ++m_misunderstood;
        qCDebug(lcSim) << "request at other line settings, not understood:" << RtuFrame::toHex(frame);
        return;
    }
    const Answer a = answer(frame);
    if (!a.frame.isEmpty())
        sendLater(&m_port, a.frame, a.delayMs);
}

SimulatorLine::Answer SimulatorLine::answer(const QByteArray &frame)
{
    ++m_requestsReceived;
    emit requestReceived(frame);
    if (!RtuFrame::hasValidCrc(frame)) {
        ++m_crcErrors;   // a real device stays silent
        qCDebug(lcSim) << "CRC error in" << RtuFrame::toHex(frame);
        return {};
    }
    if (frame.size() < 4)
        return {};
    const quint8 address = quint8(frame[0]);
    const QByteArray pdu = frame.mid(1, frame.size() - 3);
    const quint8 function = quint8(pdu[0]);
    if (function == 0x06 || function == 0x10)
        ++m_writeRequestsReceived;

    if (address == 0) {
        for (SimulatedDevice *d : std::as_const(m_devices)) {
            if (d->map().protocol.broadcast)
                d->process(pdu, true);
        }
        return {};
    }
    SimulatedDevice *target = device(address);
    if (!target) {
        for (SimulatedDevice *d : std::as_const(m_devices)) {
            if (d->map().protocol.alwaysAnswersAddress == address) {
                target = d;
                break;
            }
        }
    }
    if (!target)
        return {};

    Fault fault = m_faults.value(target->address());
    if (fault.mode != FaultMode::None && fault.remaining > 0 && --fault.remaining == 0)
        m_faults.remove(target->address());
    else if (fault.mode != FaultMode::None)
        m_faults.insert(target->address(), fault);

    QByteArray replyPdu;
    switch (fault.mode) {
    case FaultMode::Dead:
    case FaultMode::Drop:
        return {};
    case FaultMode::Exception:
        replyPdu.append(char(function | 0x80));
        replyPdu.append(char(fault.exceptionCode));
        break;
    default:
        replyPdu = target->process(pdu, false);
        break;
    }
    if (replyPdu.isEmpty())
        return {};
    QByteArray reply = RtuFrame::build(address, replyPdu);
    if (fault.mode == FaultMode::BadCrc)
        reply[reply.size() - 1] = char(~quint8(reply[reply.size() - 1]));
    if (fault.mode == FaultMode::StrayByte)
        reply.prepend('\0');

    double delay = std::max(m_processingDelayMs, m_minimumResponseTimeMs);
    if (m_pacing)
        delay += m_format.wireTimeMs(int(frame.size())) + m_format.frameGapMs() + m_format.wireTimeMs(int(reply.size()));
    if (fault.mode == FaultMode::Late)
        delay += fault.lateMs;
    return {reply, qint64(delay + 0.5)};
}

void SimulatorLine::sendLater(QIODevice *to, const QByteArray &bytes, qint64 delayMs)
{
    // One line, one reply at a time: a late reply holds back those after it.
    m_replies.enqueue({bytes, m_clock.elapsed() + delayMs, to});
    if (!m_replyTimer.isActive())
        m_replyTimer.start(int(std::max<qint64>(0, m_replies.head().dueMs - m_clock.elapsed())));
}

void SimulatorLine::sendNext()
{
    while (!m_replies.isEmpty() && m_replies.head().dueMs <= m_clock.elapsed()) {
        const PendingReply reply = m_replies.dequeue();
        if (reply.to && reply.to->isOpen()) {
            reply.to->write(reply.bytes);
            emit replySent(reply.bytes);
        }
    }
    if (!m_replies.isEmpty())
        m_replyTimer.start(int(std::max<qint64>(0, m_replies.head().dueMs - m_clock.elapsed())));
}

} // namespace jumo
