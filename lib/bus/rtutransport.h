// The production transport of a serial line: QModbusRtuSerialClient (Qt 6.4.2) with its
// retries off (the scheduler retries after a quiet gap), the timeout set per request,
// replies checked against the request before anything is decoded, and the first port
// error taken as the loss of the line (Qt keeps its state "connected" and can flood).
// The life cycle is ClientTransport's; the request's timing is Qt's own.
#pragma once

#include "bus/clienttransport.h"
#include "protocol/lineformat.h"

#include <QModbusDataUnit>
#include <QModbusDevice>
#include <QModbusPdu>
#include <QPointer>

class QModbusReply;
class QModbusRtuSerialClient;

namespace jumo {

class RtuTransport final : public ClientTransport
{
    Q_OBJECT

public:
    RtuTransport(const QString &portName, const LineFormat &format, QObject *parent = nullptr);
    ~RtuTransport() override;

    double interFrameDelayMs() const override;

    // What a finished reply means for the request it answers (Qt's error, the data unit
    // it decoded, the response as received): words only from a reply that fits the
    // request in function, address and size, the code of an exception, a write confirmed
    // only by an echo of what was written. Apart from QModbusReply so it can be fuzzed.
    static ModbusResult resultOf(const ModbusRequest &request, QModbusDevice::Error error,
                                 const QModbusDataUnit &unit, const QModbusResponse &raw,
                                 const QString &errorString);
    // The same for a response PDU as received (function code and data) by a transport
    // that frames replies itself: decoded as Qt's client decodes it, then classified.
    static ModbusResult resultOfResponse(const ModbusRequest &request, QByteArrayView pdu);

private:
    static bool echoMatches(const ModbusRequest &request, const QModbusDataUnit &unit);
    // The function code byte as received (0x80 set for an exception), 0 for no response.
    static quint8 rawFunctionByte(const QModbusPdu &pdu);
    QString peer() const override;
    Link openLink(QString *error) override;
    void closeLink() override;
    void transmit(const ModbusRequest &request) override;
    void onReplyFinished(QModbusReply *reply, const ModbusRequest &request);
    void onErrorOccurred(QModbusDevice::Error error);

    QString m_portName;
    LineFormat m_format;
    QModbusRtuSerialClient *m_client = nullptr;
    QPointer<QModbusReply> m_pending;
    // Readings of the port (its readyRead, after Qt's client has taken the bytes): when
    // the last request finished and when this one went out. Qt drops bytes that come
    // while no request is out, and one stray byte in front of a reply hides it.
    quint64 m_receptions = 0;
    quint64 m_receptionsAtFinish = 0;
    quint64 m_receptionsAtSend = 0;
    bool m_replyReading = false;   // the reading under way completed a reply
};

} // namespace jumo
