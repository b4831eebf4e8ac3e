// One control of a device page: the input that fits the entry (number, on/off, choice,
// output bits, command buttons), a write button, the current value, and the state of
// the last write with the device's answer.
#pragma once

#include <QWidget>

class QLabel;
class QLineEdit;
class QComboBox;
class QPushButton;

namespace jumo {

class BitSwitches;
class Bus;
class LiveValuesModel;
class WriteCommand;
struct RegisterEntry;
class RegisterMap;

class ControlRow : public QWidget
{
    Q_OBJECT

public:
    ControlRow(Bus *bus, int device, const RegisterMap &map, const RegisterEntry &entry, LiveValuesModel *values,
               QWidget *parent = nullptr);

    void setReadOnly(bool readOnly);
    // How the question before a write names the device (see DeviceTitle).
    void setDeviceTitle(const QString &title) { m_deviceTitle = title; }
    // The value as the input holds it now (for tests and confirmations).
    QString inputValue() const;
    void setInputValue(const QString &value);
    // Writes the input's value, after a confirmation where the write changes outputs or
    // wears the EEPROM (from the Write button and from Enter alike).
    void writeInput();
    QString stateText() const;
    // The on/off switches of a bit field's bits, or null.
    BitSwitches *switches() const { return m_switches; }

protected:
    void showEvent(QShowEvent *event) override;

private:
    bool m_dirty = true;
    // value as the codec takes it; shown as people read it ("25.0 °C", "On", a label).
    void write(const QString &value, const QString &shown, const QString &description);
    // Shows why nothing was written, without asking anything.
    void refuse(const QString &reason);
    void switchBit(const QString &bitId, bool on);
    bool confirm(const QString &description) const;
    void refreshCurrent();
    void showWriteState(int state, const QString &message);

    Bus *m_bus;
    int m_device;
    const RegisterMap &m_map;
    const RegisterEntry &m_entry;
    LiveValuesModel *m_values;
    WriteCommand *m_command;
    QLineEdit *m_edit = nullptr;
    QComboBox *m_choice = nullptr;
    BitSwitches *m_switches = nullptr;
    QList<QPushButton *> m_buttons;
    QPushButton *m_writeButton = nullptr;
    QPushButton *m_restoreButton = nullptr;
    QLabel *m_current;
    QLabel *m_state;
    bool m_readOnly = false;
    QString m_deviceTitle;
};

} // namespace jumo
