#include "trendview.h"

#include <QScopeGuard>

#include "models/livevaluesmodel.h"
#include "protocol/filesaver.h"
#include "theme.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDateTimeAxis>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScopeGuard>
#include <QSplitter>
#include <QTextStream>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>

namespace jumo {

TrendView::TrendView(LiveValuesModel *values, const QStringList &keyEntries, QWidget *parent)
    : QWidget(parent), m_values(values), m_choice(new QListWidget(this)), m_window(new QComboBox(this)),
      m_chart(new QChart), m_view(new QChartView(m_chart, this)), m_timeAxis(new QDateTimeAxis)
{
    m_choice->setObjectName(QStringLiteral("trendChoice"));
    // A long signal name wraps within the list, which never scrolls sideways.
    m_choice->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_choice->setWordWrap(true);
    m_choice->setResizeMode(QListView::Adjust);
    for (int row = 0; row < m_values->rowCount(); ++row) {
        const QModelIndex label = m_values->index(row, LiveValuesModel::LabelColumn);
        auto *item = new QListWidgetItem(label.data().toString(), m_choice);
        item->setToolTip(label.data().toString());
        item->setData(Qt::UserRole, row);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(Qt::Unchecked);
    }
    connect(m_choice, &QListWidget::itemChanged, this, [this](QListWidgetItem *item) {
        setSelected(item->data(Qt::UserRole).toInt(), item->checkState() == Qt::Checked);
    });
    m_window->addItem(tr("1 minute"), 60);
    m_window->addItem(tr("5 minutes"), 300);
    m_window->addItem(tr("15 minutes"), 900);
    m_window->addItem(tr("1 hour"), 3600);
    connect(m_window, &QComboBox::currentIndexChanged, this, &TrendView::rescale);
    auto *pause = new QCheckBox(tr("Pause"), this);
    pause->setObjectName(QStringLiteral("trendPause"));
    connect(pause, &QCheckBox::toggled, this, [this](bool on) {
        // Nothing is recorded while paused, not even a loss: the line ends here.
        m_paused = on;
        for (Trace &trace : m_traces)
            trace.broken = true;
    });
    auto *exportButton = new QPushButton(tr("Export CSV..."), this);
    connect(exportButton, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export trend"), QString(), tr("CSV files (*.csv)"));
        QString error;
        if (!path.isEmpty() && !exportCsv(path, &error))
            QMessageBox::warning(this, tr("Export trend"), error);
    });

    // The chart draws its own background: dark in a dark theme, before any series takes
    // its colour from it.
    m_chart->setTheme(Theme::isDark() ? QChart::ChartThemeDark : QChart::ChartThemeLight);
    m_timeAxis->setFormat(QStringLiteral("HH:mm:ss"));
    m_timeAxis->setTitleText(tr("Time"));
    m_chart->addAxis(m_timeAxis, Qt::AlignBottom);
    m_chart->legend()->setAlignment(Qt::AlignBottom);
    m_chart->legend()->setShowToolTips(true);
    m_view->setRenderHint(QPainter::Antialiasing);

    auto *bar = new QHBoxLayout;
    bar->addWidget(m_window);
    bar->addWidget(pause);
    bar->addStretch();
    bar->addWidget(exportButton);
    auto *right = new QWidget(this);
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    rightLayout->addLayout(bar);
    rightLayout->addWidget(m_view);
    auto *split = new QSplitter(this);
    split->addWidget(m_choice);
    split->addWidget(right);
    split->setStretchFactor(1, 3);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(split);
    // New readings and validity changes; the once-a-second age refresh (status and age
    // columns only) adds no point.
    connect(m_values, &QAbstractItemModel::dataChanged, this, [this](const QModelIndex &first, const QModelIndex &last) {
        if (first.column() <= LiveValuesModel::ValueColumn)
            onDataChanged(first.row(), last.row());
    });
    for (const QString &id : keyEntries)
        select(id, true);
    rescale();
}

