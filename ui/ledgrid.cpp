#include "ledgrid.h"

#include "models/alarmbitsmodel.h"
#include "ledindicator.h"
#include "protocol/registermap.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace jumo {

LedGrid::LedGrid(AlarmBitsModel *model, QWidget *parent) : QWidget(parent), m_model(model), m_summary(new QLabel(this))
{
    m_summary->setObjectName(QStringLiteral("activeAlarms"));
    auto *inner = new QWidget;
    auto *outer = new QVBoxLayout(inner);
    // One group per register, titled as the manual names it, three LEDs a row.
    QGridLayout *grid = nullptr;
    QString entryId;
    int index = 0;
    const int columns = 3;
    for (int row = 0; row < m_model->rowCount(); ++row) {
        const QModelIndex modelIndex = m_model->index(row);
        const QString reference = modelIndex.data(AlarmBitsModel::ReferenceRole).toString();
        const QString rowEntry = reference.section(QLatin1Char('.'), 0, 0);
        if (!grid || rowEntry != entryId) {
            entryId = rowEntry;
            auto *box = new QGroupBox(modelIndex.data(AlarmBitsModel::GroupTitleRole).toString(), inner);
            grid = new QGridLayout(box);
            grid->setHorizontalSpacing(18);
            for (int column = 0; column < columns; ++column)
                grid->setColumnStretch(column, 1);
            outer->addWidget(box);
            index = 0;
        }
        const int kind = modelIndex.data(AlarmBitsModel::KindRole).toInt();
        auto *led = new LedIndicator(modelIndex.data().toString(),
                                     kind == int(BitKind::Alarm)     ? LedIndicator::Kind::Alarm
                                     : kind == int(BitKind::Warning) ? LedIndicator::Kind::Warning
                                                                     : LedIndicator::Kind::Status,
                                     inner);
        led->setObjectName(QStringLiteral("led_") + reference);
        led->setToolTip(modelIndex.data(Qt::ToolTipRole).toString());
        grid->addWidget(led, index / columns, index % columns);
        ++index;
        m_leds << led;
    }
    outer->addStretch();
    auto *scroll = new QScrollArea(this);
    scroll->setWidget(inner);
    scroll->setWidgetResizable(true);
    // Labels wrap, so the grid always fits the page's width.
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_summary->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(scroll);
    connect(m_model, &QAbstractItemModel::dataChanged, this,
            [this](const QModelIndex &first, const QModelIndex &last) { refresh(first.row(), last.row()); });
    refresh(0, m_model->rowCount() - 1);
}

LedIndicator *LedGrid::indicator(const QString &reference) const
{
    const int row = m_model->rowOf(reference);
    return row >= 0 ? m_leds.at(row) : nullptr;
}

void LedGrid::refresh(int first, int last)
{
    if (!isVisible()) {
        m_dirty = true;   // caught up in showEvent()
        return;
    }
    for (int row = first; row <= last && row < m_leds.size(); ++row) {
        const QModelIndex index = m_model->index(row);
        const auto state = AlarmBitsModel::BitState(index.data(AlarmBitsModel::BitStateRole).toInt());
        m_leds[row]->setState(state == AlarmBitsModel::BitState::On    ? LedIndicator::State::On
                              : state == AlarmBitsModel::BitState::Off ? LedIndicator::State::Off
                                                                       : LedIndicator::State::Unknown,
                              Validity(index.data(AlarmBitsModel::ValidityRole).toInt()) == Validity::Stale);
        m_leds[row]->setToolTip(index.data(Qt::ToolTipRole).toString());
    }
    QString summary = m_model->alarmsKnown() ? tr("%n active alarm(s)", nullptr, m_model->activeAlarms())
                                             : tr("Alarms unknown: the device cannot be read");
    if (m_model->alarmsKnown() && m_model->alarmsStale())
        summary += QLatin1Char(' ') + tr("(stale: not read in the device's last cycle)");
    m_summary->setText(summary);
}

void LedGrid::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_dirty) {
        m_dirty = false;
        refresh(0, m_model->rowCount() - 1);
    }
}

} // namespace jumo
