#include "logs/eventlogreader.h"

#include "logs/eventlog.h"
#include "logs/recordfilter.h"

#include <QJsonDocument>

namespace jumo {

EventLogReader::EventLogReader(const QString &path)
{
    for (const QString &name : EventLog::files(path)) {
        QString error;
        if (auto file = LogFile::open(name, &error))
            m_files << file;
        else
            m_lastError = tr("cannot read %1").arg(error);
    }
    m_file = m_files.size() - 1;
    if (m_file >= 0)
        m_cursor = m_files.last()->lastLineEnd(m_files.last()->size());
}

std::optional<QJsonObject> EventLogReader::previous()
{
    while (m_read.isEmpty() && m_file >= 0) {
        m_cursor = m_files.at(m_file)->linesBefore(m_cursor, 64 * 1024, [this](const LogFile::Line &line) {
            if (RecordFilter::looksLikeRecord(line.text)) {
                const QJsonDocument doc = QJsonDocument::fromJson(line.text.toByteArray());
                if (doc.isObject())
                    m_read << doc.object();
            }
            return true;
        });
        if (m_cursor == 0 && --m_file >= 0)
            m_cursor = m_files.at(m_file)->lastLineEnd(m_files.at(m_file)->size());
    }
    if (m_read.isEmpty())
        return std::nullopt;
    return m_read.takeFirst();
}

} // namespace jumo
