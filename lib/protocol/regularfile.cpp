#include "protocol/regularfile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace jumo {

namespace {

QString systemError(int code)
{
    return QString::fromLocal8Bit(std::strerror(code));
}

// Hands a regular file opened by RegularFile::openDescriptor on to QFile.
bool openRegular(QFile &file, const QString &path, int flags, QIODevice::OpenMode mode, QString *error)
{
    const int fd = RegularFile::openDescriptor(path, flags, error);
    if (fd < 0)
        return false;
    if (!file.open(fd, mode, QFileDevice::AutoCloseHandle)) {
        ::close(fd);
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace

// Opens with O_NONBLOCK, so that a FIFO does not wait for a writer, looks at what was
// opened, and leaves a regular file in blocking mode.
int RegularFile::openDescriptor(const QString &path, int flags, QString *error)
{
    const int fd = ::open(QFile::encodeName(path).constData(), flags | O_NONBLOCK | O_CLOEXEC | O_NOCTTY, 0644);
    if (fd < 0) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, systemError(errno));
        return -1;
    }
    struct stat info = {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        ::close(fd);
        if (error)
            *error = tr("%1: not a regular file").arg(path);
        return -1;
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    return fd;
}

bool RegularFile::openForReading(QFile &file, const QString &path, QString *error)
{
    if (path.startsWith(QLatin1Char(':'))) {
        file.setFileName(path);
        if (file.open(QIODevice::ReadOnly))
            return true;
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return openRegular(file, path, O_RDONLY, QIODevice::ReadOnly, error);
}

bool RegularFile::openForAppending(QFile &file, const QString &path, QString *error)
{
    return openRegular(file, path, O_RDWR | O_APPEND | O_CREAT, QIODevice::ReadWrite | QIODevice::Append, error);
}

std::optional<QByteArray> RegularFile::read(const QString &path, qint64 maxBytes, QString *error)
{
    QFile file;
    if (!openForReading(file, path, error))
        return std::nullopt;
    if (file.size() > maxBytes) {
        if (error)
            *error = tr("%1: too big (%2 bytes, at most %3)").arg(path).arg(file.size()).arg(maxBytes);
        return std::nullopt;
    }
    // It may grow while it is read: never more than the limit.
    QByteArray data = file.read(maxBytes + 1);
    if (data.size() > maxBytes) {
        if (error)
            *error = tr("%1: too big (more than %2 bytes)").arg(path).arg(maxBytes);
        return std::nullopt;
    }
    if (file.error() != QFileDevice::NoError) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    return data;
}

std::optional<QString> RegularFile::firstLine(const QString &path, QString *error)
{
    const std::optional<QByteArray> data = read(path, 64 * 1024, error);
    if (!data)
        return std::nullopt;
    QByteArray line = data->left(data->indexOf('\n'));
    while (line.endsWith('\r'))
        line.chop(1);
    return QString::fromUtf8(line);
}

} // namespace jumo
