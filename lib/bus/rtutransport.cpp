#include "bus/rtutransport.h"

#include "bus/portaccess.h"
#include "bus/serialportlist.h"
#include "protocol/rtuframe.h"

#include <QDataStream>
#include <QModbusReply>
#include <QModbusRtuSerialClient>
#include <QVariant>

namespace jumo {

RtuTransport::RtuTransport(const QString &portName, const LineFormat &format, QObject *parent)
    : ClientTransport(parent), m_portName(portName), m_format(format)
{
}

RtuTransport::~RtuTransport()
{
    closeLink();
}

QString RtuTransport::peer() const
{
    return tr("the port %1").arg(m_portName);
}

ClientTransport::Link RtuTransport::openLink(QString *error)
{
    if (!m_client) {
        m_client = new QModbusRtuSerialClient(this);
        connect(m_client, &QModbusDevice::errorOccurred, this, &RtuTransport::onErrorOccurred);
        // Connected after the client's own handler, which reads every byte first: this
        // only learns that bytes came.
        if (QIODevice *port = m_client->device())
            connect(port, &QIODevice::readyRead, this, [this] {
                if (!std::exchange(m_replyReading, false))
                    ++m_receptions;
            });
    }
    // A by-id link is followed at every open, so a re-plugged adapter is found as the
    // ttyUSBn it is now; the device's own name keeps Qt's lock file (LCK..ttyUSB0) the
    // one every other program on it uses.
    m_client->setConnectionParameter(QModbusDevice::SerialPortNameParameter, SerialPortList::currentDevice(m_portName));
    m_client->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, m_format.baudRate);
    m_client->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    // Qt's default parity is Even: always set it.
    m_client->setConnectionParameter(QModbusDevice::SerialParityParameter, m_format.parity);
    m_client->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, m_format.stopBits);
    m_client->setNumberOfRetries(0);   // retries are the scheduler's, after a quiet gap
    m_client->setInterFrameDelay(0);   // the minimum: 3.5 characters, at least 2 ms
    if (!m_client->connectDevice() || m_client->state() != QModbusDevice::ConnectedState) {
        if (error) {
            // Qt says "permission error" for a locked port as for a closed one: ask the
            // system what it is and what to do.
            const QString reason = PortAccess::inspect(m_portName).message();
            *error = reason.isEmpty() ? m_client->errorString() : reason;
        }
        closeLink();
        return Link::Failed;
    }
    return Link::Open;
}

void RtuTransport::closeLink()
{
    if (!m_client)
        return;
    // Replies still queued finish as aborted while the client closes; nobody may hear
    // of it any more (a request under way has been ended already).
    if (m_pending) {
        m_pending->disconnect(this);
        connect(m_pending, &QModbusReply::finished, m_pending, &QObject::deleteLater);
        m_pending.clear();
    }
    const QSignalBlocker quiet(m_client);
    m_client->disconnectDevice();
}

double RtuTransport::interFrameDelayMs() const
{
    // QModbusRtuSerialClient waits 3.5 characters before each request, at least 2 ms.
    return std::max(2.0, m_format.frameGapMs());
}

void RtuTransport::transmit(const ModbusRequest &request)
{
    m_receptionsAtSend = m_receptions;
    m_client->setTimeout(request.timeoutMs);
    QModbusReply *reply = nullptr;
    if (request.isWrite())
        reply = m_client->sendWriteRequest(
                QModbusDataUnit(QModbusDataUnit::HoldingRegisters, request.start, request.words), request.slave);
    else
        reply = m_client->sendReadRequest(
                QModbusDataUnit(QModbusDataUnit::HoldingRegisters, request.start, request.count), request.slave);
    if (!reply) {
        fail(ModbusResult::Status::LineDown, m_client->errorString());
        return;
    }
    m_pending = reply;
    if (reply->isFinished()) {
        // A broadcast is finished once its bytes are handed to the driver.
        QMetaObject::invokeMethod(this, [this, reply, request] { onReplyFinished(reply, request); },
                                  Qt::QueuedConnection);
        return;
    }
    connect(reply, &QModbusReply::finished, this, [this, reply, request] { onReplyFinished(reply, request); });
}

void RtuTransport::onReplyFinished(QModbusReply *reply, const ModbusRequest &request)
{
    reply->deleteLater();
    if (m_pending != reply)
        return;   // of a link closed since
    m_pending.clear();
    ModbusResult result = resultOf(request, reply->error(), reply->result(), reply->rawResult(), reply->errorString());
    const QList<QModbusDevice::IntermediateError> intermediate = reply->intermediateErrors();
    result.crcErrors = int(intermediate.count(QModbusDevice::ResponseCrcError));
    result.mismatches = int(intermediate.count(QModbusDevice::ResponseRequestMismatch));
    result.unframedReceptions = int(m_receptionsAtSend - m_receptionsAtFinish);   // while nothing was out
    if (result.status == ModbusResult::Status::Timeout && result.crcErrors == 0 && result.mismatches == 0
        && m_receptions > m_receptionsAtSend)
        ++result.unframedReceptions;   // bytes came, and made nothing
    m_receptionsAtFinish = m_receptions;
    if (!request.isBroadcast() && result.status != ModbusResult::Status::Timeout
        && result.status != ModbusResult::Status::LineDown) {
        // Qt finishes a reply inside its handler of the reading that completed it: that
        // reading is the reply's, not one to count after it.
        m_replyReading = true;
        QMetaObject::invokeMethod(this, [this] { m_replyReading = false; }, Qt::QueuedConnection);
    }
    complete(result);
}

