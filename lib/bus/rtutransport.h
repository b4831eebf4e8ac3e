// The production transport of a serial line: QModbusRtuSerialClient (Qt 6.4.2) with its
// retries off (the scheduler retries after a quiet gap), the timeout set per request,
// replies checked against the request before anything is decoded, and the first port
// error taken as the loss of the line (Qt keeps its state "connected" and can flood).
#pragma once

#include "bus/transport.h"
#include "protocol/lineformat.h"

#include <QModbusDevice>
#include <QPointer>

class QModbusReply;
class QModbusRtuSerialClient;

namespace jumo {

class RtuTransport final : public Transport
{
    Q_OBJECT

public:
    RtuTransport(const QString &portName, const LineFormat &format, QObject *parent = nullptr);
    ~RtuTransport() override;

    bool open(QString *error) override;
    void close() override;
    bool isOpen() const override;
    void send(const ModbusRequest &request) override;
    double interFrameDelayMs() const override;

private:
    void onReplyFinished(QModbusReply *reply, const ModbusRequest &request);
    void onErrorOccurred(QModbusDevice::Error error);
    void deliver(const ModbusResult &result);

    QString m_portName;
    LineFormat m_format;
    QModbusRtuSerialClient *m_client = nullptr;
    QPointer<QModbusReply> m_pending;
    ModbusRequest m_pendingRequest;
    bool m_open = false;
};

} // namespace jumo
