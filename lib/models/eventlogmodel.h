// A table of an event log's records (alarm journal, audit log) for views, newest first,
// that never holds the log in memory: a worker thread finds the lines (the newest at
// once, older ones as a view scrolls down to them, new ones as they are appended, only
// those a filter passes); the model keeps their positions and reads the rows shown.
#pragma once

#include "logs/eventlogscanner.h"

#include <QAbstractTableModel>
#include <QCache>
#include <QThread>

#include <atomic>
#include <deque>
#include <functional>

namespace jumo {

class EventLog;

class EventLogModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    // columns: record keys; titles: their headers, in the same order.
    EventLogModel(EventLog *log, const QStringList &columns, const QStringList &titles, QObject *parent = nullptr);
    ~EventLogModel() override;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    bool canFetchMore(const QModelIndex &parent) const override;
    void fetchMore(const QModelIndex &parent) override;

    // Only the records with the text in a shown column (any case); empty: all of them.
    void setFilter(const QString &text);
    QString filter() const { return m_filter; }
    // A search for older records is under way.
    bool isLoading() const { return m_loading; }
    // Every record (the filter passes) is in the table.
    bool isComplete() const { return m_complete; }
    QString readError() const { return m_readError; }
    // Every record of the log (all its kept files) as CSV, written by the worker thread;
    // exportFinished says how it went.
    void exportCsv(const QString &path);

signals:
    void stateChanged();   // loading, complete or a read error
    void exportFinished(bool ok, const QString &message);

private:
    void onOlderFound(int query, const QList<EventLogScanner::LineRef> &lines, bool finished, bool complete);
    void onNewerFound(int query, const QList<EventLogScanner::LineRef> &lines);
    void requestRefresh();
    // Runs work on the scanner in its thread.
    void ask(const std::function<void(EventLogScanner *)> &work);
    QStringList rowTexts(int row) const;

    QStringList m_columns;
    QStringList m_titles;
    QThread m_thread;
    EventLogScanner *m_scanner;
    std::atomic_int m_latestQuery{1};
    int m_query = 1;
    QString m_filter;
    QList<std::shared_ptr<const LogFile>> m_files;
    std::deque<EventLogScanner::LineRef> m_rows;   // newest first
    mutable QCache<quint64, QStringList> m_shown;
    bool m_loading = true;
    bool m_complete = false;
    bool m_refreshPending = false;
    bool m_refreshAgain = false;
    QString m_readError;
};

} // namespace jumo