ModbusResult RtuTransport::resultOf(const ModbusRequest &request, QModbusDevice::Error error,
                                    const QModbusDataUnit &unit, const QModbusResponse &raw,
                                    const QString &errorString)
{
    ModbusResult result;
    // Qt 6.4 keeps an exception's function code sign-extended (0xFFFFFF83): its own
    // isException(), isValid() and functionCode() load an enum out of range (undefined
    // behaviour, caught by UBSan). The byte as received is read through its stream form.
    const quint8 functionByte = rawFunctionByte(raw);
    const bool exception = (functionByte & 0x80) || error == QModbusDevice::ProtocolError;
    switch (error) {
    case QModbusDevice::NoError:
        result.status = ModbusResult::Status::Ok;
        if (request.isBroadcast())
            break;
        if (functionByte != 0 && functionByte != quint8(request.function)) {
            result.status = ModbusResult::Status::BadReply;
            result.errorText = tr("reply with function code %1 to a request with %2")
                                       .arg(functionByte)
                                       .arg(quint8(request.function));
        } else if (!request.isWrite()) {
            // A reply of the wrong size is someone else's answer: never decode it.
            if (unit.valueCount() != request.count || unit.startAddress() != request.start) {
                result.status = ModbusResult::Status::BadReply;
                result.errorText = tr("reply of %1 words where %2 were asked for").arg(unit.valueCount()).arg(request.count);
            } else {
                result.words = unit.values();
            }
        } else if (!echoMatches(request, unit)) {
            // Qt takes a write's echo as it comes: one naming other registers (or another
            // value) does not confirm this write.
            result.status = ModbusResult::Status::BadReply;
            result.errorText = tr("write reply names %1 word(s) at %2 where %3 at %4 were written")
                                       .arg(unit.valueCount())
                                       .arg(unit.startAddress())
                                       .arg(request.count)
                                       .arg(request.start);
        }
        break;
    case QModbusDevice::ProtocolError:
        result.status = ModbusResult::Status::Exception;
        // Qt keeps the code as the first data byte; a frame without one has no code.
        result.exceptionCode = exception && !raw.data().isEmpty() ? quint8(raw.data().at(0)) : 0;
        break;
    case QModbusDevice::TimeoutError:
        result.status = ModbusResult::Status::Timeout;
        break;
    case QModbusDevice::ReplyAbortedError:
    case QModbusDevice::ConnectionError:
        result.status = ModbusResult::Status::LineDown;
        break;
    default:
        result.status = ModbusResult::Status::BadReply;
        break;
    }
    if (result.status != ModbusResult::Status::Ok && result.errorText.isEmpty())
        result.errorText = errorString;
    if (functionByte != 0) {
        QByteArray pdu(1, char(functionByte));
        pdu += raw.data();
        result.replyFrame = RtuFrame::build(request.slave, pdu);
    }
    return result;
}

ModbusResult RtuTransport::resultOfResponse(const ModbusRequest &request, QByteArrayView pdu)
{
    if (pdu.isEmpty())
        return resultOf(request, QModbusDevice::TimeoutError, QModbusDataUnit(), QModbusResponse(), tr("no reply"));
    const quint8 function = quint8(pdu[0]);
    const QByteArray data = pdu.sliced(1).toByteArray();
    const QModbusResponse raw(QModbusPdu::FunctionCode(function), data);
    if (function & 0x80)
        return resultOf(request, QModbusDevice::ProtocolError, QModbusDataUnit(), raw,
                        tr("exception %1").arg(data.isEmpty() ? 0 : quint8(data.at(0))));
    const auto wordAt = [&data](qsizetype at) { return quint16(quint8(data.at(at)) << 8 | quint8(data.at(at + 1))); };
    QModbusDataUnit unit(QModbusDataUnit::HoldingRegisters);
    if (function == 0x03 && !data.isEmpty() && data.size() == 1 + quint8(data.at(0)) && data.size() % 2 == 1) {
        QList<quint16> words;
        for (qsizetype at = 1; at + 1 < data.size(); at += 2)
            words << wordAt(at);
        unit = QModbusDataUnit(QModbusDataUnit::HoldingRegisters, request.start, words);
    } else if (function == 0x06 && data.size() == 4) {
        unit = QModbusDataUnit(QModbusDataUnit::HoldingRegisters, wordAt(0), QList<quint16>{wordAt(2)});
    } else if (function == 0x10 && data.size() == 4) {
        unit = QModbusDataUnit(QModbusDataUnit::HoldingRegisters, wordAt(0), wordAt(2));
    }
    return resultOf(request, QModbusDevice::NoError, unit, raw, QString());
}

quint8 RtuTransport::rawFunctionByte(const QModbusPdu &pdu)
{
    QByteArray bytes;
    QDataStream stream(&bytes, QIODevice::WriteOnly);
    stream << pdu;
    return bytes.isEmpty() ? 0 : quint8(bytes.at(0));
}

bool RtuTransport::echoMatches(const ModbusRequest &request, const QModbusDataUnit &unit)
{
    if (unit.startAddress() != request.start)
        return false;
    if (request.function == ModbusRequest::Function::WriteSingle)
        return unit.valueCount() == 1 && !request.words.isEmpty() && unit.value(0) == request.words.first();
    return unit.valueCount() == request.count;
}

void RtuTransport::onErrorOccurred(QModbusDevice::Error error)
{
    if (error != QModbusDevice::ConnectionError && error != QModbusDevice::ReadError
        && error != QModbusDevice::WriteError)
        return;
    if (!isOpen())
        return;   // a port that does not open says so through open()
    // An unplugged adapter keeps the client "connected" and can flood errors: close on
    // the first one and let the line come back when the port does.
    linkDown(m_client->errorString());
}

} // namespace jumo
