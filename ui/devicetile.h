// A tile of the overview: a device's name and address, whether it answers (online,
// offline since, line lost), its key values with their validity and its alarms;
// clicking it opens the device's page.
#pragma once

#include "bus/bus.h"

#include <QFrame>

class QLabel;

namespace jumo {

class AlarmBitsModel;
class LiveValuesModel;
class RegisterMap;

class DeviceTile : public QFrame
{
    Q_OBJECT

public:
    DeviceTile(DeviceId device, const RegisterMap &map, quint8 address, LiveValuesModel *values,
               AlarmBitsModel *alarms, QWidget *parent = nullptr);

    DeviceId device() const { return m_device; }
    void setCondition(const DeviceCondition &condition);
    QString valuesText() const;
    QString stateText() const;
    QString alarmText() const;
    // "Online", "Not answering since 10:42:17": the words of the tile and the device list.
    static QString conditionText(const DeviceCondition &condition);
    // "2 active alarm(s)", "Alarms unknown", with "(stale)" where they are.
    static QString alarmsText(const DeviceCondition &condition, const AlarmBitsModel &alarms);
    // Takes the colours of the theme now in use.
    void restyle() { refresh(); }

signals:
    void activated(jumo::DeviceId device);

protected:
    void showEvent(QShowEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    // The keyboard reaches each tile with Tab; Enter or Space opens the device.
    void keyPressEvent(QKeyEvent *event) override;
    void paintEvent(QPaintEvent *event) override;

private:
    bool m_dirty = true;
    void refresh();

    DeviceId m_device;
    const RegisterMap &m_map;
    LiveValuesModel *m_values;
    AlarmBitsModel *m_alarms;
    QLabel *m_title;
    QLabel *m_state;
    QLabel *m_keyValues;
    QLabel *m_alarmLabel;
    DeviceCondition m_condition;
    QString m_stateText;
};

} // namespace jumo
