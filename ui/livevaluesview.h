// The table of a device's live values: greys stale values, marks error values, and keeps
// the columns sized to their content.
#pragma once

#include <QTableView>

namespace jumo {

class LiveValuesModel;

class LiveValuesView : public QTableView
{
    Q_OBJECT

public:
    explicit LiveValuesView(LiveValuesModel *model, QWidget *parent = nullptr);

    LiveValuesModel *liveModel() const { return m_model; }
    // The text shown for an entry's value, as a person sees it.
    QString displayedValue(const QString &entryId) const;

protected:
    // While on screen, its entries are read sooner (LiveValuesModel::setShown).
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    LiveValuesModel *m_model;
};

} // namespace jumo
