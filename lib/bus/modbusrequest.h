// One Modbus request as the scheduler hands it to a transport, and what came of it:
// words, an exception with its code, no answer, a reply that did not fit, or a lost line.
#pragma once

#include <QByteArray>
#include <QList>
#include <QMetaType>
#include <QString>

namespace jumo {

struct ModbusRequest
{
    enum class Function : quint8 { ReadHolding = 0x03, WriteSingle = 0x06, WriteMultiple = 0x10 };

    quint8 slave = 0;                   // 0: broadcast (writes only)
    Function function = Function::ReadHolding;
    quint16 start = 0;
    quint16 count = 0;                  // words read, or written
    QList<quint16> words;               // to write
    int timeoutMs = 1000;

    static ModbusRequest read(quint8 slave, quint16 start, quint16 count);
    // One word goes out as 0x06, more as 0x10 (floats and 32-bit values: one atomic write).
    static ModbusRequest write(quint8 slave, quint16 start, const QList<quint16> &words);

    bool isWrite() const { return function != Function::ReadHolding; }
    bool isBroadcast() const { return slave == 0; }
    // Function code and data, without address and CRC.
    QByteArray pdu() const;
    int requestBytes() const { return int(pdu().size()) + 3; }
    int replyBytes() const;
};

struct ModbusResult
{
    enum class Status {
        Ok,          // the reply fitted the request (a broadcast: it was sent)
        Exception,   // the device answered with an exception code
        Timeout,     // no reply in time
        BadReply,    // a reply of the wrong size, address or function: never decoded
        LineDown,    // the port was lost or closed while the request was under way
    };

    Status status = Status::Timeout;
    QList<quint16> words;       // read replies
    int exceptionCode = 0;
    int crcErrors = 0;          // replies discarded for a bad CRC on the way
    int mismatches = 0;         // replies discarded that belonged to another request
    // Bytes heard that made no reply the client could frame: while no request was out (a
    // late answer between two requests, lost), or during this one when it got none (the
    // tail of a late answer, noise). A scan hears late answers by them as by mismatches.
    int unframedReceptions = 0;
    QByteArray replyFrame;      // the whole RTU frame as received (reconstructed), empty if none
    QString errorText;          // empty when the status is Ok

    // 0x0A (gateway path unavailable) and 0x0B (gateway target device failed to respond)
    // come from a gateway, not from the device: it was not reached, or did not answer.
    static constexpr int gatewayPathUnavailable = 0x0A;
    static constexpr int gatewayTargetFailed = 0x0B;
    bool isGatewayException() const
    {
        return status == Status::Exception
                && (exceptionCode == gatewayPathUnavailable || exceptionCode == gatewayTargetFailed);
    }
    // The device itself answered (a gateway's exception is no answer of the device's).
    bool answered() const { return status == Status::Ok || (status == Status::Exception && !isGatewayException()); }
    // No answer of the device's, as a timeout: it may be asked again; a write's outcome is open.
    bool deviceSilent() const
    {
        return status == Status::Timeout || status == Status::BadReply || isGatewayException();
    }
};

} // namespace jumo

Q_DECLARE_METATYPE(jumo::ModbusResult)
