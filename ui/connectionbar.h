// The connection bar: the line it acts on (a chooser while there are several), its
// address (listed adapters under their stable by-id names, a typed path or a gateway's
// URL), baud rate, data format, connect/disconnect, and the line's state.
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
    // The lines to choose from, the current one chosen; the chooser shows with two or more.
    void setLines(const QStringList &names, int current);
    int currentLine() const;

signals:
    void connectRequested();
    void disconnectRequested();
    // The user chose another line.
    void lineChosen(int index);
    // The user changed the address, baud or format.
    void settingsEdited();

private:
    void setPort(const QString &port);

    QComboBox *m_line;
    QLabel *m_lineLabel;
    QComboBox *m_port;
    QComboBox *m_baud;
    QComboBox *m_format;
    QPushButton *m_button;
    QLabel *m_state;
    bool m_connected = false;
};

} // namespace jumo
