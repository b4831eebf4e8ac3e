// An append-only log of records kept as JSON lines in a file, rotated by size into
// older files beside it, so it survives restarts and a crash loses at most the line being
// written. A record reported kept is on disk (synced); one that is not is reported. The
// alarm journal and the write audit log are two of them; the HMI and jumoctl append to
// the same audit log at once, so appends and rotation are locked against each other.
#pragma once

#include <QJsonObject>
#include <QObject>

class QSettings;

namespace jumo {

class EventLog : public QObject
{
    Q_OBJECT

public:
    struct Rotation
    {
        qint64 maxFileBytes = 32 * 1024 * 1024;
        int keepFiles = 9;   // older files kept beside the current one

        // logs/maxFileMiB and logs/keepFiles (the user's settings, else the system's).
        static Rotation fromSettings(const QSettings &settings);
    };

    // Opens nothing yet: the file is opened (and created) by the first append.
    explicit EventLog(const QString &path, QObject *parent = nullptr);
    ~EventLog() override;

    // The folder where the HMI and jumoctl keep their logs ($JUMO_LOG_DIR, else the
    // application data folder + /jumo), created when missing. Empty (and why in error)
    // when there is none: no JUMO_LOG_DIR, and neither XDG_DATA_HOME nor HOME is set.
    static QString defaultFolder(QString *error = nullptr);
    // The files of the log at path that exist, oldest first: the rotated ones
    // (path's name + "-" + UTC time of the rotation), then path itself.
    static QStringList files(const QString &path);

    QString path() const { return m_path; }
    QString lastError() const { return m_lastError; }
    void setRotation(const Rotation &rotation) { m_rotation = rotation; }
    Rotation rotation() const { return m_rotation; }
    // Records not kept since the last one that was.
    int unwrittenRecords() const { return m_unwritten; }

    // Writes the record (a "time" added when it has none), flushed and synced. False
    // (and writeFailed) when the file could not take it: the caller must not pretend it
    // was logged. appended is emitted in either case.
    bool append(QJsonObject record);

signals:
    void appended(const QJsonObject &record);
    void writeFailed(const QString &message);
    // The first record kept after lostRecords were not.
    void writeRecovered(int lostRecords);

private:
    bool writeLine(QByteArray line);
    bool openFile();
    void closeFile();
    bool rotate();
    void setSystemError(int code);

    QString m_path;
    Rotation m_rotation;
    int m_fd = -1;
    QString m_lastError;
    int m_unwritten = 0;
    bool m_rotationFailed = false;
};

} // namespace jumo
