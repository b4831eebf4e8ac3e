// The identity of a device at the top of its page: name, software version, serial or
// fabrication number, order code and the decoded type codes, as its map lists them.
#pragma once

#include <QWidget>

class QLabel;

namespace jumo {

class LiveValuesModel;
class RegisterMap;

class IdentityPanel : public QWidget
{
    Q_OBJECT

public:
    IdentityPanel(const RegisterMap &map, quint8 address, LiveValuesModel *values, QWidget *parent = nullptr);

protected:
    void showEvent(QShowEvent *event) override;

private:
    bool m_dirty = true;
    void refresh();

    const RegisterMap &m_map;
    LiveValuesModel *m_values;
    QLabel *m_text;
    quint8 m_address;
};

} // namespace jumo
