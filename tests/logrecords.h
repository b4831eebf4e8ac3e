// Every record of an event log (all its kept files), oldest first, for tests.
#pragma once

#include "logs/eventlogreader.h"

namespace jumo::test {

inline QList<QJsonObject> logRecords(const QString &path)
{
    QList<QJsonObject> out;
    EventLogReader reader(path);
    while (const auto record = reader.previous())
        out.prepend(*record);
    return out;
}

} // namespace jumo::test
