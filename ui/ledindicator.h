// One LED of an LED grid: a round lamp coloured by kind and state, with its label beside
// it, so colour never carries the meaning alone.
#pragma once

#include <QWidget>

namespace jumo {

class LedIndicator : public QWidget
{
    Q_OBJECT

public:
    enum class Kind { Alarm, Warning, Status };

    LedIndicator(const QString &label, Kind kind, QWidget *parent = nullptr);

    void setState(bool on, bool current);
    bool isOn() const { return m_on; }
    bool isCurrent() const { return m_current; }
    QString label() const { return m_label; }

    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QString m_label;
    Kind m_kind;
    bool m_on = false;
    bool m_current = false;
};

} // namespace jumo
