// The connection bar: serial port (listed adapters or a typed path), baud rate, data
// format, connect/disconnect, and the line's state.
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
    QComboBox *m_port;
    QComboBox *m_baud;
    QComboBox *m_format;
    QPushButton *m_button;
    QLabel *m_state;
    bool m_connected = false;
};

} // namespace jumo
