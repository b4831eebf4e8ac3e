#include "logs/eventlog.h"

#include "protocol/regularfile.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QLoggingCategory>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

Q_LOGGING_CATEGORY(lcLog, "jumo.log", QtWarningMsg)

namespace jumo {

namespace {

struct RotatedFile
{
    QString stamp;   // yyyyMMddTHHmmssZ
    int sequence;    // 1, or 2... for a second rotation within the same second
    QString path;
};

// "write-audit.jsonl" -> "write-audit", ".jsonl"
std::pair<QString, QString> stemAndExtension(const QString &fileName)
{
    static const QString extension = QStringLiteral(".jsonl");
    if (fileName.endsWith(extension) && fileName.size() > extension.size())
        return {fileName.chopped(extension.size()), extension};
    return {fileName, QString()};
}

QString rotatedPath(const QString &path, const QString &stamp, int sequence)
{
    const QFileInfo info(path);
    const auto [stem, extension] = stemAndExtension(info.fileName());
    const QString suffix = sequence > 1 ? QStringLiteral("-%1").arg(sequence) : QString();
    return info.dir().filePath(stem + QLatin1Char('-') + stamp + suffix + extension);
}

// The rotated files of the log at path, oldest first. They are ordered by their names,
// which a rotation always makes sort after the ones before it, whatever the clock says.
QList<RotatedFile> rotatedFiles(const QString &path)
{
    const QFileInfo info(path);
    const auto [stem, extension] = stemAndExtension(info.fileName());
    const QRegularExpression pattern(QLatin1Char('^') + QRegularExpression::escape(stem)
                                     + QStringLiteral("-(\\d{8}T\\d{6}Z)(?:-(\\d+))?")
                                     + QRegularExpression::escape(extension) + QLatin1Char('$'));
    QList<RotatedFile> out;
    const QDir dir = info.absoluteDir();
    for (const QString &name : dir.entryList(QDir::Files | QDir::Hidden)) {
        const QRegularExpressionMatch m = pattern.match(name);
        if (m.hasMatch())
            out << RotatedFile{m.captured(1), m.captured(2).isEmpty() ? 1 : m.captured(2).toInt(), dir.filePath(name)};
    }
    std::sort(out.begin(), out.end(), [](const RotatedFile &a, const RotatedFile &b) {
        return a.stamp != b.stamp ? a.stamp < b.stamp : a.sequence < b.sequence;
    });
    return out;
}

QString systemError(int code)
{
    return QString::fromLocal8Bit(std::strerror(code));
}

} // namespace

EventLog::Rotation EventLog::Rotation::fromSettings(const QSettings &settings)
{
    Rotation rotation;
    bool ok = false;
    if (const QVariant v = settings.value(QStringLiteral("logs/maxFileMiB")); v.isValid()) {
        const int mib = v.toInt(&ok);
        if (ok && mib >= 1 && mib <= 4096)
            rotation.maxFileBytes = qint64(mib) * 1024 * 1024;
        else
            qCWarning(lcLog) << "logs/maxFileMiB in" << settings.fileName() << "is not 1..4096; using"
                             << rotation.maxFileBytes / (1024 * 1024);
    }
    if (const QVariant v = settings.value(QStringLiteral("logs/keepFiles")); v.isValid()) {
        const int keep = v.toInt(&ok);
        if (ok && keep >= 1 && keep <= 1000)
            rotation.keepFiles = keep;
        else
            qCWarning(lcLog) << "logs/keepFiles in" << settings.fileName() << "is not 1..1000; using" << rotation.keepFiles;
    }
    return rotation;
}

EventLog::EventLog(const QString &path, QObject *parent) : QObject(parent), m_path(path) { }

EventLog::~EventLog()
{
    closeFile();
}

QString EventLog::defaultFolder(QString *error)
{
    QString folder = qEnvironmentVariable("JUMO_LOG_DIR");
    if (folder.isEmpty()) {
        // Without a home (HOME unset, as a service may run) Qt names /.local/share: logs
        // of everyone's writes in the root folder, or none at all. No folder is the
        // honest answer, and the caller says so.
        if (!QDir::isAbsolutePath(qEnvironmentVariable("XDG_DATA_HOME"))
            && !QDir::isAbsolutePath(qEnvironmentVariable("HOME"))) {
            if (error)
                *error = tr("no folder for the logs: neither JUMO_LOG_DIR, XDG_DATA_HOME nor HOME is set to an "
                            "absolute folder");
            return {};
        }
        folder = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) + QStringLiteral("/jumo");
    }
    QDir().mkpath(folder);
    return folder;
}

QStringList EventLog::files(const QString &path)
{
    QStringList out;
    for (const RotatedFile &f : rotatedFiles(path))
        out << f.path;
    if (QFileInfo::exists(path))
        out << path;
    return out;
}

