#include "trafficview.h"

#include "protocol/rtuframe.h"

#include <QCheckBox>
#include <QHeaderView>
#include <QPlainTextEdit>
#include <QSplitter>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace jumo {

TrafficView::TrafficView(Bus *bus, QWidget *parent)
    : QWidget(parent), m_bus(bus), m_log(new QPlainTextEdit(this)), m_statistics(new QTableWidget(this)),
      m_timer(new QTimer(this))
{
    m_log->setObjectName(QStringLiteral("trafficLog"));
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(500);
    m_log->setFont(QFont(QStringLiteral("monospace")));
    m_log->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_statistics->setObjectName(QStringLiteral("statistics"));
    m_statistics->setColumnCount(9);
    m_statistics->setHorizontalHeaderLabels({tr("Device"), tr("Requests"), tr("Timeouts"), tr("CRC errors"),
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
    connect(m_bus, &Bus::traffic, this, &TrafficView::append);
    connect(m_timer, &QTimer::timeout, this, &TrafficView::refreshStatistics);
    m_timer->start(1000);
}

void TrafficView::append(const TrafficRecord &record)
{
    if (m_paused || !isVisible())
        return;   // nobody reads it: spare the CPU
    QString line = QStringLiteral("%1  %2 -> %3")
                           .arg(QString::number(record.timeMs / 1000.0, 'f', 3).rightJustified(10),
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
    const QList<DeviceId> devices = m_bus->devices();
    m_statistics->setRowCount(int(devices.size()));
    int row = 0;
    for (DeviceId id : devices) {
        const DeviceStatistics *s = m_bus->statistics(id);
        QStringList exceptions;
        for (auto it = s->exceptions.cbegin(); it != s->exceptions.cend(); ++it)
            exceptions << QStringLiteral("%1x%2").arg(it.value()).arg(it.key());
        const QStringList cells{QStringLiteral("%1@%2").arg(m_bus->deviceMap(id)->family).arg(m_bus->deviceAddress(id)),
                                QString::number(s->requests), QString::number(s->timeouts),
                                QString::number(s->crcErrors), QString::number(s->mismatches),
                                exceptions.join(QStringLiteral(", ")),
                                tr("%1 ms").arg(QString::number(s->lastRoundTripMs, 'f', 1)),
                                tr("%1 ms").arg(QString::number(s->meanRoundTripMs, 'f', 1)),
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
