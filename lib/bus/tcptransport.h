// The transport of a Modbus TCP gateway: Qt's QModbusTcpClient with its retries off, the
// timeout set per request and the unit id the device's address. Results are checked
// against the request as on a serial line (RtuTransport::resultOf). Connecting takes time:
// requests wait for it, and a gateway that cannot be reached in time, or a connection
// that drops, is the loss of the line, never a line that is "connected" and silent.
#pragma once

#include "bus/lineaddress.h"
#include "bus/transport.h"
#include "protocol/lineformat.h"

#include <QModbusDevice>
#include <QPointer>
#include <QTimer>

#include <optional>

class QModbusReply;
class QModbusTcpClient;

namespace jumo {

class TcpTransport final : public Transport
{
    Q_OBJECT

public:
    // How long a gateway may take to accept the connection.
    static constexpr int connectTimeoutMs = 5000;
    // How much longer than its timeout a reply may take before the connection counts as
    // broken: Qt's client stops a request's timer once an MBAP header has come and then
    // waits for as many bytes as the header's length says, for ever.
    static constexpr int replyGuardMarginMs = 1000;

    TcpTransport(const LineAddress &address, const LineFormat &format, QObject *parent = nullptr);
    ~TcpTransport() override;

    bool open(QString *error) override;
    void close() override;
    bool isOpen() const override;
    bool isConnecting() const override;
    void send(const ModbusRequest &request) override;
    double interFrameDelayMs() const override;

private:
    void sendNow(const ModbusRequest &request);
    void onStateChanged(QModbusDevice::State state);
    void onErrorOccurred(QModbusDevice::Error error);
    void onReplyFinished(QModbusReply *reply, const ModbusRequest &request);
    void onReplyOverdue();
    void loseLine(const QString &reason);
    void deliverLater(const ModbusResult &result);

    LineAddress m_address;
    LineFormat m_format;
    QModbusTcpClient *m_client = nullptr;
    QPointer<QModbusReply> m_pending;
    std::optional<ModbusRequest> m_waiting;   // sent once the connection stands
    QTimer m_connectTimer;
    QTimer m_replyGuard;
    bool m_started = false;   // open() was called and close() was not
    bool m_connected = false;
};

} // namespace jumo
