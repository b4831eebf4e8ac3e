// Where a line is: a serial port (RTU), a Modbus TCP gateway (tcp://HOST[:PORT], the unit
// id is the device address) or a serial device server carrying raw RTU frames
// (rtu+tcp://HOST:PORT). Parsed from BusSettings::portName, which keeps the text.
#pragma once

#include <QCoreApplication>
#include <QSet>
#include <QString>

#include <functional>
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
    // A path is a path: Qt would put /dev/ in front of a relative one ("line/master"), so it
    // is taken from folder. A bare name (ttyUSB0) and a URL stay as they are.
    static QString absolutePort(const QString &port, const QString &folder);
    // "rtu", "tcp", "rtu+tcp": the words of station files, JSON and MQTT.
    QString kindName() const;
    bool isNetwork() const { return kind != Kind::Serial; }
    // "HOST:PORT", with brackets around an IPv6 address.
    QString endpoint() const;

    // What the host means, for telling whether two addresses name one server: an IP
    // address as the address it is in any spelling (an IPv4-mapped IPv6 address as its
    // IPv4 one), "localhost" as both loopback addresses, another name as the addresses it
    // resolves to when `resolve` is given (a blocking look-up), else the name itself.
    QSet<QString> hostMeanings(const std::function<QStringList(const QString &)> &resolve = {}) const;
    // Whether two lines talk to one master: one serial port (by its canonical path), or one
    // device server (rtu+tcp, one port and a host meaning in common; names are looked up
    // with `resolve` only when the literal meanings do not decide it). Modbus TCP lines
    // never do: a gateway orders the connections it has.
    static bool shareMaster(const LineAddress &a, const LineAddress &b,
                            const std::function<QStringList(const QString &)> &resolve = {});
    // The addresses a name resolves to (QHostInfo, blocking), as text; empty when it does not.
    static QStringList lookUp(const QString &name);
};

} // namespace jumo
