// The traffic of one line: request and reply frames in hex with time, round trip and
// errors (the newest few hundred), and the statistics of each device.
#pragma once

#include "bus/bus.h"

#include <QWidget>

class QPlainTextEdit;
class QTableWidget;
class QTimer;

namespace jumo {

class TrafficView : public QWidget
{
    Q_OBJECT

public:
    explicit TrafficView(Bus *bus, QWidget *parent = nullptr);

private:
    void append(const TrafficRecord &record);
    void refreshStatistics();

    Bus *m_bus;
    QPlainTextEdit *m_log;
    QTableWidget *m_statistics;
    QTimer *m_timer;
    bool m_paused = false;
};

} // namespace jumo
