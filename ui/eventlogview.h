// A page for an event log (alarm journal or write audit log): the records in a table,
// newest first, older ones loaded as the table is scrolled down to them; a filter over
// all columns (searched in the background as the user types); CSV export of the log.
#pragma once

#include <QWidget>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;
class QTimer;

namespace jumo {

class EventLog;
class EventLogModel;

class EventLogView : public QWidget
{
    Q_OBJECT

public:
    EventLogView(EventLog *log, const QStringList &columns, const QStringList &titles, QWidget *parent = nullptr);

    EventLogModel *model() const { return m_model; }
    QTableView *table() const { return m_table; }
    int visibleRows() const;
    // At once (typing waits for a pause first).
    void setFilter(const QString &text);

private:
    void updateState();

    EventLogModel *m_model;
    QTableView *m_table;
    QLineEdit *m_filterEdit;
    QTimer *m_typing;
    QLabel *m_state;
    QPushButton *m_exportButton;
};

} // namespace jumo
