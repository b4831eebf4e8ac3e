// Which records of an event log a view shows, read straight from the log's lines: a
// text found, regardless of case, in the shown text of any column (the time as shown,
// in local time). Lines whose values cannot contain the text are passed over without
// parsing them.
#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace jumo {

class RecordFilter
{
public:
    RecordFilter() = default;   // every readable record
    RecordFilter(const QString &text, const QStringList &columns);

    QString text() const { return m_text; }
    // Whether the line is a record (a JSON object) that the filter passes.
    bool matches(QByteArrayView line);

    // The text a view shows for a column of a record: the time, kept in UTC, in local time.
    static QString shownText(const QJsonObject &record, const QString &column);
    // A line that can be a record at all (a cut line cannot), without parsing it.
    static bool looksLikeRecord(QByteArrayView line);

private:
    QString shownTime(const QString &stored);

    QString m_text;
    QStringList m_columns;
    QByteArray m_needle;        // lower-case UTF-8, for the raw line
    bool m_rawSearch = false;   // the text appears in the line as it is shown
    QString m_minuteStored;     // "yyyy-MM-ddTHH:mm" and its local "yyyy-MM-dd HH:mm"
    QString m_minuteShown;
};

} // namespace jumo
