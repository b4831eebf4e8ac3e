// The LED grid of a device: every alarm, warning and status bit of its bit fields, with
// the count of active alarms on top. Driven by an AlarmBitsModel.
#pragma once

#include <QWidget>

class QLabel;

namespace jumo {

class AlarmBitsModel;
class LedIndicator;

class LedGrid : public QWidget
{
    Q_OBJECT

public:
    explicit LedGrid(AlarmBitsModel *model, QWidget *parent = nullptr);

    LedIndicator *indicator(const QString &reference) const;   // "entry.bit"

protected:
    void showEvent(QShowEvent *event) override;

private:
    bool m_dirty = true;
    void refresh(int first, int last);

    AlarmBitsModel *m_model;
    QLabel *m_summary;
    QList<LedIndicator *> m_leds;
};

} // namespace jumo
