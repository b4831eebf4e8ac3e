#include "bus/rtutcptransport.h"

#include "bus/linetiming.h"
#include "bus/rtutransport.h"
#include "protocol/rtuframe.h"

#include <QLoggingCategory>
#include <QModbusDataUnit>
#include <QModbusPdu>

#include <cmath>

Q_DECLARE_LOGGING_CATEGORY(lcBus)

namespace jumo {

namespace {

quint16 wordAt(const QByteArray &bytes, qsizetype at)
{
    return quint16(quint8(bytes.at(at)) << 8 | quint8(bytes.at(at + 1)));
}

} // namespace

RtuTcpTransport::RtuTcpTransport(const LineAddress &address, const LineFormat &format, QObject *parent)
    : Transport(parent), m_address(address), m_format(format)
{
    m_connectTimer.setSingleShot(true);
    m_connectTimer.setInterval(connectTimeoutMs);
    m_gapTimer.setSingleShot(true);
    m_gapTimer.setTimerType(Qt::PreciseTimer);
    m_replyTimer.setSingleShot(true);
    m_replyTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        loseLine(tr("the device server %1 did not accept a connection within %2 s")
                         .arg(m_address.endpoint())
                         .arg(connectTimeoutMs / 1000));
    });
    connect(&m_gapTimer, &QTimer::timeout, this, &RtuTcpTransport::transmit);
    connect(&m_replyTimer, &QTimer::timeout, this, &RtuTcpTransport::onTimeout);
    connect(&m_socket, &QTcpSocket::connected, this, &RtuTcpTransport::onConnected);
    connect(&m_socket, &QTcpSocket::disconnected, this, &RtuTcpTransport::onDisconnected);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &RtuTcpTransport::onSocketError);
    connect(&m_socket, &QTcpSocket::readyRead, this, &RtuTcpTransport::onReadyRead);
    m_lastTraffic.start();
}

RtuTcpTransport::~RtuTcpTransport()
{
    m_socket.disconnect(this);
    m_socket.abort();
}

bool RtuTcpTransport::open(QString *error)
{
    Q_UNUSED(error)
    m_socket.abort();
    m_buffer.clear();
    m_started = true;
    m_connected = false;
    m_socket.connectToHost(m_address.host, m_address.port);
    m_connectTimer.start();
    return true;
}

void RtuTcpTransport::close()
{
    shutDown(tr("the line was closed"));
}

void RtuTcpTransport::shutDown(const QString &reason)
{
    const bool busy = m_request.has_value();
    m_started = false;
    m_connected = false;
    m_connectTimer.stop();
    m_gapTimer.stop();
    m_replyTimer.stop();
    m_request.reset();
    m_socket.abort();
    if (busy) {
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = reason;
        deliverLater(result);
    }
}

bool RtuTcpTransport::isOpen() const
{
    return m_connected;
}

bool RtuTcpTransport::isConnecting() const
{
    return m_started && !m_connected;
}

double RtuTcpTransport::interFrameDelayMs() const
{
    return LineTiming::interFrameDelayMs(m_format);
}

void RtuTcpTransport::send(const ModbusRequest &request)
{
    if (!m_started) {
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = tr("not connected to the device server %1").arg(m_address.endpoint());
        deliverLater(result);
        return;
    }
    m_request = request;
    m_sent = false;
    m_crcErrors = 0;
    m_requestAge.start();
    if (m_connected)
        transmit();   // else onConnected() sends it
}

void RtuTcpTransport::transmit()
{
    if (!m_request || m_sent || !m_connected)
        return;
    // The device server passes bytes on as they come: the silence before a request must
    // be kept here, at the baud rate of its serial side.
    const qint64 gapMs = qint64(std::ceil(interFrameDelayMs()));
    if (const qint64 waited = m_lastTraffic.elapsed(); waited < gapMs) {
        if (m_requestAge.elapsed() >= m_request->timeoutMs) {
            // Noise, or another master on the serial side: a request sent now would
            // collide with it. Said as such, not waited for until the end of time.
            ModbusResult result;
            result.status = ModbusResult::Status::Timeout;
            result.errorText = tr("not sent: the line was never silent for %1 ms within %2 ms (noise or another "
                                  "master on the serial side?)")
                                       .arg(gapMs)
                                       .arg(m_request->timeoutMs);
            m_request.reset();
            deliverLater(result);
            return;
        }
        m_gapTimer.start(int(gapMs - waited));
        return;
    }
    // Whatever came since the last reply answers nothing that is asked now.
    m_buffer.clear();
    m_socket.readAll();
    m_sent = true;
    m_socket.write(RtuFrame::build(m_request->slave, m_request->pdu()));
    m_lastTraffic.restart();
    if (m_request->isBroadcast()) {
        // Nobody answers address 0: done once it is handed on, as on a serial line.
        ModbusResult result;
        result.status = ModbusResult::Status::Ok;
        m_request.reset();
        deliverLater(result);
        return;
    }
    m_replyTimer.start(m_request->timeoutMs);
}

void RtuTcpTransport::onReadyRead()
{
    m_buffer += m_socket.readAll();
    m_lastTraffic.restart();
    if (!m_request || !m_sent) {
        m_buffer.clear();   // answers nothing asked: transmit() would drop it anyway
        return;
    }
    // A reply is at most 256 bytes: far more in front of it is a flood, searched no more.
    constexpr qsizetype keptBytes = 512;
    if (m_buffer.size() > 2 * keptBytes)
        m_buffer.remove(0, m_buffer.size() - keptBytes);
    qsizetype skipped = 0;
    int crcErrors = 0;
    const std::optional<qsizetype> length = findReply(*m_request, m_buffer, &skipped, &crcErrors);
    if (!length)
        return;
    if (skipped > 0)
        qCDebug(lcBus).noquote() << "skipped" << skipped << "stray byte(s) before the reply:"
                                 << RtuFrame::toHex(m_buffer.left(skipped));
    ModbusResult result = resultOfFrame(*m_request, m_buffer.mid(skipped, *length));
    result.crcErrors = crcErrors;
    m_buffer.remove(0, skipped + *length);
    complete(result);
}

