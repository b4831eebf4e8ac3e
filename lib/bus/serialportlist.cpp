#include "bus/serialportlist.h"

#include <QDir>
#include <QFileInfo>
#include <QSerialPortInfo>

#include <algorithm>

namespace jumo {

QString SerialPortList::byIdFolder()
{
    const QString folder = qEnvironmentVariable("JUMO_SERIAL_BY_ID_DIR");
    return folder.isEmpty() ? QStringLiteral("/dev/serial/by-id") : folder;
}

QList<SerialPort> SerialPortList::available()
{
    QList<SerialPort> ports;
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts()) {
        SerialPort port;
        port.device = QFileInfo(info.systemLocation()).canonicalFilePath();
        if (port.device.isEmpty())
            port.device = info.systemLocation();
        port.location = port.device;
        port.description = info.description();
        port.manufacturer = info.manufacturer();
        port.serialNumber = info.serialNumber();
        if (info.hasVendorIdentifier())
            port.vendorId = info.vendorIdentifier();
        if (info.hasProductIdentifier())
            port.productId = info.productIdentifier();
        ports << port;
    }
    return merge(ports, byIdLinks(byIdFolder()));
}

QHash<QString, QString> SerialPortList::byIdLinks(const QString &folder)
{
    QHash<QString, QString> links;
    const QDir dir(folder);
    for (const QFileInfo &link : dir.entryInfoList(QDir::System | QDir::Files | QDir::NoDotAndDotDot, QDir::Name)) {
        if (!link.isSymLink())
            continue;
        const QString target = link.canonicalFilePath();   // empty for a link to nothing
        if (!target.isEmpty() && !links.contains(target))
            links.insert(target, link.absoluteFilePath());
    }
    return links;
}

QList<SerialPort> SerialPortList::merge(QList<SerialPort> systemPorts, const QHash<QString, QString> &links)
{
    QHash<QString, QString> unlisted = links;
    for (SerialPort &port : systemPorts) {
        if (const auto it = links.constFind(port.device); it != links.constEnd())
            port.location = *it;
        unlisted.remove(port.device);
    }
    for (auto it = unlisted.cbegin(); it != unlisted.cend(); ++it) {
        SerialPort port;
        port.device = it.key();
        port.location = it.value();
        systemPorts << port;
    }
    std::sort(systemPorts.begin(), systemPorts.end(),
              [](const SerialPort &a, const SerialPort &b) { return a.location < b.location; });
    return systemPorts;
}

QString SerialPortList::currentDevice(const QString &port)
{
    const QString device = QFileInfo(port).canonicalFilePath();
    return device.isEmpty() ? port : device;
}

QString SerialPortList::label(const SerialPort &port)
{
    QStringList about;
    if (!port.description.isEmpty())
        about << port.description;
    if (!port.serialNumber.isEmpty())
        about << tr("serial number %1").arg(port.serialNumber);
    if (port.hasStableName())
        about << QFileInfo(port.device).fileName();
    return about.isEmpty() ? port.location : tr("%1 (%2)").arg(port.location, about.join(QStringLiteral(", ")));
}

} // namespace jumo
