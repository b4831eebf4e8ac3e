// The traffic of the station's lines: request and reply frames in hex with time, line,
// round trip and errors (the newest few hundred), and the statistics of each device.
#pragma once

#include "bus/bus.h"

#include <QWidget>

class QPlainTextEdit;
class QTableWidget;
class QTimer;

namespace jumo {

class StationLine;

class TrafficView : public QWidget
{
    Q_OBJECT

public:
    explicit TrafficView(QWidget *parent = nullptr);

    void addLine(StationLine *line);
    void removeLine(StationLine *line);

private:
    void append(const StationLine *line, const TrafficRecord &record);
    void refreshStatistics();

    QList<StationLine *> m_lines;
    QPlainTextEdit *m_log;
    QTableWidget *m_statistics;
    QTimer *m_timer;
    bool m_paused = false;
};

} // namespace jumo
