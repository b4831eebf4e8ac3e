// How the parameter editor's cells look and are edited: changed rows bold with their
// mark, values that are not current grey (stale ones italic), write outcomes in their
// colours; the new value edited in a field that knows the entry's range and precision,
// or chosen from the entry's values. Refused input is said, never taken silently.
#pragma once

#include <QStyledItemDelegate>

namespace jumo {

class ParameterEditModel;

class ParameterValueDelegate : public QStyledItemDelegate
{
    Q_OBJECT

public:
    ParameterValueDelegate(ParameterEditModel *model, QObject *parent = nullptr);

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option, const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model, const QModelIndex &index) const override;

signals:
    // What became of an input: refused with why, or a note (a value the device holds).
    void inputRefused(const QString &entryId, const QString &reason) const;
    void inputNote(const QString &entryId, const QString &note) const;
    void inputTaken(const QString &entryId) const;

protected:
    void initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const override;

private:
    ParameterEditModel *m_model;
};

} // namespace jumo
