// A trend of chosen live values of one device over a time window, with pause and CSV
// export. Samples come from the live values model as the poll cycles deliver them; only
// current values are drawn. A value that turns stale or unknown ends its line: the trend
// shows a gap until the value is current again, never a line across the outage.
#pragma once

#include <QHash>
#include <QWidget>

class QChart;
class QChartView;
class QComboBox;
class QDateTimeAxis;
class QListWidget;
class QLineSeries;
class QPointF;
class QValueAxis;

namespace jumo {

class LiveValuesModel;

class TrendView : public QWidget
{
    Q_OBJECT

public:
    explicit TrendView(LiveValuesModel *values, QWidget *parent = nullptr);

    bool exportCsv(const QString &path, QString *error = nullptr) const;
    // Chooses an entry for the trend (as ticking it in the list does).
    void select(const QString &entryId, bool on);
    // The drawn segments of an entry's trace: more than one means gaps.
    QList<QList<QPointF>> segments(const QString &entryId) const;

private:
    void onDataChanged(int first, int last);
    void setSelected(int row, bool on);
    void rescale();

    LiveValuesModel *m_values;
    QListWidget *m_choice;
    QComboBox *m_window;
    QChart *m_chart;
    QChartView *m_view;
    QDateTimeAxis *m_timeAxis;
    QValueAxis *m_valueAxis;
    // One trace per chosen entry: a series per unbroken stretch of current values.
    struct Trace
    {
        QList<QLineSeries *> segments;
        bool broken = false;   // the last sample was not current: the next one starts a segment
    };
    QLineSeries *addSegment(int row, Trace &trace);

    QHash<int, Trace> m_traces;   // model row -> trace
    bool m_paused = false;
};

} // namespace jumo
