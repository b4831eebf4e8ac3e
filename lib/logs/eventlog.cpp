#include "protocol/csv.h"
#include "logs/eventlog.h"
#include "protocol/filesaver.h"
#include "protocol/regularfile.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QLoggingCategory>
#include <QStandardPaths>

#include <cerrno>
#include <cstring>
#include <unistd.h>

Q_LOGGING_CATEGORY(lcLog, "jumo.log", QtWarningMsg)

namespace jumo {

EventLog::EventLog(const QString &path, QObject *parent, Open mode) : QObject(parent), m_path(path)
{
    if (m_path.isEmpty() || mode == Open::AppendOnly)
        return;
    QFile file;
    if (!QFile::exists(m_path))
        return;
    QString reason;
    if (!RegularFile::openForReading(file, m_path, &reason)) {
        m_lastError = tr("cannot read %1").arg(reason);
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

bool EventLog::append(QJsonObject record)
{
    if (!record.contains(QLatin1String("time")))
        record.insert(QStringLiteral("time"), QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    m_records << record;
    const bool written = m_path.isEmpty() || writeLine(QJsonDocument(record).toJson(QJsonDocument::Compact));
    emit appended(record);
    if (!written) {
        qCDebug(lcLog).noquote() << m_lastError;   // the caller reports it
        emit writeFailed(m_lastError);
    }
    return written;
}

bool EventLog::writeLine(QByteArray line)
{
    QDir().mkpath(QFileInfo(m_path).absolutePath());
    QFile file;
    QString reason;
    if (!RegularFile::openForAppending(file, m_path, &reason)) {
        m_lastError = tr("cannot write %1").arg(reason);
        return false;
    }
    // A line cut by a crash must not swallow the next record: start a new line.
    line += '\n';
    if (file.size() > 0 && file.seek(file.size() - 1) && file.peek(1) != "\n")
        line.prepend('\n');
    // Flushed and synced: a record the caller was told about must survive a power cut.
    if (file.write(line) != line.size() || !file.flush() || ::fsync(file.handle()) != 0) {
        m_lastError = tr("cannot write %1: %2")
                              .arg(m_path, file.error() != QFileDevice::NoError ? file.errorString()
                                                                                 : QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    return true;
}

bool EventLog::exportCsv(const QString &path, const QStringList &columns, QString *error) const
{
    QByteArray csv = columns.join(QLatin1Char(',')).toUtf8() + '\n';
    for (const QJsonObject &r : m_records) {
        QStringList row;
        for (const QString &c : columns)
            row << csvField(r.value(c).toVariant().toString());
        csv += row.join(QLatin1Char(',')).toUtf8() + '\n';
    }
    return FileSaver::save(path, csv, error);
}

} // namespace jumo
