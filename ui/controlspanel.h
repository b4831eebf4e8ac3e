// A scrollable page of ControlRows for the entries of a device whose control is one of
// the given kinds: the setpoints first (the one in RAM before those in EEPROM), then the
// others grouped by the manual's sections.
#pragma once

#include <QWidget>

namespace jumo {

class Bus;
class ControlRow;
class LiveValuesModel;
class RegisterMap;

class ControlsPanel : public QWidget
{
    Q_OBJECT

public:
    ControlsPanel(Bus *bus, int device, const RegisterMap &map, const QStringList &controls, LiveValuesModel *values,
                  QWidget *parent = nullptr);

    void setReadOnly(bool readOnly);
    void setDeviceTitle(const QString &title);
    ControlRow *row(const QString &entryId) const;
    bool isEmpty() const { return m_rows.isEmpty(); }

private:
    QList<ControlRow *> m_rows;
};

} // namespace jumo
