#include "models/eventlogmodel.h"

#include "logs/eventlog.h"

#include <QJsonDocument>

namespace jumo {

namespace {

constexpr int firstRecords = 500;       // a screenful or two, found at once
constexpr int largestBatch = 100000;    // batches grow with the table, up to this
constexpr int shownRowsCached = 4096;

} // namespace

EventLogModel::EventLogModel(EventLog *log, const QStringList &columns, const QStringList &titles, QObject *parent)
    : QAbstractTableModel(parent), m_columns(columns), m_titles(titles),
      m_scanner(new EventLogScanner(log->path(), columns, &m_latestQuery)), m_shown(shownRowsCached)
{
    m_scanner->moveToThread(&m_thread);
    connect(m_scanner, &EventLogScanner::fileOpened, this,
            [this](int index, const std::shared_ptr<const LogFile> &file) {
                Q_ASSERT(index == m_files.size());
                m_files << file;
            });
    connect(m_scanner, &EventLogScanner::olderFound, this, &EventLogModel::onOlderFound);
    connect(m_scanner, &EventLogScanner::newerFound, this, &EventLogModel::onNewerFound);
    connect(m_scanner, &EventLogScanner::readFailed, this, [this](const QString &message) {
        m_readError = message;
        emit stateChanged();
    });
    connect(m_scanner, &EventLogScanner::exportFinished, this, &EventLogModel::exportFinished);
    connect(log, &EventLog::appended, this, &EventLogModel::requestRefresh);
    m_thread.setObjectName(QStringLiteral("jumo-log-reader"));
    m_thread.start(QThread::LowPriority);
    ask([query = m_query](EventLogScanner *scanner) { scanner->start(query, QString(), firstRecords); });
}

EventLogModel::~EventLogModel()
{
    m_latestQuery = -1;   // a long search or export stops at once
    m_thread.quit();
    m_thread.wait();
    delete m_scanner;
}

int EventLogModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int EventLogModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_columns.size());
}

QStringList EventLogModel::rowTexts(int row) const
{
    const EventLogScanner::LineRef &line = m_rows[size_t(row)];
    const quint64 key = (quint64(line.file) << 40) | quint64(line.offset);
    if (const QStringList *texts = m_shown.object(key))
        return *texts;
    QStringList texts;
    const std::shared_ptr<const LogFile> file = m_files.value(line.file);
    const QJsonDocument doc = file ? QJsonDocument::fromJson(file->read(line.offset, line.length)) : QJsonDocument();
    if (doc.isObject()) {
        for (const QString &column : m_columns)
            texts << RecordFilter::shownText(doc.object(), column);
    } else {   // changed under us, or a broken line that looked like a record
        for (qsizetype i = 0; i + 1 < m_columns.size(); ++i)
            texts << QString();
        texts << tr("unreadable record at byte %1 of %2").arg(line.offset).arg(file ? file->path() : QString());
    }
    m_shown.insert(key, new QStringList(texts));
    return texts;
}

QVariant EventLogModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount() || (role != Qt::DisplayRole && role != Qt::ToolTipRole))
        return {};
    return rowTexts(index.row()).value(index.column());
}

QVariant EventLogModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole || section >= m_titles.size())
        return {};
    return m_titles.at(section);
}

bool EventLogModel::canFetchMore(const QModelIndex &parent) const
{
    return !parent.isValid() && !m_complete;
}

void EventLogModel::fetchMore(const QModelIndex &parent)
{
    if (parent.isValid() || m_complete || m_loading)
        return;
    m_loading = true;
    emit stateChanged();
    ask([query = m_query, count = std::clamp(rowCount(), firstRecords, largestBatch)](EventLogScanner *scanner) {
        scanner->fetchOlder(query, count);
    });
}

void EventLogModel::setFilter(const QString &text)
{
    if (text == m_filter)
        return;
    m_filter = text;
    m_latestQuery = ++m_query;   // the search for the old filter stops
    beginResetModel();
    m_rows.clear();
    m_shown.clear();
    endResetModel();
    m_loading = true;
    m_complete = false;
    emit stateChanged();
    ask([query = m_query, text](EventLogScanner *scanner) { scanner->start(query, text, firstRecords); });
}

void EventLogModel::ask(const std::function<void(EventLogScanner *)> &work)
{
    QMetaObject::invokeMethod(m_scanner, [scanner = m_scanner, work] { work(scanner); }, Qt::QueuedConnection);
}

void EventLogModel::exportCsv(const QString &path)
{
    ask([path](EventLogScanner *scanner) { scanner->exportCsv(path); });
}

void EventLogModel::onOlderFound(int query, const QList<EventLogScanner::LineRef> &lines, bool finished, bool complete)
{
    if (query != m_query)
        return;
    if (!lines.isEmpty()) {
        const int first = rowCount();
        beginInsertRows({}, first, first + int(lines.size()) - 1);
        m_rows.insert(m_rows.end(), lines.cbegin(), lines.cend());
        endInsertRows();
    }
    if (finished) {
        m_loading = false;
        m_complete = complete;
        emit stateChanged();
    }
}

void EventLogModel::requestRefresh()
{
    // One look at a time: records that come meanwhile are found by the next one.
    if (m_refreshPending) {
        m_refreshAgain = true;
        return;
    }
    m_refreshPending = true;
    ask([query = m_query](EventLogScanner *scanner) { scanner->refresh(query); });
}

void EventLogModel::onNewerFound(int query, const QList<EventLogScanner::LineRef> &lines)
{
    m_refreshPending = false;
    if (query == m_query && !lines.isEmpty()) {
        beginInsertRows({}, 0, int(lines.size()) - 1);
        for (const EventLogScanner::LineRef &line : lines)   // oldest first: each goes on top
            m_rows.push_front(line);
        endInsertRows();
    }
    if (m_refreshAgain) {
        m_refreshAgain = false;
        requestRefresh();
    }
}

} // namespace jumo
