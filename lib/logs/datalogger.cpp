#include "protocol/csv.h"
#include "logs/datalogger.h"

#include <QDateTime>
#include <QDir>

namespace jumo {

DataLogger::DataLogger(Bus *bus, QObject *parent) : QObject(parent), m_bus(bus)
{
    connect(&m_timer, &QTimer::timeout, this, &DataLogger::sample);
}

bool DataLogger::start(const Settings &settings, QString *error)
{
    stop();
    if (settings.entries.isEmpty() || settings.intervalMs < 100 || settings.maxFileBytes < 1024) {
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
    if (!openNewFile(error))
        return false;
    m_timer.start(settings.intervalMs);
    return true;
}

void DataLogger::stop()
{
    m_timer.stop();
    if (m_file.isOpen())
        m_file.close();
}

bool DataLogger::openNewFile(QString *error)
{
    if (m_file.isOpen())
        m_file.close();
    const QDateTime now = QDateTime::currentDateTime();
    QString name = QDir(m_settings.folder).filePath(QStringLiteral("jumo-data-%1.csv").arg(now.toString(QStringLiteral("yyyyMMdd-HHmmss"))));
    for (int n = 2; QFile::exists(name); ++n)   // two files within one second
        name = QDir(m_settings.folder)
                       .filePath(QStringLiteral("jumo-data-%1-%2.csv").arg(now.toString(QStringLiteral("yyyyMMdd-HHmmss"))).arg(n));
    m_file.setFileName(name);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = tr("cannot write %1: %2").arg(name, m_file.errorString());
        return false;
    }
    m_file.write("time,device,id,value,unit,status\n");
    m_fileDate = now.date();
    m_files << name;
    return true;
}

void DataLogger::sample()
{
    if (m_file.size() >= m_settings.maxFileBytes || QDate::currentDate() != m_fileDate) {
        QString error;
        if (!openNewFile(&error)) {
            stop();
            emit failed(error);
            return;
        }
    }
    const QString time = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
    QByteArray rows;
    for (const auto &[device, id] : std::as_const(m_settings.entries)) {
        const auto map = m_bus->deviceMap(device);
        if (!map)
            continue;
        const RegisterEntry *e = map->entry(id);
        const EntryState *s = m_bus->entryState(device, id);
        // Only a current good value is written; otherwise the status says why not.
        const QString value = csvField(s && s->isCurrent() && s->value.isOk() ? s->value.display : QString());
        rows += QStringLiteral("%1,%2@%3,%4,%5,%6,%7\n")
                        .arg(time, map->family)
                        .arg(m_bus->deviceAddress(device))
                        .arg(id, value, e ? e->unit : QString(), s ? s->statusName() : QStringLiteral("not_read"))
                        .toUtf8();
        ++m_rows;
    }
    if (m_file.write(rows) < 0) {
        const QString reason = tr("cannot write %1: %2").arg(m_file.fileName(), m_file.errorString());
        stop();
        emit failed(reason);
        return;
    }
    m_file.flush();
}

} // namespace jumo
