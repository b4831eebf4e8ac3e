// The transport of RTU over TCP: raw RTU frames through a serial device server (a port
// server, a Moxa NPort in "TCP server" mode, socat). The frames and the timing are a
// serial line's: the frame gap at the configured baud before each request, a reply framed
// by its expected length and checked by CRC and against the request. Unlike Qt's RTU
// client it skips stray bytes in front of a reply (echoes, noise) and finds the reply
// after them. A connection that cannot be made or drops is the loss of the line.
#pragma once

#include "bus/lineaddress.h"
#include "bus/transport.h"
#include "protocol/lineformat.h"

#include <QElapsedTimer>
#include <QTcpSocket>
#include <QTimer>

#include <optional>

namespace jumo {

class RtuTcpTransport final : public Transport
{
    Q_OBJECT

public:
    static constexpr int connectTimeoutMs = 5000;

    RtuTcpTransport(const LineAddress &address, const LineFormat &format, QObject *parent = nullptr);
    ~RtuTcpTransport() override;

    bool open(QString *error) override;
    void close() override;
    bool isOpen() const override;
    bool isConnecting() const override;
    void send(const ModbusRequest &request) override;
    double interFrameDelayMs() const override;

    // What a received reply frame (address .. CRC, CRC checked) means for the request:
    // the same checks as a serial line's. Apart from the socket so it can be tested.
    static ModbusResult resultOfFrame(const ModbusRequest &request, const QByteArray &frame);
    // Finds the reply to the request in the bytes received so far: its length once it is
    // complete, with *skipped bytes in front of it that belong to nothing (stray bytes,
    // a frame with a bad CRC: counted in *crcErrors). nullopt while more must arrive.
    static std::optional<qsizetype> findReply(const ModbusRequest &request, const QByteArray &buffer,
                                              qsizetype *skipped, int *crcErrors);

private:
    // Stops everything; a request under way finishes as LineDown with the reason.
    void shutDown(const QString &reason);
    void transmit();
    void onReadyRead();
    void onTimeout();
    void onConnected();
    void onDisconnected();
    void onSocketError(QAbstractSocket::SocketError error);
    void complete(const ModbusResult &result);
    void loseLine(const QString &reason);
    void deliverLater(const ModbusResult &result);

    LineAddress m_address;
    LineFormat m_format;
    QTcpSocket m_socket;
    QTimer m_connectTimer;
    QTimer m_gapTimer;        // the frame gap before a request
    QTimer m_replyTimer;      // the request's timeout
    QElapsedTimer m_lastTraffic;
    QElapsedTimer m_requestAge;   // since send(): the silence before it is waited for no longer than its timeout
    QByteArray m_buffer;
    std::optional<ModbusRequest> m_request;   // waiting to go out, or under way
    bool m_sent = false;
    int m_crcErrors = 0;
    bool m_started = false;
    bool m_connected = false;
};

} // namespace jumo
