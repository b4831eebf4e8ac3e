#include "protocol/csv.h"
#include "logs/eventlog.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QLoggingCategory>
#include <QSaveFile>
#include <QStandardPaths>
#include <QTextStream>

Q_LOGGING_CATEGORY(lcLog, "jumo.log", QtWarningMsg)

namespace jumo {

EventLog::EventLog(const QString &path, QObject *parent, Open mode) : QObject(parent), m_path(path)
{
    if (m_path.isEmpty() || mode == Open::AppendOnly)
        return;
    QFile file(m_path);
    if (!file.exists())
        return;
    if (!file.open(QIODevice::ReadOnly)) {
        m_lastError = tr("cannot read %1: %2").arg(m_path, file.errorString());
        return;
    }
    int line = 0;
    while (!file.atEnd()) {
        const QByteArray bytes = file.readLine();
        ++line;
        if (bytes.trimmed().isEmpty())
            continue;
        const QJsonDocument doc = QJsonDocument::fromJson(bytes);
        if (doc.isObject())
            m_records << doc.object();
        else   // a line cut by a crash: skip it, keep the rest
            qCWarning(lcLog) << m_path << "line" << line << "is not a record";
    }
}

QString EventLog::defaultFolder()
{
    QString folder = qEnvironmentVariable("JUMO_LOG_DIR");
    if (folder.isEmpty())
        folder = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) + QStringLiteral("/jumo");
    QDir().mkpath(folder);
    return folder;
}

void EventLog::append(QJsonObject record)
{
    if (!record.contains(QLatin1String("time")))
        record.insert(QStringLiteral("time"), QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    m_records << record;
    if (!m_path.isEmpty()) {
        QDir().mkpath(QFileInfo(m_path).absolutePath());
        QFile file(m_path);
        if (file.open(QIODevice::ReadWrite | QIODevice::Append)) {
            // A line cut by a crash must not swallow the next record: start a new line.
            QByteArray line = QJsonDocument(record).toJson(QJsonDocument::Compact) + '\n';
            if (file.size() > 0 && file.seek(file.size() - 1) && file.peek(1) != "\n")
                line.prepend('\n');
            file.write(line);
            file.flush();
        } else {
            m_lastError = tr("cannot write %1: %2").arg(m_path, file.errorString());
            qCWarning(lcLog).noquote() << m_lastError;
        }
    }
    emit appended(record);
}

bool EventLog::exportCsv(const QString &path, const QStringList &columns, QString *error) const
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    QTextStream out(&file);
    out << columns.join(QLatin1Char(',')) << '\n';
    for (const QJsonObject &r : m_records) {
        QStringList row;
        for (const QString &c : columns)
            row << csvField(r.value(c).toVariant().toString());
        out << row.join(QLatin1Char(',')) << '\n';
    }
    out.flush();
    if (!file.commit()) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace jumo
