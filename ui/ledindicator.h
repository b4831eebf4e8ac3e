// One LED of an LED grid: a round lamp coloured by kind and state, with its label beside
// it, so colour never carries the meaning alone. A long label wraps onto more lines.
#pragma once

#include <QWidget>

class QLabel;

namespace jumo {

class LedIndicator : public QWidget
{
    Q_OBJECT

public:
    enum class Kind { Alarm, Warning, Status };
    // Unknown is neither on nor off: a hollow lamp with a question mark.
    enum class State { Off, On, Unknown };

    LedIndicator(const QString &label, Kind kind, QWidget *parent = nullptr);

    // stale: the state is the last one read, longer ago than the device's cycle allows.
    void setState(State state, bool stale);
    State state() const { return m_state; }
    bool isOn() const { return m_state == State::On; }
    bool isStale() const { return m_stale; }
    QString label() const { return m_label; }

    // The whole label on one line where there is room; it wraps where there is not.
    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    int lampSize() const;
    void updateText();

    QString m_label;
    Kind m_kind;
    State m_state = State::Unknown;
    bool m_stale = false;
    QLabel *m_text;
};

} // namespace jumo
