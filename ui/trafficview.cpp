#include "trafficview.h"

#include "protocol/rtuframe.h"
#include "stationline.h"

#include <QCheckBox>
#include <QHeaderView>
#include <QPlainTextEdit>
#include <QSplitter>
#include <QLocale>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace jumo {

TrafficView::TrafficView(QWidget *parent)
    : QWidget(parent), m_log(new QPlainTextEdit(this)), m_statistics(new QTableWidget(this)),
      m_timer(new QTimer(this))
{
    m_log->setObjectName(QStringLiteral("trafficLog"));
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(500);
    m_log->setFont(QFont(QStringLiteral("monospace")));
    m_log->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_statistics->setObjectName(QStringLiteral("statistics"));
    m_statistics->setColumnCount(10);
    m_statistics->setHorizontalHeaderLabels({tr("Line"), tr("Device"), tr("Requests"), tr("Timeouts"), tr("CRC errors"),
                                             tr("Mismatches"), tr("Exceptions"), tr("Last round trip"),
                                             tr("Mean round trip"), tr("Last cycle")});
    m_statistics->verticalHeader()->hide();
    m_statistics->horizontalHeader()->setStretchLastSection(true);
    auto *pause = new QCheckBox(tr("Pause"), this);
    connect(pause, &QCheckBox::toggled, this, [this](bool on) { m_paused = on; });
    auto *split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_log);
    split->addWidget(m_statistics);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(pause);
    layout->addWidget(split);
    connect(m_timer, &QTimer::timeout, this, &TrafficView::refreshStatistics);
    m_timer->start(1000);
}

void TrafficView::addLine(StationLine *line)
{
    m_lines << line;
    connect(line->bus(), &Bus::traffic, this, [this, line](const TrafficRecord &record) { append(line, record); });
}

void TrafficView::removeLine(StationLine *line)
{
    m_lines.removeAll(line);
    line->bus()->disconnect(this);
}

void TrafficView::append(const StationLine *station, const TrafficRecord &record)
{
    if (m_paused || !isVisible())
        return;   // nobody reads it: spare the CPU
    // The line's name where several lines share the page.
    const QString name = m_lines.size() > 1 ? QStringLiteral("%1  ").arg(station->name(), -12) : QString();
    QString line = QStringLiteral("%1  %2%3 -> %4")
                           .arg(QString::number(record.timeMs / 1000.0, 'f', 3).rightJustified(10), name,
                                QString::fromLatin1(RtuFrame::toHex(record.request)),
                                record.reply.isEmpty() ? tr("(no reply)") : QString::fromLatin1(RtuFrame::toHex(record.reply)));
    line += tr("  %1 ms").arg(QString::number(record.roundTripMs, 'f', 0));
    if (!record.error.isEmpty())
        line += QStringLiteral("  !! ") + record.error;
    m_log->appendPlainText(line);
}

void TrafficView::refreshStatistics()
{
    if (!isVisible())
        return;
    QList<QPair<const StationLine *, DeviceId>> devices;
    for (const StationLine *line : std::as_const(m_lines)) {
        for (DeviceId id : line->bus()->devices())
            devices << qMakePair(line, id);
    }
    m_statistics->setRowCount(int(devices.size()));
    m_statistics->setColumnHidden(0, m_lines.size() < 2);
    int row = 0;
    for (const auto &[line, id] : std::as_const(devices)) {
        const Bus *bus = line->bus();
        const DeviceStatistics *s = bus->statistics(id);
        QStringList exceptions;
        for (auto it = s->exceptions.cbegin(); it != s->exceptions.cend(); ++it)
            exceptions << QStringLiteral("%1x%2").arg(it.value()).arg(it.key());
        const QStringList cells{line->name(), bus->deviceName(id),
                                QString::number(s->requests), QString::number(s->timeouts),
                                QString::number(s->crcErrors), QString::number(s->mismatches),
                                exceptions.join(QStringLiteral(", ")),
                                tr("%1 ms").arg(QLocale().toString(s->lastRoundTripMs, 'f', 1)),
                                tr("%1 ms").arg(QLocale().toString(s->meanRoundTripMs, 'f', 1)),
                                tr("%1 ms").arg(QString::number(s->lastCycleMs, 'f', 0))};
        for (int c = 0; c < cells.size(); ++c) {
            auto *item = m_statistics->item(row, c);
            if (!item) {
                item = new QTableWidgetItem;
                m_statistics->setItem(row, c, item);
            }
            item->setText(cells[c]);
        }
        ++row;
    }
}

} // namespace jumo
