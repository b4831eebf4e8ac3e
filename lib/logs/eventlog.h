// An append-only log of records kept in a file as JSON lines, so it survives restarts
// and a crash loses at most the line being written. The alarm journal and the write
// audit log are two of them.
#pragma once

#include <QDateTime>
#include <QFile>
#include <QJsonObject>
#include <QList>
#include <QObject>

namespace jumo {

class EventLog : public QObject
{
    Q_OBJECT

public:
    enum class Open { ReadRecords, AppendOnly };

    // Opens the file and reads its records (or, AppendOnly, only appends to it: for
    // jumoctl, which never shows them). An empty path keeps records in memory only.
    explicit EventLog(const QString &path, QObject *parent = nullptr, Open mode = Open::ReadRecords);

    // The folder where the HMI and jumoctl keep their logs ($JUMO_LOG_DIR, else the
    // application data folder + /jumo), created when missing.
    static QString defaultFolder();

    QString path() const { return m_path; }
    QString lastError() const { return m_lastError; }
    const QList<QJsonObject> &records() const { return m_records; }

    // Kept in memory in any case; false (and writeFailed) when the file could not take
    // it: the caller must not pretend it was logged.
    bool append(QJsonObject record);
    // CSV with the given columns (keys of the records), one row per record.
    bool exportCsv(const QString &path, const QStringList &columns, QString *error = nullptr) const;

signals:
    void appended(const QJsonObject &record);
    void writeFailed(const QString &message);

private:
    bool writeLine(QByteArray line);

    QString m_path;
    QString m_lastError;
    QList<QJsonObject> m_records;
};

} // namespace jumo
