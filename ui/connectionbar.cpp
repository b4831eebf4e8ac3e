#include "connectionbar.h"

#include "bus/serialportlist.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QAbstractItemView>
#include <QToolButton>

namespace jumo {

namespace {
constexpr int DeviceRole = Qt::UserRole + 1;   // the device a listed port is now
}

ConnectionBar::ConnectionBar(QWidget *parent)
    : QWidget(parent), m_port(new QComboBox(this)), m_baud(new QComboBox(this)), m_format(new QComboBox(this)),
      m_button(new QPushButton(tr("Connect"), this)), m_state(new QLabel(this))
{
    m_port->setObjectName(QStringLiteral("portBox"));
    m_baud->setObjectName(QStringLiteral("baudBox"));
    m_format->setObjectName(QStringLiteral("formatBox"));
    m_button->setObjectName(QStringLiteral("connectButton"));
    m_state->setObjectName(QStringLiteral("lineState"));
    // Adapters are listed by their stable by-id names; pseudo-terminals and odd adapters
    // are not listed: the path can be typed.
    m_port->setEditable(true);
    m_port->setMinimumWidth(220);
    m_port->lineEdit()->setPlaceholderText(tr("/dev/ttyUSB0 or tcp://HOST"));
    m_port->setToolTip(tr("The line: a serial port (listed, or a typed path);\n"
                          "tcp://HOST[:PORT] for a Modbus TCP gateway (port 502 by default,\n"
                          "the device address is the unit id);\n"
                          "rtu+tcp://HOST:PORT for RTU frames through a serial device server.\n"
                          "Behind a gateway, baud and format are those of its serial side."));
    for (int baud : {4800, 9600, 19200, 38400})
        m_baud->addItem(QString::number(baud), baud);
    m_baud->setCurrentIndex(1);
    for (const char *f : {"8N1", "8E1", "8O1", "8N2"})
        m_format->addItem(QLatin1String(f), QLatin1String(f));
    auto *refresh = new QToolButton(this);
    refresh->setText(tr("Refresh"));
    refresh->setToolTip(tr("List the serial ports again"));
    connect(refresh, &QToolButton::clicked, this, &ConnectionBar::refreshPorts);
    connect(m_button, &QPushButton::clicked, this, [this] {
        if (m_connected)
            emit disconnectRequested();
        else
            emit connectRequested();
    });
    auto *layout = new QHBoxLayout(this);
    // Alt and the underlined letter reach each field from the keyboard.
    auto buddy = [this](const QString &text, QWidget *field) {
        auto *label = new QLabel(text, this);
        label->setBuddy(field);
        return label;
    };
    layout->addWidget(buddy(tr("&Port:"), m_port));
    layout->addWidget(m_port);
    layout->addWidget(refresh);
    layout->addWidget(buddy(tr("&Baud:"), m_baud));
    layout->addWidget(m_baud);
    layout->addWidget(buddy(tr("Fo&rmat:"), m_format));
    layout->addWidget(m_format);
    layout->addWidget(m_button);
    layout->addWidget(m_state, 1);
    refreshPorts();
    setConnected(false, tr("Disconnected"));
}

void ConnectionBar::refreshPorts()
{
    const QString current = port();
    m_port->clear();
    for (const SerialPort &info : SerialPortList::available()) {
        m_port->addItem(SerialPortList::label(info), info.location);
        const int row = m_port->count() - 1;
        m_port->setItemData(row, info.device, DeviceRole);
        QStringList details{tr("Port: %1").arg(info.location), tr("Device now: %1").arg(info.device)};
        if (!info.manufacturer.isEmpty())
            details << tr("Manufacturer: %1").arg(info.manufacturer);
        if (!info.serialNumber.isEmpty())
            details << tr("Serial number: %1").arg(info.serialNumber);
        m_port->setItemData(row, details.join(QLatin1Char('\n')), Qt::ToolTipRole);
    }
    // Labels are long: the list may be wider than the box.
    m_port->view()->setMinimumWidth(m_port->view()->sizeHintForColumn(0));
    setPort(current);
}

void ConnectionBar::setPort(const QString &port)
{
    // A remembered by-id name, or a device a listed adapter is now (settings from
    // before by-id names): the listed port, so its stable name is what is kept.
    int row = m_port->findData(port);
    if (row < 0 && !port.isEmpty())
        row = m_port->findData(port, DeviceRole);
    if (row >= 0)
        m_port->setCurrentIndex(row);
    else
        m_port->setEditText(port);
}

void ConnectionBar::setSettings(const QString &port, int baud, const QString &format)
{
    setPort(port);
    m_baud->setCurrentIndex(std::max(0, m_baud->findData(baud)));
    m_format->setCurrentIndex(std::max(0, m_format->findData(format)));
}

QString ConnectionBar::port() const
{
    // A listed port shows its label; what it stands for is its location.
    const int row = m_port->currentIndex();
    if (row >= 0 && m_port->itemText(row) == m_port->currentText())
        return m_port->itemData(row).toString();
    return m_port->currentText().trimmed();
}

int ConnectionBar::baud() const
{
    return m_baud->currentData().toInt();
}

QString ConnectionBar::format() const
{
    return m_format->currentData().toString();
}

void ConnectionBar::setConnected(bool connected, const QString &stateText)
{
    m_connected = connected;
    m_port->setEnabled(!connected);
    m_baud->setEnabled(!connected);
    m_format->setEnabled(!connected);
    m_button->setText(connected ? tr("Disconnect") : tr("Connect"));
    m_state->setText(stateText);
}

} // namespace jumo
