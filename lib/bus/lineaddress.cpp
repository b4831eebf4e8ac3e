#include "bus/lineaddress.h"

#include <QDir>
#include <QFileInfo>
#include <QHostAddress>
#include <QHostInfo>
#include <QRegularExpression>

namespace jumo {

std::optional<LineAddress> LineAddress::parse(const QString &text, QString *error)
{
    auto fail = [error](const QString &message) -> std::optional<LineAddress> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    LineAddress address;
    address.text = text;
    const qsizetype separator = text.indexOf(QLatin1String("://"));
    if (separator < 0) {
        if (text.trimmed().isEmpty())
            return fail(tr("no line address: give a serial port, tcp://HOST[:PORT] or rtu+tcp://HOST:PORT"));
        return address;   // a serial port path, opened as given
    }
    const QString scheme = text.left(separator).toLower();
    if (scheme == QLatin1String("tcp"))
        address.kind = Kind::ModbusTcp;
    else if (scheme == QLatin1String("rtu+tcp"))
        address.kind = Kind::RtuOverTcp;
    else
        return fail(tr("unknown line address scheme '%1://' in '%2': use tcp://HOST[:PORT] (Modbus TCP) or "
                       "rtu+tcp://HOST:PORT (RTU over TCP)")
                            .arg(text.left(separator), text));

    const QString rest = text.mid(separator + 3);
    const qsizetype extra = rest.indexOf(QRegularExpression(QStringLiteral("[/?#]")));
    if (extra >= 0)
        return fail(tr("'%1' has '%2' after the port: a line address is only HOST and PORT").arg(text, rest.mid(extra)));
    if (rest.contains(QLatin1Char('@')))
        return fail(tr("'%1': user names are not part of a line address").arg(text));

    QString host;
    QString portText;
    bool hasPort = false;
    if (rest.startsWith(QLatin1Char('['))) {
        const qsizetype close = rest.indexOf(QLatin1Char(']'));
        if (close < 0)
            return fail(tr("'%1': an IPv6 address in brackets lacks its ']'").arg(text));
        host = rest.mid(1, close - 1);
        const QString after = rest.mid(close + 1);
        if (!after.isEmpty()) {
            if (!after.startsWith(QLatin1Char(':')))
                return fail(tr("'%1': after ']' only ':PORT' may follow").arg(text));
            hasPort = true;
            portText = after.mid(1);
        }
    } else {
        const qsizetype colon = rest.lastIndexOf(QLatin1Char(':'));
        if (colon >= 0 && rest.indexOf(QLatin1Char(':')) != colon)
            return fail(tr("'%1': write an IPv6 address in brackets, e.g. tcp://[::1]:502").arg(text));
        host = colon >= 0 ? rest.left(colon) : rest;
        if (colon >= 0) {
            hasPort = true;
            portText = rest.mid(colon + 1);
        }
    }
    static const QRegularExpression hostPattern(
            QRegularExpression::anchoredPattern(QStringLiteral("[A-Za-z0-9._:%-]+")));
    if (host.isEmpty())
        return fail(tr("'%1' names no host").arg(text));
    if (!hostPattern.match(host).hasMatch())
        return fail(tr("'%1': '%2' is not a host name or address").arg(text, host));
    if (!hasPort && address.kind == Kind::RtuOverTcp)
        return fail(tr("'%1' names no port: a serial device server has no standard port, give rtu+tcp://HOST:PORT")
                            .arg(text));
    quint16 port = modbusTcpPort;
    if (hasPort) {
        static const QRegularExpression digits(QRegularExpression::anchoredPattern(QStringLiteral("[0-9]{1,5}")));
        const int value = digits.match(portText).hasMatch() ? portText.toInt() : -1;
        if (portText.isEmpty())
            return fail(tr("'%1' has ':' but no port after it").arg(text));
        if (value < 1 || value > 65535)
            return fail(tr("'%1': the port must be a number 1..65535, not '%2'").arg(text, portText));
        port = quint16(value);
    }
    address.host = host;
    address.port = port;
    return address;
}

QString LineAddress::kindName() const
{
    switch (kind) {
    case Kind::Serial:
        return QStringLiteral("rtu");
    case Kind::ModbusTcp:
        return QStringLiteral("tcp");
    case Kind::RtuOverTcp:
        return QStringLiteral("rtu+tcp");
    }
    return {};
}

QString LineAddress::endpoint() const
{
    if (host.contains(QLatin1Char(':')))
        return QStringLiteral("[%1]:%2").arg(host).arg(port);
    return QStringLiteral("%1:%2").arg(host).arg(port);
}

namespace {

// An IP address in one spelling; nullopt for a name.
std::optional<QString> canonicalAddress(const QString &host)
{
    QHostAddress address;
    if (!address.setAddress(host))
        return std::nullopt;
    bool mapped = false;
    const quint32 ipv4 = address.toIPv4Address(&mapped);
    if (mapped && address.protocol() == QAbstractSocket::IPv6Protocol)
        address = QHostAddress(ipv4);   // ::ffff:127.0.0.1 is 127.0.0.1
    return address.toString();
}

} // namespace

QSet<QString> LineAddress::hostMeanings(const std::function<QStringList(const QString &)> &resolve) const
{
    if (const std::optional<QString> address = canonicalAddress(host))
        return {*address};
    const QString name = host.toLower();
    // RFC 6761: localhost and its subdomains are the loopback, without asking anyone.
    if (name == QLatin1String("localhost") || name.endsWith(QLatin1String(".localhost")))
        return {QStringLiteral("127.0.0.1"), QStringLiteral("::1")};
    QSet<QString> meanings;
    if (resolve) {
        for (const QString &resolved : resolve(name)) {
            if (const std::optional<QString> address = canonicalAddress(resolved))
                meanings.insert(*address);
        }
    }
    if (meanings.isEmpty())
        meanings.insert(name);
    return meanings;
}

bool LineAddress::shareMaster(const LineAddress &a, const LineAddress &b,
                              const std::function<QStringList(const QString &)> &resolve)
{
    if (a.kind != b.kind || a.kind == Kind::ModbusTcp)
        return false;
    if (a.kind == Kind::Serial) {
        const auto identity = [](const QString &path) {
            const QString canonical = QFileInfo(path).canonicalFilePath();   // by-id links, ./ and ../
            return canonical.isEmpty() ? QDir::cleanPath(path) : canonical;
        };
        return identity(a.text) == identity(b.text);
    }
    if (a.port != b.port)
        return false;
    if (a.hostMeanings().intersects(b.hostMeanings()))
        return true;
    // Names are looked up only now: two device-server lines on one port that their
    // literal meanings do not tell apart or together.
    const bool named = !canonicalAddress(a.host) || !canonicalAddress(b.host);
    return named && resolve && a.hostMeanings(resolve).intersects(b.hostMeanings(resolve));
}

QStringList LineAddress::lookUp(const QString &name)
{
    QStringList addresses;
    for (const QHostAddress &address : QHostInfo::fromName(name).addresses())
        addresses << address.toString();
    return addresses;
}

QString LineAddress::absolutePort(const QString &port, const QString &folder)
{
    if (port.contains(QLatin1String("://")) || !port.contains(QLatin1Char('/')) || port.startsWith(QLatin1Char('/')))
        return port;
    return QDir::cleanPath(QDir(folder).absoluteFilePath(port));
}

} // namespace jumo
