#include "livevaluesview.h"

#include "models/livevaluesmodel.h"
#include "protocol/valuecodec.h"
#include "theme.h"

#include <QBrush>
#include <QFont>
#include <QHeaderView>
#include <QIdentityProxyModel>
#include <QStyle>

#include <algorithm>

namespace jumo {

namespace {

// Turns the model's validity and error roles into colour and type: stale values grey
// and italic, unknown ones grey (they show no number, and the status says why).
class LiveValuesStyle : public QIdentityProxyModel
{
public:
    using QIdentityProxyModel::QIdentityProxyModel;

    QVariant data(const QModelIndex &index, int role) const override
    {
        const auto validity = Validity(QIdentityProxyModel::data(index, LiveValuesModel::ValidityRole).toInt());
        if (role == Qt::ForegroundRole) {
            if (validity != Validity::Current)
                return QBrush(Theme::color(Theme::Role::Hint));
            if (QIdentityProxyModel::data(index, LiveValuesModel::ErrorValueRole).toBool())
                return QBrush(Theme::color(Theme::Role::ErrorValue));
        }
        if (role == Qt::FontRole && validity == Validity::Stale) {
            QFont font = QIdentityProxyModel::data(index, role).value<QFont>();
            font.setItalic(true);
            return font;
        }
        return QIdentityProxyModel::data(index, role);
    }
};

} // namespace

void LiveValuesView::showEvent(QShowEvent *event)
{
    QTableView::showEvent(event);
    m_model->setShown(this, true);
}

void LiveValuesView::hideEvent(QHideEvent *event)
{
    QTableView::hideEvent(event);
    m_model->setShown(this, false);
}

LiveValuesView::LiveValuesView(LiveValuesModel *model, QWidget *parent) : QTableView(parent), m_model(model)
{
    auto *styled = new LiveValuesStyle(this);
    styled->setSourceModel(model);
    setModel(styled);
    verticalHeader()->hide();
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setAlternatingRowColors(true);
    setWordWrap(false);
    setTextElideMode(Qt::ElideRight);
    // The table is as wide as the page, never wider: the signal column takes what the
    // others leave, and a text that does not fit ends in "…" with the whole of it in
    // the tooltip.
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    QHeaderView *header = horizontalHeader();
    header->setStretchLastSection(false);
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setSectionResizeMode(LiveValuesModel::LabelColumn, QHeaderView::Stretch);
    header->setMinimumSectionSize(fontMetrics().horizontalAdvance(QStringLiteral("0000")));
    const QFontMetrics fm = fontMetrics();
    // Cell padding: the style's text margins on both sides and a little air.
    const int pad = 2 * (style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, this) + 1) + 8;
    auto fit = [&](int column, const QStringList &samples) {
        const int headerMargin = style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
        int width = header->fontMetrics().horizontalAdvance(model->headerData(column, Qt::Horizontal).toString())
                + 2 * headerMargin + 4;
        for (const QString &sample : samples)
            width = std::max(width, fm.horizontalAdvance(sample) + pad);
        setColumnWidth(column, width);
    };
    QStringList units;
    QStringList sections;
    for (int row = 0; row < model->rowCount(); ++row) {
        units << model->index(row, LiveValuesModel::UnitColumn).data().toString();
        sections << model->index(row, LiveValuesModel::SectionColumn).data().toString();
    }
    // The sections in full where they are not much longer than "5.2.1 RMS measured values";
    // the rest end in "…" and are in the tooltip.
    fit(LiveValuesModel::SectionColumn, sections);
    setColumnWidth(LiveValuesModel::SectionColumn,
                   std::min(columnWidth(LiveValuesModel::SectionColumn),
                            fm.horizontalAdvance(QStringLiteral("5.1.2 Operating level parameters")) + pad));
    // Numbers, and texts as long as an order code.
    fit(LiveValuesModel::ValueColumn, {QStringLiteral("-88888.888"), QStringLiteral("709051/8-01-100-54/252"),
                                       ValueCodec::statusText(ValueStatus::Underrange)});
    fit(LiveValuesModel::UnitColumn, units);
    // A status that does not fit ends in "…" and is in the tooltip.
    fit(LiveValuesModel::StatusColumn, {QStringLiteral("Stale (888 s old)")});
    fit(LiveValuesModel::AgeColumn, {QStringLiteral("8888.8 s")});
}

QString LiveValuesView::displayedValue(const QString &entryId) const
{
    const int row = m_model->rowOf(entryId);
    return row < 0 ? QString() : model()->index(row, LiveValuesModel::ValueColumn).data().toString();
}

} // namespace jumo
