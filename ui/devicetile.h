// A tile of the overview: a device's name and address, its key values, its alarm count
// and whether it answers; clicking it opens the device's page.
#pragma once

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
    DeviceTile(const RegisterMap &map, quint8 address, LiveValuesModel *values, AlarmBitsModel *alarms,
               QWidget *parent = nullptr);

    void setOnline(bool online);
    QString valuesText() const;

signals:
    void activated();

protected:
    void showEvent(QShowEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    bool m_dirty = true;
    void refresh();

    const RegisterMap &m_map;
    LiveValuesModel *m_values;
    AlarmBitsModel *m_alarms;
    QLabel *m_title;
    QLabel *m_keyValues;
    QLabel *m_alarmLabel;
    bool m_online = true;
};

} // namespace jumo
