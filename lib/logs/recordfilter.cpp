#include "logs/recordfilter.h"

#include <QDateTime>
#include <QJsonDocument>

#include <algorithm>

namespace jumo {

namespace {

// Whether the ASCII needle (lower case) is in text, regardless of case.
bool containsFolded(QByteArrayView text, QByteArrayView needle)
{
    const auto fold = [](char c) { return c >= 'A' && c <= 'Z' ? char(c + ('a' - 'A')) : c; };
    return std::search(text.begin(), text.end(), needle.begin(), needle.end(),
                       [&fold](char a, char b) { return fold(a) == b; })
         != text.end();
}

// Whether a value of the line (a string or a bare number, true, false, null; never a
// key) may hold the needle: a quick look at the line as it is, before it is parsed.
// A string with escapes may hold it in another spelling: maybe.
bool valueMayContain(QByteArrayView line, QByteArrayView needle)
{
    const auto endsBareValue = [](char c) { return c == ',' || c == '}' || c == ']' || c == ' ' || c == '\t'; };
    const qsizetype n = line.size();
    qsizetype i = 0;
    while (i < n) {
        const char c = line[i];
        if (c == '"') {
            const qsizetype start = ++i;
            bool escaped = false;
            while (i < n && line[i] != '"') {
                escaped = escaped || line[i] == '\\';
                i += line[i] == '\\' ? 2 : 1;
            }
            const qsizetype end = std::min(i, n);
            ++i;
            qsizetype next = i;
            while (next < n && (line[next] == ' ' || line[next] == '\t'))
                ++next;
            if (next < n && line[next] == ':')
                continue;   // a key
            if (escaped || containsFolded(line.sliced(start, end - start), needle))
                return true;
        } else if (c == ',' || c == ':' || c == '{' || c == '}' || c == '[' || c == ']' || c == ' ' || c == '\t') {
            ++i;
        } else {
            const qsizetype start = i;
            while (i < n && !endsBareValue(line[i]))
                ++i;
            if (containsFolded(line.sliced(start, i - start), needle))
                return true;
        }
    }
    return false;
}

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
    if (m_rawSearch && !valueMayContain(line, m_needle))
        return false;
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
