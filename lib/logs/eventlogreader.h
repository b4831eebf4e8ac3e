// Reads an event log's records from the newest back, across its rotated files, for a
// program that needs the recent ones (jumoctl's report: today's writes), without
// reading more of the log than it asks for.
#pragma once

#include "logs/logfile.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QList>

#include <memory>
#include <optional>

namespace jumo {

class EventLogReader
{
    Q_DECLARE_TR_FUNCTIONS(jumo::EventLogReader)

public:
    explicit EventLogReader(const QString &path);

    // Why a file of the log could not be read ("cannot read PATH: reason"); empty if all
    // could. Such a file is left out.
    QString lastError() const { return m_lastError; }
    // The next older record; nullopt after the oldest. Lines that are no record (cut by
    // a crash) are passed over.
    std::optional<QJsonObject> previous();

private:
    QList<std::shared_ptr<const LogFile>> m_files;   // oldest first
    qsizetype m_file = -1;
    qint64 m_cursor = 0;
    QList<QJsonObject> m_read;   // newest first
    QString m_lastError;
};

} // namespace jumo
