#include "models/eventlogmodel.h"

#include "logs/eventlog.h"

#include <QDateTime>

namespace jumo {

EventLogModel::EventLogModel(EventLog *log, const QStringList &columns, const QStringList &titles, QObject *parent)
    : QAbstractTableModel(parent), m_log(log), m_columns(columns), m_titles(titles)
{
    connect(m_log, &EventLog::appended, this, [this] {
        // The record is already in the log: announce the last row.
        const int row = int(m_log->records().size()) - 1;
        beginInsertRows({}, row, row);
        endInsertRows();
    });
}

int EventLogModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_log->records().size());
}

int EventLogModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_columns.size());
}

QVariant EventLogModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_log->records().size() || (role != Qt::DisplayRole && role != Qt::ToolTipRole))
        return {};
    const QJsonValue v = m_log->records().at(index.row()).value(m_columns.at(index.column()));
    if (m_columns.at(index.column()) == QLatin1String("time")) {
        // Stored in UTC; shown in local time.
        const QDateTime t = QDateTime::fromString(v.toString(), Qt::ISODateWithMs);
        return t.isValid() ? t.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")) : v.toString();
    }
    return v.toVariant().toString();
}

QVariant EventLogModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole || section >= m_titles.size())
        return {};
    return m_titles.at(section);
}

} // namespace jumo
