// jumoctl history --json written as it is read: the document QJsonDocument would give
// (indented, its keys in its order), one record at a time, so that a long history never
// has to fit in memory before its first line is printed.
#pragma once

#include <QJsonObject>
#include <QString>
#include <QTextStream>

namespace jumo {

class HistoryJsonWriter
{
public:
    explicit HistoryJsonWriter(QTextStream &out);

    // {"device", "entries": [...], "from", "to"}: the span is given first and printed
    // after the entries, where QJsonDocument's key order puts it.
    void begin(const QString &device, const QString &from, const QString &to);
    void beginEntry(const QString &entry, const QString &unit);
    void record(const QJsonObject &record);
    void endEntry();
    void end();

private:
    QTextStream &m_out;
    QString m_from;
    QString m_to;
    QString m_unit;
    bool m_firstEntry = true;
    bool m_firstRecord = true;
};

} // namespace jumo
