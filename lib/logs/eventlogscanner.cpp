#include "logs/eventlogscanner.h"

#include "logs/eventlog.h"
#include "protocol/csv.h"
#include "protocol/filesaver.h"

#include <QElapsedTimer>
#include <QJsonDocument>

namespace jumo {

namespace {

constexpr qint64 backwardChunk = 256 * 1024;
constexpr qint64 exportBuffer = 1024 * 1024;
constexpr int partialResultMs = 100;   // a long search shows what it found meanwhile

} // namespace

EventLogScanner::EventLogScanner(const QString &path, const QStringList &columns, const std::atomic_int *latestQuery,
                                 QObject *parent)
    : QObject(parent), m_path(path), m_columns(columns), m_latestQuery(latestQuery)
{
}

bool EventLogScanner::stopped(int query) const
{
    return m_latestQuery->load() != query;
}

void EventLogScanner::addFile(const QString &path)
{
    QString error;
    std::shared_ptr<const LogFile> file = LogFile::open(path, &error);
    if (!file) {
        emit readFailed(tr("cannot read %1").arg(error));
        return;
    }
    m_files << file;
    emit fileOpened(int(m_files.size() - 1), file);
}

void EventLogScanner::openFiles()
{
    m_opened = true;
    for (const QString &path : EventLog::files(m_path))
        addFile(path);
    // A line being written right now is not complete yet: the next refresh has it.
    m_tailEnd = m_files.isEmpty() ? 0 : m_files.last()->lastLineEnd(m_files.last()->size());
}

void EventLogScanner::addNewFiles(QList<LineRef> *found)
{
    // The files that came since the newest one known: rotated ones, then the current one.
    const QStringList paths = EventLog::files(m_path);
    qsizetype lastKnown = -1;
    for (qsizetype i = 0; i < paths.size(); ++i) {
        for (const auto &file : std::as_const(m_files)) {
            if (file->isAt(paths.at(i)))
                lastKnown = i;
        }
    }
    for (qsizetype i = lastKnown + 1; i < paths.size(); ++i) {
        const qsizetype before = m_files.size();
        addFile(paths.at(i));
        if (m_files.size() == before)
            continue;
        const int index = int(m_files.size() - 1);
        m_tailEnd = m_files.last()->linesFrom(0, m_files.last()->size(), [&](const LogFile::Line &line) {
            if (m_filter.matches(line.text))
                found->append(LineRef{line.offset, qint32(line.length), index});
            return true;
        });
    }
}

void EventLogScanner::start(int query, const QString &filter, int count)
{
    if (!m_opened)
        openFiles();
    m_query = query;
    m_filter = RecordFilter(filter, m_columns);
    m_cursorFile = int(m_files.size()) - 1;
    m_cursor = m_tailEnd;
    fetchOlder(query, count);
}

void EventLogScanner::fetchOlder(int query, int count)
{
    if (query != m_query || stopped(query))
        return;
    QList<LineRef> found;
    QElapsedTimer sinceShown;
    sinceShown.start();
    while (m_cursorFile >= 0 && count > 0) {
        if (stopped(query))
            return;   // a newer query starts from its own beginning
        const int index = m_cursorFile;
        m_cursor = m_files.at(index)->linesBefore(m_cursor, backwardChunk, [&](const LogFile::Line &line) {
            if (m_filter.matches(line.text)) {
                found << LineRef{line.offset, qint32(line.length), index};
                --count;
            }
            return count > 0;
        });
        if (m_cursor == 0 && --m_cursorFile >= 0)
            m_cursor = m_files.at(m_cursorFile)->lastLineEnd(m_files.at(m_cursorFile)->size());
        if (!found.isEmpty() && sinceShown.elapsed() >= partialResultMs && m_cursorFile >= 0 && count > 0) {
            emit olderFound(query, found, false, false);
            found.clear();
            sinceShown.restart();
        }
    }
    emit olderFound(query, found, true, m_cursorFile < 0);
}

void EventLogScanner::refresh(int query)
{
    if (!m_opened)
        openFiles();
    QList<LineRef> found;
    if (m_files.isEmpty()) {
        addNewFiles(&found);
    } else {
        // Looked at before the last lines are read: a rotation after the look leaves
        // lines for the next refresh, never behind.
        const bool rotated = !m_files.last()->isAt(m_path);
        const int index = int(m_files.size() - 1);
        m_tailEnd = m_files.last()->linesFrom(m_tailEnd, m_files.last()->size(), [&](const LogFile::Line &line) {
            if (m_filter.matches(line.text))
                found << LineRef{line.offset, qint32(line.length), index};
            return true;
        });
        if (rotated)
            addNewFiles(&found);
    }
    emit newerFound(query, found);
}

void EventLogScanner::exportCsv(const QString &target)
{
    if (!m_opened)
        openFiles();
    FileSaver out(target);
    QByteArray buffer = m_columns.join(QLatin1Char(',')).toUtf8() + '\n';
    int records = 0;
    for (const auto &file : std::as_const(m_files)) {
        file->linesFrom(0, file->size(), [&](const LogFile::Line &line) {
            if (!RecordFilter::looksLikeRecord(line.text))
                return true;
            const QJsonDocument doc = QJsonDocument::fromJson(line.text.toByteArray());
            if (!doc.isObject())
                return true;
            const QJsonObject record = doc.object();
            QStringList row;
            for (const QString &c : std::as_const(m_columns))
                row << csvField(record.value(c).toVariant().toString());
            buffer += row.join(QLatin1Char(',')).toUtf8() + '\n';
            ++records;
            if (buffer.size() >= exportBuffer) {
                out.write(buffer);
                buffer.clear();
            }
            return m_latestQuery->load() >= 0;
        });
        if (m_latestQuery->load() < 0)
            return;   // the view is gone: nothing replaces the target
    }
    out.write(buffer);
    QString error;
    if (out.commit(&error))
        emit exportFinished(true, tr("%n record(s) exported to %1", nullptr, records).arg(target));
    else
        emit exportFinished(false, error);
}

} // namespace jumo
