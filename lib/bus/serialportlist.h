// The serial ports of this machine as users know them: a USB adapter under its stable
// /dev/serial/by-id name (it survives re-plugging, when the adapter may come back as
// another ttyUSBn), with its description and serial number and the device it is now.
#pragma once

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>

#include <optional>

namespace jumo {

struct SerialPort
{
    QString location;   // the name to open and to remember: the by-id link, else the device
    QString device;     // what it is now, e.g. /dev/ttyUSB0
    QString description;
    QString manufacturer;
    QString serialNumber;
    std::optional<quint16> vendorId;
    std::optional<quint16> productId;

    bool hasStableName() const { return location != device; }
};

class SerialPortList
{
    Q_DECLARE_TR_FUNCTIONS(jumo::SerialPortList)

public:
    // /dev/serial/by-id, or $JUMO_SERIAL_BY_ID_DIR (tests, systems with other rules).
    static QString byIdFolder();
    // The ports the system lists, under their by-id names where there is one, sorted.
    static QList<SerialPort> available();
    // Every link of the folder that leads to an existing file: its target (canonical
    // path) -> the link's path. A device with several links keeps the first by name.
    static QHash<QString, QString> byIdLinks(const QString &folder);
    // The system's ports named by their links; a link to a device the system does not
    // list (a pseudo-terminal, say) is a port of its own. Sorted by location.
    static QList<SerialPort> merge(QList<SerialPort> systemPorts, const QHash<QString, QString> &links);
    // The device a port name leads to now (a by-id link is followed); the name itself
    // when it leads nowhere.
    static QString currentDevice(const QString &port);
    // One line for a port list: location, description, serial number, device.
    static QString label(const SerialPort &port);
};

} // namespace jumo