void TrendView::restyle()
{
    // A new chart theme recolours every series and axis: the traces keep one colour over
    // their segments and each axis takes its first trace's colour again.
    m_chart->setTheme(Theme::isDark() ? QChart::ChartThemeDark : QChart::ChartThemeLight);
    for (const Trace &trace : std::as_const(m_traces)) {
        for (QLineSeries *segment : trace.segments)
            segment->setPen(trace.segments.first()->pen());
    }
    for (const auto &[unit, axis] : std::as_const(m_valueAxes)) {
        for (auto it = m_traces.cbegin(); it != m_traces.cend(); ++it) {
            if (unitOf(it.key()) == unit && !it.value().segments.isEmpty()) {
                const QColor color = it.value().segments.first()->color();
                axis->setLinePenColor(color);
                axis->setLabelsColor(color);
                axis->setTitleBrush(color);
                break;
            }
        }
    }
}

QString TrendView::unitOf(int row) const
{
    return m_values->index(row, LiveValuesModel::UnitColumn).data().toString();
}

QValueAxis *TrendView::axisFor(const QString &unit, const QColor &color)
{
    for (const auto &[u, axis] : std::as_const(m_valueAxes)) {
        if (u == unit)
            return axis;
    }
    auto *axis = new QValueAxis;
    axis->setTitleText(unit.isEmpty() ? tr("Value (no unit)") : unit);
    // In the colour of the first trace on it, so each line finds its scale.
    axis->setLinePenColor(color);
    axis->setLabelsColor(color);
    axis->setTitleBrush(color);
    // Axes alternate left and right, so two units read side by side.
    m_chart->addAxis(axis, m_valueAxes.size() % 2 == 0 ? Qt::AlignLeft : Qt::AlignRight);
    m_valueAxes.append({unit, axis});
    return axis;
}

void TrendView::dropUnusedAxes()
{
    for (qsizetype i = m_valueAxes.size() - 1; i >= 0; --i) {
        bool used = false;
        for (auto it = m_traces.cbegin(); it != m_traces.cend() && !used; ++it)
            used = unitOf(it.key()) == m_valueAxes[i].first;
        if (!used) {
            m_chart->removeAxis(m_valueAxes[i].second);
            delete m_valueAxes[i].second;
            m_valueAxes.removeAt(i);
        }
    }
}

QStringList TrendView::selectedEntries() const
{
    QList<int> rows = m_traces.keys();
    std::sort(rows.begin(), rows.end());
    QStringList out;
    for (int row : rows)
        out << m_values->entryId(row);
    return out;
}

QStringList TrendView::axisTitles() const
{
    QStringList out;
    for (const auto &[unit, axis] : m_valueAxes)
        out << axis->titleText();
    return out;
}

void TrendView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    tellShown();
}

void TrendView::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_values->setShown(this, false);
}

void TrendView::tellShown()
{
    const QStringList chosen = selectedEntries();
    // Nothing chosen is nothing shown (an empty list would mean every row).
    m_values->setShown(this, isVisible() && !chosen.isEmpty(), chosen);
}

void TrendView::setSelected(int row, bool on)
{
    // What the trend draws is what the line reads sooner while it is on screen.
    const auto tell = qScopeGuard([this] { tellShown(); });
    if (!on) {
        const Trace trace = m_traces.take(row);
        for (QLineSeries *s : trace.segments) {
            m_chart->removeSeries(s);
            delete s;
        }
        dropUnusedAxes();
        rescale();
        return;
    }
    if (m_traces.contains(row))
        return;
    Trace &trace = m_traces[row];
    trace.broken = true;
    addSegment(row, trace);
}

void TrendView::select(const QString &entryId, bool on)
{
    const int row = m_values->rowOf(entryId);
    for (int i = 0; i < m_choice->count(); ++i) {
        if (m_choice->item(i)->data(Qt::UserRole).toInt() == row)
            m_choice->item(i)->setCheckState(on ? Qt::Checked : Qt::Unchecked);
    }
}

QList<QList<QPointF>> TrendView::segments(const QString &entryId) const
{
    QList<QList<QPointF>> out;
    for (const QLineSeries *s : m_traces.value(m_values->rowOf(entryId)).segments) {
        if (s->count() > 0)
            out << s->points();
    }
    return out;
}

