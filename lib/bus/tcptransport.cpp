#include "bus/tcptransport.h"

#include "bus/linetiming.h"
#include "bus/rtutransport.h"

#include <QLoggingCategory>
#include <QModbusReply>
#include <QModbusTcpClient>
#include <QVariant>

Q_DECLARE_LOGGING_CATEGORY(lcBus)

namespace jumo {

TcpTransport::TcpTransport(const LineAddress &address, const LineFormat &format, QObject *parent)
    : Transport(parent), m_address(address), m_format(format)
{
    m_connectTimer.setSingleShot(true);
    m_connectTimer.setInterval(connectTimeoutMs);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        loseLine(tr("the gateway %1 did not accept a connection within %2 s")
                         .arg(m_address.endpoint())
                         .arg(connectTimeoutMs / 1000));
    });
    m_replyGuard.setSingleShot(true);
    connect(&m_replyGuard, &QTimer::timeout, this, &TcpTransport::onReplyOverdue);
}

TcpTransport::~TcpTransport()
{
    if (m_client) {
        m_client->disconnect(this);
        if (m_pending)
            m_pending->disconnect(this);
        m_client->disconnectDevice();
    }
}

bool TcpTransport::open(QString *error)
{
    if (!m_client) {
        m_client = new QModbusTcpClient(this);
        connect(m_client, &QModbusDevice::stateChanged, this, &TcpTransport::onStateChanged);
        connect(m_client, &QModbusDevice::errorOccurred, this, &TcpTransport::onErrorOccurred);
    }
    if (m_client->state() != QModbusDevice::UnconnectedState)
        m_client->disconnectDevice();
    m_client->setConnectionParameter(QModbusDevice::NetworkAddressParameter, m_address.host);
    m_client->setConnectionParameter(QModbusDevice::NetworkPortParameter, m_address.port);
    m_client->setNumberOfRetries(0);   // retries are the scheduler's
    m_connected = false;
    m_started = true;
    if (!m_client->connectDevice()) {
        if (error)
            *error = m_client->errorString();
        m_started = false;
        return false;
    }
    if (m_client->state() == QModbusDevice::ConnectedState)
        m_connected = true;
    else
        m_connectTimer.start();
    return true;
}

void TcpTransport::close()
{
    m_started = false;
    m_connected = false;
    m_connectTimer.stop();
    m_replyGuard.stop();
    if (m_waiting) {
        m_waiting.reset();
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = tr("the line was closed");
        deliverLater(result);
    }
    if (m_client)
        m_client->disconnectDevice();   // a pending reply finishes as aborted: LineDown
}

bool TcpTransport::isOpen() const
{
    return m_connected;
}

bool TcpTransport::isConnecting() const
{
    return m_started && !m_connected;
}

double TcpTransport::interFrameDelayMs() const
{
    // The gateway keeps the frame gap on its RS-485 side; the bus's timing counts it.
    return LineTiming::interFrameDelayMs(m_format);
}

void TcpTransport::send(const ModbusRequest &request)
{
    if (request.isBroadcast()) {
        // The bus refuses broadcasts on a Modbus TCP line before they come here.
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = tr("broadcasts are not sent through a Modbus TCP gateway");
        deliverLater(result);
        return;
    }
    if (!m_connected && m_started) {
        m_waiting = request;   // its timeout starts when it goes out
        return;
    }
    sendNow(request);
}

