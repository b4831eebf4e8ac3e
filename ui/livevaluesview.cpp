#include "livevaluesview.h"

#include "models/livevaluesmodel.h"

#include <QBrush>
#include <QFont>
#include <QHeaderView>
#include <QIdentityProxyModel>

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
                return QBrush(Qt::gray);
            if (QIdentityProxyModel::data(index, LiveValuesModel::ErrorValueRole).toBool())
                return QBrush(QColor(170, 0, 0));
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

LiveValuesView::LiveValuesView(LiveValuesModel *model, QWidget *parent) : QTableView(parent), m_model(model)
{
    auto *style = new LiveValuesStyle(this);
    style->setSourceModel(model);
    setModel(style);
    verticalHeader()->hide();
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    horizontalHeader()->setStretchLastSection(true);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setAlternatingRowColors(true);
    setColumnWidth(LiveValuesModel::SectionColumn, 180);
    setColumnWidth(LiveValuesModel::LabelColumn, 300);
    setColumnWidth(LiveValuesModel::ValueColumn, 130);
    setColumnWidth(LiveValuesModel::UnitColumn, 50);
    setColumnWidth(LiveValuesModel::StatusColumn, 160);
}

QString LiveValuesView::displayedValue(const QString &entryId) const
{
    const int row = m_model->rowOf(entryId);
    return row < 0 ? QString() : model()->index(row, LiveValuesModel::ValueColumn).data().toString();
}

} // namespace jumo
