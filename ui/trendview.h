// A trend of chosen live values of one device over a time window, with pause and CSV
// export. It opens with the device's key values (those of its overview tile) chosen, one
// value axis per unit, titled with the unit. Samples come from the live values model as the poll cycles deliver them; only
// current values are drawn. A value that turns stale or unknown ends its line: the trend
// shows a gap until the value is current again, never a line across the outage.
#pragma once

#include <QHash>
#include <QWidget>

class QChart;
class QColor;
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
    // keyEntries: chosen from the start (the map's overview entries).
    TrendView(LiveValuesModel *values, const QStringList &keyEntries, QWidget *parent = nullptr);

    bool exportCsv(const QString &path, QString *error = nullptr) const;
    // Chooses an entry for the trend (as ticking it in the list does).
    void select(const QString &entryId, bool on);
    // The drawn segments of an entry's trace: more than one means gaps.
    QList<QList<QPointF>> segments(const QString &entryId) const;
    // The chosen entries, in the model's order.
    QStringList selectedEntries() const;
    // The value axes' titles (one axis per unit in use), in the order they were added.
    QStringList axisTitles() const;
    // Takes the chart colours of the theme now in use.
    void restyle();

protected:
    // While on screen, the chosen entries are read sooner (LiveValuesModel::setShown).
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void tellShown();
    void onDataChanged(int first, int last);
    void setSelected(int row, bool on);
    void rescale();

    LiveValuesModel *m_values;
    QListWidget *m_choice;
    QComboBox *m_window;
    QChart *m_chart;
    QChartView *m_view;
    QDateTimeAxis *m_timeAxis;
    // One value axis per unit of the chosen entries; made when first needed, removed
    // when no trace uses it.
    QValueAxis *axisFor(const QString &unit, const QColor &color);
    void dropUnusedAxes();
    QString unitOf(int row) const;
    QList<QPair<QString, QValueAxis *>> m_valueAxes;
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
