// Where a line is: a serial port (RTU), a Modbus TCP gateway (tcp://HOST[:PORT], the unit
// id is the device address) or a serial device server carrying raw RTU frames
// (rtu+tcp://HOST:PORT). Parsed from BusSettings::portName, which keeps the text.
#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace jumo {

struct LineAddress
{
    Q_DECLARE_TR_FUNCTIONS(jumo::LineAddress)

public:
    enum class Kind { Serial, ModbusTcp, RtuOverTcp };

    static constexpr quint16 modbusTcpPort = 502;

    Kind kind = Kind::Serial;
    QString text;        // as given
    QString host;        // TCP kinds: a name, an IPv4 or an IPv6 address (without brackets)
    quint16 port = 0;    // TCP kinds

    // Anything that is not a URL ("scheme://") is a serial port path. A URL must name a
    // known scheme, a host and (for rtu+tcp) a port 1..65535, and nothing after it.
    static std::optional<LineAddress> parse(const QString &text, QString *error);
    // "rtu", "tcp", "rtu+tcp": the words of station files, JSON and MQTT.
    QString kindName() const;
    bool isNetwork() const { return kind != Kind::Serial; }
    // "HOST:PORT", with brackets around an IPv6 address.
    QString endpoint() const;
};

} // namespace jumo