void TcpTransport::sendNow(const ModbusRequest &request)
{
    if (!m_connected) {
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = tr("not connected to the gateway %1").arg(m_address.endpoint());
        deliverLater(result);
        return;
    }
    m_client->setTimeout(request.timeoutMs);
    const int unit = request.slave;   // the unit id is the device's address
    QModbusReply *reply = request.isWrite()
            ? m_client->sendWriteRequest(QModbusDataUnit(QModbusDataUnit::HoldingRegisters, request.start, request.words),
                                         unit)
            : m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::HoldingRegisters, request.start, request.count),
                                        unit);
    if (!reply) {
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = m_client->errorString();
        deliverLater(result);
        return;
    }
    m_pending = reply;
    m_replyGuard.start(request.timeoutMs + replyGuardMarginMs);
    if (reply->isFinished()) {
        QMetaObject::invokeMethod(this, [this, reply, request] { onReplyFinished(reply, request); },
                                  Qt::QueuedConnection);
        return;
    }
    connect(reply, &QModbusReply::finished, this, [this, reply, request] { onReplyFinished(reply, request); });
}

void TcpTransport::onReplyFinished(QModbusReply *reply, const ModbusRequest &request)
{
    reply->deleteLater();
    if (m_pending == reply) {
        m_pending.clear();
        m_replyGuard.stop();
    }
    emit finished(RtuTransport::resultOf(request, reply->error(), reply->result(), reply->rawResult(),
                                         reply->errorString()));
}

void TcpTransport::onReplyOverdue()
{
    if (!m_pending)
        return;
    // The reply began (or its header promised more than a Modbus PDU can hold) and the
    // rest never came: what follows on this connection cannot be framed any more. The
    // request ends here, and the connection is made anew.
    QModbusReply *reply = m_pending;
    m_pending.clear();
    reply->disconnect(this);
    connect(reply, &QModbusReply::finished, reply, &QObject::deleteLater);
    const QString reason = tr("the gateway %1 sent an incomplete reply and then nothing for %2 ms")
                                   .arg(m_address.endpoint())
                                   .arg(m_replyGuard.interval());
    ModbusResult result;
    result.status = ModbusResult::Status::LineDown;
    result.errorText = reason;
    deliverLater(result);
    loseLine(reason);
}

void TcpTransport::onStateChanged(QModbusDevice::State state)
{
    if (!m_started)
        return;
    if (state == QModbusDevice::ConnectedState && !m_connected) {
        m_connectTimer.stop();
        m_connected = true;
        emit opened();
        if (m_waiting)
            sendNow(*std::exchange(m_waiting, std::nullopt));
        return;
    }
    if (state == QModbusDevice::UnconnectedState) {
        // Qt says why only after this (errorOccurred): that reason is the better one.
        QMetaObject::invokeMethod(
                this,
                [this, wasConnected = m_connected] {
                    const QString why = m_client->errorString().isEmpty() ? tr("the connection was refused or closed")
                                                                           : m_client->errorString();
                    loseLine(wasConnected ? tr("the gateway %1 closed the connection").arg(m_address.endpoint())
                                          : tr("no connection to the gateway %1: %2").arg(m_address.endpoint(), why));
                },
                Qt::QueuedConnection);
    }
}

void TcpTransport::onErrorOccurred(QModbusDevice::Error error)
{
    if (!m_started || error != QModbusDevice::ConnectionError)
        return;
    loseLine(m_connected ? tr("connection to the gateway %1 lost: %2").arg(m_address.endpoint(), m_client->errorString())
                         : tr("no connection to the gateway %1: %2").arg(m_address.endpoint(), m_client->errorString()));
}

void TcpTransport::loseLine(const QString &reason)
{
    if (!m_started)
        return;
    qCInfo(lcBus).noquote() << "gateway" << m_address.text << "lost:" << reason;
    m_started = false;
    m_connected = false;
    m_connectTimer.stop();
    m_replyGuard.stop();
    if (m_waiting) {
        m_waiting.reset();
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = reason;
        deliverLater(result);
    }
    m_client->disconnectDevice();   // a reply under way finishes as aborted: LineDown
    emit lost(reason);
}

void TcpTransport::deliverLater(const ModbusResult &result)
{
    QMetaObject::invokeMethod(this, [this, result] { emit finished(result); }, Qt::QueuedConnection);
}

} // namespace jumo
