// Logs chosen live values of chosen devices to CSV files at a fixed interval, starting a
// new file when one grows past a size or the day changes, keeping the newest files it
// wrote when asked to. Rows are the same as "jumoctl monitor --csv":
// time,device,id,value,unit,status. Every write is checked: logging stops and says why
// (failed) rather than go on with rows that never reach the disk.
#pragma once

#include "bus/devicesource.h"

#include <QDate>
#include <QFile>
#include <QTimer>

namespace jumo {

class DataLogger : public QObject
{
    Q_OBJECT

public:
    struct Settings
    {
        QString folder;
        int intervalMs = 1000;
        qint64 maxFileBytes = 10 * 1024 * 1024;
        int keepFiles = 0;   // of the files this logger wrote, the newest kept; 0: all
        QList<QPair<DeviceId, QString>> entries;   // device, entry id
    };

    DataLogger(const DeviceSource *devices, QObject *parent = nullptr);

    bool start(const Settings &settings, QString *error);
    void stop();
    bool isRunning() const { return m_timer.isActive(); }
    QString currentFile() const { return m_file.fileName(); }
    QStringList files() const { return m_files; }
    int rowsWritten() const { return m_rows; }

signals:
    void failed(const QString &reason);

private:
    void sample();
    bool openNewFile(QString *error);
    bool write(const QByteArray &rows, QString *error);
    // Flushed and synced, so that a power cut after a new file started loses nothing of
    // the old one.
    bool closeFile(QString *error);
    void fail(const QString &reason);

    const DeviceSource *m_devices;
    Settings m_settings;
    QTimer m_timer;
    QFile m_file;
    QDate m_fileDate;
    QStringList m_files;
    int m_rows = 0;
};

} // namespace jumo
