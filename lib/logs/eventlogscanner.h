// Reads an event log for a view in a worker thread: the newest records first, older ones
// in batches as the view asks, new ones as they are appended (across rotations, and by
// other processes too), only those a filter passes; and exports the whole log as CSV.
// Lines are handed over as positions: the view reads the few it shows. The slots are
// called queued from the view's thread; results come back as signals.
#pragma once

#include "logs/logfile.h"
#include "logs/recordfilter.h"

#include <QList>
#include <QObject>

#include <atomic>
#include <memory>

namespace jumo {

class EventLogScanner : public QObject
{
    Q_OBJECT

public:
    struct LineRef
    {
        qint64 offset;
        qint32 length;
        qint32 file;   // index in the files announced by fileOpened
    };

    // latestQuery: the newest query the view has asked for (set before asking); work on
    // an older one stops early, and -1 stops everything.
    EventLogScanner(const QString &path, const QStringList &columns, const std::atomic_int *latestQuery,
                    QObject *parent = nullptr);

    // A new query, from the newest record back: the first count records it passes.
    void start(int query, const QString &filter, int count);
    // The next count older records of the query.
    void fetchOlder(int query, int count);
    // Records appended since the last look (newerFound, even when there are none).
    void refresh(int query);
    // Every record of every kept file, oldest first, as CSV with the columns.
    void exportCsv(const QString &target);

signals:
    void fileOpened(int index, const std::shared_ptr<const jumo::LogFile> &file);
    // Newest first. finished: the request is done (else more follows); complete: there
    // is nothing older.
    void olderFound(int query, const QList<jumo::EventLogScanner::LineRef> &lines, bool finished, bool complete);
    // Oldest first.
    void newerFound(int query, const QList<jumo::EventLogScanner::LineRef> &lines);
    void readFailed(const QString &message);
    void exportFinished(bool ok, const QString &message);

private:
    void openFiles();
    void addNewFiles(QList<LineRef> *found);
    void addFile(const QString &path);
    bool stopped(int query) const;

    QString m_path;
    QStringList m_columns;
    const std::atomic_int *m_latestQuery;
    QList<std::shared_ptr<const LogFile>> m_files;   // oldest first
    bool m_opened = false;
    qint64 m_tailEnd = 0;   // the newest file's lines before this are known
    int m_query = 0;
    RecordFilter m_filter;
    int m_cursorFile = -1;   // where the query goes on back
    qint64 m_cursor = 0;
};

} // namespace jumo