QLineSeries *TrendView::addSegment(int row, Trace &trace)
{
    auto *series = new QLineSeries;
    m_chart->addSeries(series);
    series->attachAxis(m_timeAxis);
    series->attachAxis(axisFor(unitOf(row), series->color()));
    if (trace.segments.isEmpty()) {
        // "Load voltage [V]"; a unit set on the device reads "(configured)" already.
        const QString label = m_values->index(row, LiveValuesModel::LabelColumn).data().toString();
        const QString unit = unitOf(row);
        series->setName(unit.isEmpty()                       ? label
                        : unit.startsWith(QLatin1Char('(')) ? label + QLatin1Char(' ') + unit
                                                             : label + QStringLiteral(" [") + unit + QLatin1Char(']'));
    } else {
        // A continuation: the same colour, one legend entry for the whole trace.
        series->setPen(trace.segments.first()->pen());
        for (QLegendMarker *marker : m_chart->legend()->markers(series))
            marker->setVisible(false);
    }
    trace.segments << series;
    return series;
}

void TrendView::onDataChanged(int first, int last)
{
    if (m_paused || m_traces.isEmpty())
        return;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    const qint64 keepFrom = now - 3600 * 1000;
    bool added = false;
    for (auto it = m_traces.begin(); it != m_traces.end(); ++it) {
        if (it.key() < first || it.key() > last)
            continue;
        Trace &trace = it.value();
        // Only a current good number is a point; anything else (stale, unknown, an error
        // value) ends the line here.
        const QVariant v = m_values->index(it.key(), 0).data(LiveValuesModel::NumericRole);
        if (!v.isValid()) {
            trace.broken = true;
            continue;
        }
        QLineSeries *series = trace.segments.last();
        if (trace.broken && series->count() > 0)
            series = addSegment(it.key(), trace);
        trace.broken = false;
        series->append(double(now), v.toDouble());
        // An hour is kept; segments that fell out of it entirely go.
        for (QLineSeries *s : std::as_const(trace.segments)) {
            while (s->count() > 0 && s->at(0).x() < keepFrom)
                s->remove(0);
        }
        while (trace.segments.size() > 1 && trace.segments.first()->count() == 0) {
            QLineSeries *gone = trace.segments.takeFirst();
            trace.segments.first()->setName(gone->name());
            for (QLegendMarker *marker : m_chart->legend()->markers(trace.segments.first()))
                marker->setVisible(true);
            m_chart->removeSeries(gone);
            delete gone;
        }
        added = true;
    }
    if (added)
        rescale();
}

void TrendView::rescale()
{
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    const qint64 span = m_window->currentData().toLongLong() * 1000;
    m_timeAxis->setRange(QDateTime::fromMSecsSinceEpoch(now - span), QDateTime::fromMSecsSinceEpoch(now));
    for (const auto &[unit, axis] : std::as_const(m_valueAxes)) {
        double lo = std::numeric_limits<double>::max();
        double hi = std::numeric_limits<double>::lowest();
        for (auto it = m_traces.cbegin(); it != m_traces.cend(); ++it) {
            if (unitOf(it.key()) != unit)
                continue;
            for (const QLineSeries *s : it.value().segments) {
                for (const QPointF &p : s->points()) {
                    if (p.x() >= now - span) {
                        lo = std::min(lo, p.y());
                        hi = std::max(hi, p.y());
                    }
                }
            }
        }
        if (lo > hi) {
            axis->setRange(0, 1);
        } else {
            axis->setRange(lo - (hi - lo) * 0.05 - 0.5, hi + (hi - lo) * 0.05 + 0.5);
            axis->applyNiceNumbers();
        }
    }
}

bool TrendView::exportCsv(const QString &path, QString *error) const
{
    QString csv;
    QTextStream out(&csv);
    out << "time,entry,value,unit\n";
    for (auto it = m_traces.cbegin(); it != m_traces.cend(); ++it) {
        const QString id = m_values->entryId(it.key());
        const QString unit = m_values->index(it.key(), LiveValuesModel::UnitColumn).data().toString();
        for (const QLineSeries *s : it.value().segments) {
            for (const QPointF &p : s->points())
                out << QDateTime::fromMSecsSinceEpoch(qint64(p.x()), Qt::UTC).toString(Qt::ISODateWithMs) << ',' << id
                    << ',' << QString::number(p.y(), 'g', 9) << ',' << unit << '\n';
        }
    }
    out.flush();
    return FileSaver::save(path, csv.toUtf8(), error);
}

} // namespace jumo
