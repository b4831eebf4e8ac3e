// A trend of chosen live values of one device over a time window, with pause and CSV
// export. Samples come from the live values model as the poll cycles deliver them.
#pragma once

#include <QHash>
#include <QWidget>

class QChart;
class QChartView;
class QComboBox;
class QDateTimeAxis;
class QListWidget;
class QLineSeries;
class QValueAxis;

namespace jumo {

class LiveValuesModel;

class TrendView : public QWidget
{
    Q_OBJECT

public:
    explicit TrendView(LiveValuesModel *values, QWidget *parent = nullptr);

    bool exportCsv(const QString &path, QString *error = nullptr) const;

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
    QHash<int, QLineSeries *> m_series;   // model row -> series
    bool m_paused = false;
};

} // namespace jumo
