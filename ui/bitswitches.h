// The bits of a bit field that hold states (binary outputs, external inputs), for an
// operator to switch one at a time: each bit's state as the device reports it (on, off,
// unknown) with On and Off buttons that change that bit alone. A word whose other bits
// the device does not report can only be written whole: then it shows check boxes, and
// the row's write button says that every bit is written as ticked.
#pragma once

#include "bus/bus.h"

#include <QHash>
#include <QWidget>

class QCheckBox;
class QLabel;
class QPushButton;

namespace jumo {

class LedIndicator;

class BitSwitches : public QWidget
{
    Q_OBJECT

public:
    BitSwitches(const Bus *bus, DeviceId device, const RegisterMap &map, const RegisterEntry &entry,
                QWidget *parent = nullptr);

    // Each bit has On and Off (else only the whole word, as ticked).
    bool switchesSingleBits() const { return m_single; }
    void refresh();
    // While a write is under way the buttons wait for its outcome.
    void setBusy(bool busy);
    void setReadOnly(bool readOnly);

    LedIndicator *indicator(const QString &bitId) const { return m_leds.value(bitId); }
    QPushButton *button(const QString &bitId, bool on) const { return (on ? m_onButtons : m_offButtons).value(bitId); }
    // The whole word as ticked: "bit+bit", or "0".
    QString tickedValue() const;
    void setTicked(const QString &value);

signals:
    void switchRequested(const QString &bitId, bool on);

private:
    void updateEnabled();

    const Bus *m_bus;
    DeviceId m_device;
    const RegisterEntry &m_entry;
    bool m_single;
    bool m_busy = false;
    bool m_readOnly = false;
    QHash<QString, LedIndicator *> m_leds;
    QHash<QString, QPushButton *> m_onButtons;
    QHash<QString, QPushButton *> m_offButtons;
    QList<QCheckBox *> m_boxes;
};

} // namespace jumo
