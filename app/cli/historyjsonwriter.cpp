#include "historyjsonwriter.h"

#include <QJsonArray>
#include <QJsonDocument>

namespace jumo {

namespace {

// A string as QJsonDocument writes it, quotes and escapes included.
QString jsonString(const QString &text)
{
    const QByteArray array = QJsonDocument(QJsonArray{text}).toJson(QJsonDocument::Compact);
    return QString::fromUtf8(array.mid(1, array.size() - 2));
}

QString indent(int levels)
{
    return QString(4 * levels, QLatin1Char(' '));
}

} // namespace

HistoryJsonWriter::HistoryJsonWriter(QTextStream &out) : m_out(out) { }

void HistoryJsonWriter::begin(const QString &device, const QString &from, const QString &to)
{
    m_from = from;
    m_to = to;
    m_firstEntry = true;
    m_out << "{\n" << indent(1) << "\"device\": " << jsonString(device) << ",\n" << indent(1) << "\"entries\": [\n";
}

void HistoryJsonWriter::beginEntry(const QString &entry, const QString &unit)
{
    if (!m_firstEntry)
        m_out << ",\n";
    m_firstEntry = false;
    m_firstRecord = true;
    m_unit = unit;
    m_out << indent(2) << "{\n" << indent(3) << "\"entry\": " << jsonString(entry) << ",\n" << indent(3)
          << "\"records\": [\n";
}

void HistoryJsonWriter::record(const QJsonObject &record)
{
    if (!m_firstRecord)
        m_out << ",\n";
    m_firstRecord = false;
    // The object as QJsonDocument indents it at the top, moved in to its depth.
    const QList<QByteArray> lines = QJsonDocument(record).toJson(QJsonDocument::Indented).trimmed().split('\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (i > 0)
            m_out << '\n';
        m_out << indent(4) << QString::fromUtf8(lines[i]);
    }
}

void HistoryJsonWriter::endEntry()
{
    if (!m_firstRecord)
        m_out << '\n';
    m_out << indent(3) << "],\n" << indent(3) << "\"unit\": " << jsonString(m_unit) << '\n' << indent(2) << '}';
}

void HistoryJsonWriter::end()
{
    if (!m_firstEntry)
        m_out << '\n';
    m_out << indent(1) << "],\n"
          << indent(1) << "\"from\": " << jsonString(m_from) << ",\n"
          << indent(1) << "\"to\": " << jsonString(m_to) << "\n}\n";
}

} // namespace jumo
