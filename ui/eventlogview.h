// A page for an event log (alarm journal or write audit log): the records in a table,
// a filter over all columns, and CSV export.
#pragma once

#include <QWidget>

class QLineEdit;
class QSortFilterProxyModel;
class QTableView;

namespace jumo {

class EventLog;
class EventLogModel;

class EventLogView : public QWidget
{
    Q_OBJECT

public:
    EventLogView(EventLog *log, const QStringList &columns, const QStringList &titles, QWidget *parent = nullptr);

    int visibleRows() const;
    void setFilter(const QString &text);

private:
    EventLog *m_log;
    QStringList m_columns;
    EventLogModel *m_model;
    QSortFilterProxyModel *m_filter;
    QTableView *m_table;
    QLineEdit *m_filterEdit;
};

} // namespace jumo
