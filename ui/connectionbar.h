// The connection bar: serial port (listed adapters under their stable by-id names, or a
// typed path or tcp:// / rtu+tcp:// gateway address), baud rate, data format,
// connect/disconnect, and the line's state.
#pragma once

#include "bus/bussettings.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;

namespace jumo {

class ConnectionBar : public QWidget
{
    Q_OBJECT

public:
    explicit ConnectionBar(QWidget *parent = nullptr);

    void setSettings(const QString &port, int baud, const QString &format);
    // The port to open and remember: a listed adapter's by-id name, or the typed path.
    QString port() const;
    int baud() const;
    QString format() const;
    // Connected: the fields lock and the button disconnects.
    void setConnected(bool connected, const QString &stateText);
    void refreshPorts();

signals:
    void connectRequested();
    void disconnectRequested();

private:
    void setPort(const QString &port);

    QComboBox *m_port;
    QComboBox *m_baud;
    QComboBox *m_format;
    QPushButton *m_button;
    QLabel *m_state;
    bool m_connected = false;
};

} // namespace jumo