bool EventLog::append(QJsonObject record)
{
    if (!record.contains(QLatin1String("time")))
        record.insert(QStringLiteral("time"), QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    const bool written = writeLine(QJsonDocument(record).toJson(QJsonDocument::Compact) + '\n');
    emit appended(record);
    if (written && m_unwritten > 0) {
        const int lost = m_unwritten;
        m_unwritten = 0;
        emit writeRecovered(lost);
    } else if (!written) {
        ++m_unwritten;
        qCDebug(lcLog).noquote() << m_lastError;   // the caller reports it
        emit writeFailed(m_lastError);
    }
    return written;
}

void EventLog::setSystemError(int code)
{
    m_lastError = tr("cannot write %1: %2").arg(m_path, systemError(code));
}

bool EventLog::openFile()
{
    QDir().mkpath(QFileInfo(m_path).absolutePath());
    QString reason;
    // Read access too: the last byte says whether a cut line needs ending first.
    m_fd = RegularFile::openDescriptor(m_path, O_RDWR | O_APPEND | O_CREAT, &reason);
    if (m_fd < 0)
        m_lastError = tr("cannot write %1").arg(reason);
    return m_fd >= 0;
}

void EventLog::closeFile()
{
    if (m_fd >= 0)
        ::close(m_fd);   // its lock goes with it
    m_fd = -1;
}

bool EventLog::writeLine(QByteArray line)
{
    const QByteArray name = QFile::encodeName(m_path);
    // Another process (jumoctl, a second HMI) may rotate or remove the file between two
    // appends: the lock is taken on the file held open, then the name must still lead to
    // it; otherwise the file the name leads to now is opened. Each time round, another
    // writer has rotated the file, so it makes progress; flock is not fair, though, and a
    // busy writer can rotate many times while this one waits for the lock. A record is
    // worth the wait: 256 rounds, not 8 (a suspected cause of a rare lost record in
    // tst_eventlog's two-writer test; not reproduced).
    for (int attempt = 0; attempt < 256; ++attempt) {
        if (m_fd < 0 && !openFile())
            return false;
        int locked;
        while ((locked = ::flock(m_fd, LOCK_EX)) != 0 && errno == EINTR) { }
        struct stat held = {};
        struct stat named = {};
        if (locked != 0 || ::fstat(m_fd, &held) != 0) {
            setSystemError(errno);
            closeFile();
            return false;
        }
        if (::stat(name.constData(), &named) != 0 || named.st_dev != held.st_dev || named.st_ino != held.st_ino) {
            closeFile();
            continue;
        }
        if (held.st_size > 0 && held.st_size + line.size() > m_rotation.maxFileBytes && rotate()) {
            closeFile();
            continue;
        }
        // A line cut by a crash (or a full disk) must not swallow this record.
        char last = '\n';
        if (held.st_size > 0 && ::pread(m_fd, &last, 1, held.st_size - 1) == 1 && last != '\n')
            line.prepend('\n');
        qint64 written = 0;
        while (written < line.size()) {
            const ssize_t n = ::write(m_fd, line.constData() + written, size_t(line.size() - written));
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0) {
                setSystemError(n < 0 ? errno : ENOSPC);
                closeFile();
                return false;
            }
            written += n;
        }
        // Synced: a record the caller was told about must survive a power cut.
        if (::fdatasync(m_fd) != 0) {
            setSystemError(errno);
            closeFile();
            return false;
        }
        ::flock(m_fd, LOCK_UN);
        return true;
    }
    m_lastError = tr("cannot write %1: %2").arg(m_path, tr("the file is replaced again and again"));
    return false;
}

// Called with the current file locked: renames it after the time of the rotation and
// removes the oldest files beyond those kept. A failed rename leaves the file as it is
// (it grows on: a record is worth more than a size limit).
bool EventLog::rotate()
{
    const QList<RotatedFile> older = rotatedFiles(m_path);
    QString stamp = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd'T'HHmmss'Z'"));
    int sequence = 1;
    if (!older.isEmpty() && older.last().stamp >= stamp) {   // within a second, or the clock went back
        stamp = older.last().stamp;
        sequence = older.last().sequence + 1;
    }
    const QString target = rotatedPath(m_path, stamp, sequence);
    if (::rename(QFile::encodeName(m_path).constData(), QFile::encodeName(target).constData()) != 0) {
        if (!m_rotationFailed)   // once, not at every record from now on
            qCWarning(lcLog).noquote() << "cannot rotate" << m_path << "to" << target << ":" << systemError(errno);
        m_rotationFailed = true;
        return false;
    }
    m_rotationFailed = false;
    for (qsizetype i = 0; i < older.size() + 1 - m_rotation.keepFiles; ++i) {
        if (::unlink(QFile::encodeName(older.at(i).path).constData()) != 0)
            qCWarning(lcLog).noquote() << "cannot remove" << older.at(i).path << ":" << systemError(errno);
    }
    // The new names reach the disk with the folder.
    const int folder = ::open(QFile::encodeName(QFileInfo(m_path).absolutePath()).constData(),
                              O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folder >= 0) {
        ::fsync(folder);
        ::close(folder);
    }
    return true;
}

} // namespace jumo
