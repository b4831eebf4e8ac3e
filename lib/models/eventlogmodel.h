// A table of an EventLog's records (alarm journal, audit log) for views: one row per
// record, the chosen keys as columns, new records appended as they come.
#pragma once

#include <QAbstractTableModel>

namespace jumo {

class EventLog;

class EventLogModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    // columns: record keys; titles: their headers, in the same order.
    EventLogModel(EventLog *log, const QStringList &columns, const QStringList &titles, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    EventLog *m_log;
    QStringList m_columns;
    QStringList m_titles;
};

} // namespace jumo
