#include "portcommands.h"

#include "bus/portaccess.h"
#include "bus/serialportlist.h"
#include "commandparser.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace jumo {

namespace {

QJsonValue hexId(const std::optional<quint16> &id)
{
    return id ? QJsonValue(QStringLiteral("%1").arg(*id, 4, 16, QLatin1Char('0'))) : QJsonValue();
}

QJsonValue textOrNull(const QString &text)
{
    return text.isEmpty() ? QJsonValue() : QJsonValue(text);
}

QJsonObject portJson(const SerialPort &port, const PortAccess &access)
{
    QJsonArray holders;
    for (const PortHolder &holder : access.holders)
        holders.append(QJsonObject{{"pid", holder.pid}, {"command", holder.command}});
    return QJsonObject{{"port", port.location},
                       {"device", port.device},
                       {"stable", port.hasStableName()},
                       {"description", textOrNull(port.description)},
                       {"manufacturer", textOrNull(port.manufacturer)},
                       {"serial_number", textOrNull(port.serialNumber)},
                       {"vendor_id", hexId(port.vendorId)},
                       {"product_id", hexId(port.productId)},
                       {"access", access.problemName()},
                       {"group", textOrNull(access.group)},
                       {"holders", holders},
                       {"message", textOrNull(access.message())}};
}

} // namespace

PortCommands::PortCommands(QTextStream &out, QTextStream &err) : m_out(out), m_err(err)
{
}

int PortCommands::ports(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("ports"),
                         tr("Lists the serial ports: USB adapters under their stable /dev/serial/by-id names (give "
                            "that name to --port: it still finds the adapter when it comes back as another ttyUSBn), "
                            "with description, serial number, the device each is now, and whether it can be opened. "
                            "Pseudo-terminals are not listed."));
    parser.addOption({QStringLiteral("json"), tr("Print a JSON array.")});
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 0, 0))
        return *stop;
    const QList<SerialPort> ports = SerialPortList::available();
    if (parser.isSet(QStringLiteral("json"))) {
        QJsonArray array;
        for (const SerialPort &port : ports)
            array.append(portJson(port, PortAccess::inspect(port.location)));
        m_out << QJsonDocument(array).toJson(QJsonDocument::Indented);
        return 0;
    }
    if (ports.isEmpty()) {
        m_out << tr("No serial ports found (pseudo-terminals are not listed; give their path to --port).") << Qt::endl;
        return 0;
    }
    for (const SerialPort &port : ports) {
        const PortAccess access = PortAccess::inspect(port.location);
        m_out << port.location << Qt::endl;
        if (port.hasStableName())
            m_out << "  " << tr("device now: %1").arg(port.device) << Qt::endl;
        if (!port.description.isEmpty())
            m_out << "  " << tr("description: %1").arg(port.description) << Qt::endl;
        if (!port.manufacturer.isEmpty())
            m_out << "  " << tr("manufacturer: %1").arg(port.manufacturer) << Qt::endl;
        if (!port.serialNumber.isEmpty())
            m_out << "  " << tr("serial number: %1").arg(port.serialNumber) << Qt::endl;
        if (port.vendorId && port.productId)
            m_out << "  " << tr("USB id: %1:%2").arg(*port.vendorId, 4, 16, QLatin1Char('0')).arg(*port.productId, 4, 16, QLatin1Char('0')) << Qt::endl;
        m_out << "  " << (access.problem == PortAccess::Problem::None ? tr("access: ok") : tr("access: %1").arg(access.message()))
              << Qt::endl;
    }
    return 0;
}

} // namespace jumo
