#include "connectionbar.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QToolButton>

namespace jumo {

ConnectionBar::ConnectionBar(QWidget *parent)
    : QWidget(parent), m_port(new QComboBox(this)), m_baud(new QComboBox(this)), m_format(new QComboBox(this)),
      m_button(new QPushButton(tr("Connect"), this)), m_state(new QLabel(this))
{
    m_port->setObjectName(QStringLiteral("portBox"));
    m_baud->setObjectName(QStringLiteral("baudBox"));
    m_format->setObjectName(QStringLiteral("formatBox"));
    m_button->setObjectName(QStringLiteral("connectButton"));
    m_state->setObjectName(QStringLiteral("lineState"));
    // Pseudo-terminals and odd adapters are not listed: the path can be typed.
    m_port->setEditable(true);
    m_port->setMinimumWidth(220);
    m_port->lineEdit()->setPlaceholderText(tr("/dev/ttyUSB0"));
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
    layout->addWidget(new QLabel(tr("Port:"), this));
    layout->addWidget(m_port);
    layout->addWidget(refresh);
    layout->addWidget(new QLabel(tr("Baud:"), this));
    layout->addWidget(m_baud);
    layout->addWidget(new QLabel(tr("Format:"), this));
    layout->addWidget(m_format);
    layout->addWidget(m_button);
    layout->addWidget(m_state, 1);
    refreshPorts();
    setConnected(false, tr("Disconnected"));
}

void ConnectionBar::refreshPorts()
{
    const QString current = m_port->currentText();
    m_port->clear();
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts())
        m_port->addItem(info.systemLocation(), info.systemLocation());
    m_port->setEditText(current);
}

void ConnectionBar::setSettings(const QString &port, int baud, const QString &format)
{
    m_port->setEditText(port);
    m_baud->setCurrentIndex(std::max(0, m_baud->findData(baud)));
    m_format->setCurrentIndex(std::max(0, m_format->findData(format)));
}

QString ConnectionBar::port() const
{
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
