#include "protocol/csv.h"
#include "logs/datalogger.h"

#include <QDateTime>
#include <QDir>
#include <QLoggingCategory>

#include <cerrno>
#include <cstring>
#include <unistd.h>

Q_DECLARE_LOGGING_CATEGORY(lcLog)

namespace jumo {

DataLogger::DataLogger(const DeviceSource *devices, QObject *parent) : QObject(parent), m_devices(devices)
{
    connect(&m_timer, &QTimer::timeout, this, &DataLogger::sample);
}

bool DataLogger::start(const Settings &settings, QString *error)
{
    stop();
    if (settings.entries.isEmpty() || settings.intervalMs < 100 || settings.maxFileBytes < 1024 || settings.keepFiles < 0) {
        if (error)
            *error = tr("choose at least one value, an interval of at least 100 ms and files of at least 1 KiB");
        return false;
    }
    m_settings = settings;
    if (!QDir().mkpath(settings.folder)) {
        if (error)
            *error = tr("cannot create the folder %1").arg(settings.folder);
        return false;
    }
    m_files.clear();
    m_rows = 0;
    if (!openNewFile(error)) {
        m_file.close();
        return false;
    }
    m_timer.start(settings.intervalMs);
    return true;
}

void DataLogger::stop()
{
    m_timer.stop();
    QString error;
    if (!closeFile(&error))
        emit failed(error);
}

void DataLogger::fail(const QString &reason)
{
    m_timer.stop();
    m_file.close();
    emit failed(reason);
}

bool DataLogger::closeFile(QString *error)
{
    if (!m_file.isOpen())
        return true;
    const bool ok = ::fdatasync(m_file.handle()) == 0;
    const int code = errno;
    m_file.close();
    if (!ok && error)
        *error = tr("cannot write %1: %2").arg(m_file.fileName(), QString::fromLocal8Bit(std::strerror(code)));
    return ok;
}

bool DataLogger::write(const QByteArray &rows, QString *error)
{
    // Straight to the file, so that a write cut short (a full disk) is told with the
    // system's reason, which QFile leaves out then.
    qint64 written = 0;
    while (written < rows.size()) {
        const ssize_t n = ::write(m_file.handle(), rows.constData() + written, size_t(rows.size() - written));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            if (error)
                *error = tr("cannot write %1: %2")
                                 .arg(m_file.fileName(), QString::fromLocal8Bit(std::strerror(n < 0 ? errno : ENOSPC)));
            return false;
        }
        written += n;
    }
    return true;
}

bool DataLogger::openNewFile(QString *error)
{
    if (!closeFile(error))
        return false;
    const QDateTime now = QDateTime::currentDateTime();
    QString name = QDir(m_settings.folder).filePath(QStringLiteral("jumo-data-%1.csv").arg(now.toString(QStringLiteral("yyyyMMdd-HHmmss"))));
    for (int n = 2; QFile::exists(name); ++n)   // two files within one second
        name = QDir(m_settings.folder)
                       .filePath(QStringLiteral("jumo-data-%1-%2.csv").arg(now.toString(QStringLiteral("yyyyMMdd-HHmmss"))).arg(n));
    m_file.setFileName(name);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Unbuffered)) {
        if (error)
            *error = tr("cannot write %1: %2").arg(name, m_file.errorString());
        return false;
    }
    m_fileDate = now.date();
    m_files << name;
    if (!write("time,device,id,value,unit,status\n", error))
        return false;
    while (m_settings.keepFiles > 0 && m_files.size() > m_settings.keepFiles) {
        const QString oldest = m_files.takeFirst();
        if (!QFile::remove(oldest))
            qCWarning(lcLog).noquote() << "cannot remove" << oldest;
    }
    return true;
}

void DataLogger::sample()
{
    if (m_file.size() >= m_settings.maxFileBytes || QDate::currentDate() != m_fileDate) {
        QString error;
        if (!openNewFile(&error)) {
            fail(error);
            return;
        }
    }
    const QString time = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
    QByteArray rows;
    int count = 0;
    for (const auto &[device, id] : std::as_const(m_settings.entries)) {
        const auto map = m_devices->deviceMap(device);
        if (!map)
            continue;
        const RegisterEntry *e = map->entry(id);
        const EntryState *s = m_devices->entryState(device, id);
        // Only a current good value is written; otherwise the status says why not.
        const QString value = csvField(s && s->isCurrent() && s->value.isOk() ? s->value.display : QString());
        rows += QStringLiteral("%1,%2@%3,%4,%5,%6,%7\n")
                        .arg(time, map->family)
                        .arg(m_devices->deviceAddress(device))
                        .arg(id, value, e ? e->unit : QString(), s ? s->statusName() : QStringLiteral("not_read"))
                        .toUtf8();
        ++count;
    }
    QString error;
    if (!write(rows, &error)) {
        fail(error);
        return;
    }
    m_rows += count;
}

} // namespace jumo
