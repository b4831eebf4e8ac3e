#include "logs/recordfilter.h"

#include <QDateTime>
#include <QJsonDocument>

namespace jumo {

namespace {

const QString shownTimeFormat = QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz");

QString localTime(const QString &stored)
{
    const QDateTime t = QDateTime::fromString(stored, Qt::ISODateWithMs);
    return t.isValid() ? t.toLocalTime().toString(shownTimeFormat) : stored;
}

} // namespace

RecordFilter::RecordFilter(const QString &text, const QStringList &columns) : m_text(text), m_columns(columns)
{
    // The line holds a value as it is shown unless JSON escapes it (quotes, backslashes,
    // control characters), it is the time (shown in local time) or case goes beyond ASCII.
    bool plain = !text.isEmpty();
    bool timeLike = true;
    for (const QChar c : text) {
        plain = plain && c.unicode() >= 0x20 && c.unicode() < 0x7f && c != QLatin1Char('"') && c != QLatin1Char('\\');
        timeLike = timeLike && (c.isDigit() || QStringLiteral("-:. ").contains(c));
    }
    m_rawSearch = plain && !(timeLike && columns.contains(QLatin1String("time")));
    m_needle = text.toLower().toUtf8();
}

bool RecordFilter::looksLikeRecord(QByteArrayView line)
{
    line = line.trimmed();
    return line.size() >= 2 && line.front() == '{' && line.back() == '}';
}

bool RecordFilter::matches(QByteArrayView line)
{
    if (!looksLikeRecord(line))
        return false;
    if (m_text.isEmpty())
        return true;
    if (m_rawSearch) {
        m_lowered.resize(line.size());
        for (qsizetype i = 0; i < line.size(); ++i) {
            const char c = line[i];
            m_lowered[i] = c >= 'A' && c <= 'Z' ? char(c + ('a' - 'A')) : c;
        }
        if (QByteArrayView(m_lowered).indexOf(m_needle) < 0)
            return false;
    }
    const QJsonDocument doc = QJsonDocument::fromJson(line.toByteArray());
    if (!doc.isObject())
        return false;
    const QJsonObject record = doc.object();
    for (const QString &column : std::as_const(m_columns)) {
        const QString shown = column == QLatin1String("time") ? shownTime(record.value(column).toString())
                                                              : shownText(record, column);
        if (shown.contains(m_text, Qt::CaseInsensitive))
            return true;
    }
    return false;
}

QString RecordFilter::shownTime(const QString &stored)
{
    // Records come in time order: the local time of their minute is worked out once.
    // (Time zones are whole minutes apart.)
    const bool usual = stored.size() == 24 && stored.at(10) == QLatin1Char('T') && stored.endsWith(QLatin1Char('Z'));
    if (!usual)
        return localTime(stored);
    if (!stored.startsWith(m_minuteStored) || m_minuteStored.isEmpty()) {
        m_minuteStored = stored.left(16);
        m_minuteShown = localTime(stored).left(16);
    }
    return m_minuteShown + stored.mid(16, 7);
}

QString RecordFilter::shownText(const QJsonObject &record, const QString &column)
{
    const QJsonValue v = record.value(column);
    if (column == QLatin1String("time"))
        return localTime(v.toString());
    return v.toVariant().toString();
}

} // namespace jumo