void RtuTcpTransport::onTimeout()
{
    if (!m_request)
        return;
    ModbusResult result;
    result.status = ModbusResult::Status::Timeout;
    result.errorText = m_buffer.isEmpty()
            ? tr("no reply within %1 ms").arg(m_request->timeoutMs)
            : tr("no complete reply within %1 ms (%2 byte(s) received: %3)")
                      .arg(m_request->timeoutMs)
                      .arg(m_buffer.size())
                      .arg(QString::fromLatin1(RtuFrame::toHex(m_buffer.left(16))));
    qsizetype skipped = 0;
    findReply(*m_request, m_buffer, &skipped, &result.crcErrors);
    complete(result);
}

void RtuTcpTransport::complete(const ModbusResult &result)
{
    m_replyTimer.stop();
    m_request.reset();
    m_sent = false;
    emit finished(result);
}

std::optional<qsizetype> RtuTcpTransport::findReply(const ModbusRequest &request, const QByteArray &buffer,
                                                    qsizetype *skipped, int *crcErrors)
{
    const quint8 function = quint8(request.function);
    // An adapter or device server that echoes what it sends: the request itself (a 0x06
    // reply is the request's echo by the standard, so it is the answer there).
    const QByteArray echo = request.function == ModbusRequest::Function::WriteSingle
            ? QByteArray()
            : RtuFrame::build(request.slave, request.pdu());
    int badFrames = 0;
    for (qsizetype at = 0; at < buffer.size(); ++at) {
        const QByteArrayView head = QByteArrayView(buffer).sliced(at);
        if (quint8(head[0]) != request.slave)
            continue;
        if (!echo.isEmpty() && head.startsWith(echo)) {
            at += echo.size() - 1;
            continue;
        }
        if (head.size() < 2)
            break;
        const quint8 received = quint8(head[1]);
        if (received != function && received != (function | 0x80))
            continue;
        const std::optional<int> length = RtuFrame::expectedLength(head, RtuFrame::Direction::Response);
        if (!length || head.size() < *length)
            break;   // perhaps the reply, not complete yet
        if (*length < 0)
            continue;
        if (!RtuFrame::hasValidCrc(head.first(*length))) {
            ++badFrames;   // garbled, or bytes that only looked like a reply: look further
            continue;
        }
        *skipped = at;
        *crcErrors = badFrames;
        return *length;
    }
    *crcErrors = badFrames;
    return std::nullopt;
}

ModbusResult RtuTcpTransport::resultOfFrame(const ModbusRequest &request, const QByteArray &frame)
{
    const quint8 function = quint8(frame.at(1));
    const QByteArray data = frame.mid(2, frame.size() - 4);
    const QModbusResponse raw(QModbusPdu::FunctionCode(function), data);
    if (function & 0x80)
        return RtuTransport::resultOf(request, QModbusDevice::ProtocolError, QModbusDataUnit(), raw,
                                      tr("exception %1").arg(data.isEmpty() ? 0 : quint8(data.at(0))));
    QModbusDataUnit unit(QModbusDataUnit::HoldingRegisters);
    if (function == 0x03 && !data.isEmpty() && data.size() == 1 + quint8(data.at(0)) && data.size() % 2 == 1) {
        QList<quint16> words;
        for (qsizetype at = 1; at + 1 < data.size(); at += 2)
            words << wordAt(data, at);
        unit = QModbusDataUnit(QModbusDataUnit::HoldingRegisters, request.start, words);
    } else if (function == 0x06 && data.size() == 4) {
        unit = QModbusDataUnit(QModbusDataUnit::HoldingRegisters, wordAt(data, 0), QList<quint16>{wordAt(data, 2)});
    } else if (function == 0x10 && data.size() == 4) {
        unit = QModbusDataUnit(QModbusDataUnit::HoldingRegisters, wordAt(data, 0), wordAt(data, 2));
    }
    return RtuTransport::resultOf(request, QModbusDevice::NoError, unit, raw, QString());
}

void RtuTcpTransport::onConnected()
{
    if (!m_started)
        return;
    m_connectTimer.stop();
    m_connected = true;
    // Small frames must leave at once, not wait for more to fill a segment.
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_lastTraffic.restart();
    emit opened();
    transmit();
}

void RtuTcpTransport::onDisconnected()
{
    loseLine(tr("the device server %1 closed the connection").arg(m_address.endpoint()));
}

void RtuTcpTransport::onSocketError(QAbstractSocket::SocketError error)
{
    Q_UNUSED(error)
    loseLine(m_connected ? tr("connection to the device server %1 lost: %2").arg(m_address.endpoint(), m_socket.errorString())
                         : tr("no connection to the device server %1: %2").arg(m_address.endpoint(), m_socket.errorString()));
}

void RtuTcpTransport::loseLine(const QString &reason)
{
    if (!m_started)
        return;
    qCInfo(lcBus).noquote() << "device server" << m_address.text << "lost:" << reason;
    shutDown(reason);
    emit lost(reason);
}

void RtuTcpTransport::deliverLater(const ModbusResult &result)
{
    QMetaObject::invokeMethod(this, [this, result] { emit finished(result); }, Qt::QueuedConnection);
}

} // namespace jumo
