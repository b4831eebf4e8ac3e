#include "logs/logfile.h"

#include "protocol/regularfile.h"

#include <QFile>

#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace jumo {

namespace {

constexpr qint64 searchChunk = 64 * 1024;
constexpr qint64 forwardChunk = 1024 * 1024;

// The position of the last newline in data, -1 if none.
qint64 lastNewline(const QByteArray &data, qint64 before)
{
    const void *p = before > 0 ? ::memrchr(data.constData(), '\n', size_t(before)) : nullptr;
    return p ? static_cast<const char *>(p) - data.constData() : -1;
}

} // namespace

std::shared_ptr<const LogFile> LogFile::open(const QString &path, QString *error)
{
    const int fd = RegularFile::openDescriptor(path, O_RDONLY, error);
    if (fd < 0)
        return nullptr;
    return std::shared_ptr<const LogFile>(new LogFile(fd, path));
}

LogFile::LogFile(int fd, const QString &path) : m_fd(fd), m_path(path)
{
    struct stat info = {};
    if (::fstat(fd, &info) == 0) {
        m_device = info.st_dev;
        m_inode = info.st_ino;
    }
}

LogFile::~LogFile()
{
    ::close(m_fd);
}

qint64 LogFile::size() const
{
    struct stat info = {};
    return ::fstat(m_fd, &info) == 0 ? qint64(info.st_size) : 0;
}

bool LogFile::isAt(const QString &path) const
{
    struct stat info = {};
    return ::stat(QFile::encodeName(path).constData(), &info) == 0 && info.st_dev == m_device && info.st_ino == m_inode;
}

QByteArray LogFile::read(qint64 offset, qint64 length) const
{
    QByteArray out(qsizetype(std::max<qint64>(length, 0)), Qt::Uninitialized);
    qint64 done = 0;
    while (done < length) {
        const ssize_t n = ::pread(m_fd, out.data() + done, size_t(length - done), off_t(offset + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        done += n;
    }
    out.truncate(qsizetype(done));
    return out;
}

qint64 LogFile::lastLineEnd(qint64 end) const
{
    for (qint64 pos = end; pos > 0;) {
        const qint64 from = std::max<qint64>(0, pos - searchChunk);
        const QByteArray data = read(from, pos - from);
        if (data.size() != pos - from)
            return 0;
        if (const qint64 at = lastNewline(data, data.size()); at >= 0)
            return from + at + 1;
        pos = from;
    }
    return 0;
}

qint64 LogFile::linesBefore(qint64 cursor, qint64 chunkBytes, const LineVisitor &visit) const
{
    if (cursor <= 0)
        return 0;
    const qint64 from = std::max<qint64>(0, cursor - std::max<qint64>(chunkBytes, 2));
    const QByteArray chunk = read(from, cursor - from);
    if (chunk.size() != cursor - from)
        return 0;   // cut short under us: nothing before can be trusted
    qint64 end = chunk.size() - 1;   // the newline that ends the current line
    for (;;) {
        const qint64 at = lastNewline(chunk, end);
        if (at < 0 && from > 0) {
            if (end + 1 < chunk.size())
                return from + end + 1;   // the line's start is in the next chunk back
            // No line starts in this chunk: find the start of this long one.
            qint64 start = 0;
            for (qint64 pos = from; pos > 0;) {
                const qint64 before = std::max<qint64>(0, pos - searchChunk);
                const QByteArray data = read(before, pos - before);
                if (data.size() != pos - before)
                    return 0;
                if (const qint64 k = lastNewline(data, data.size()); k >= 0) {
                    start = before + k + 1;
                    break;
                }
                pos = before;
            }
            const qint64 length = cursor - 1 - start;
            const QByteArray text = length <= maxLineBytes ? read(start, length) : QByteArray();
            visit(Line{start, length, QByteArrayView(text)});
            return start;
        }
        const qint64 start = at + 1;   // 0 at the start of the file
        const bool goOn = visit(Line{from + start, end - start, QByteArrayView(chunk.constData() + start, end - start)});
        if (from + start == 0)
            return 0;
        if (!goOn)
            return from + start;
        end = at;
    }
}

qint64 LogFile::linesFrom(qint64 start, qint64 end, const LineVisitor &visit) const
{
    qint64 lineStart = start;
    QByteArray carried;   // the first part of a line that goes on in the next chunk
    bool tooLong = false;
    for (qint64 pos = start; pos < end;) {
        const QByteArray data = read(pos, std::min(forwardChunk, end - pos));
        if (data.isEmpty())
            break;
        qint64 i = 0;
        while (i < data.size()) {
            const void *p = ::memchr(data.constData() + i, '\n', size_t(data.size() - i));
            if (!p) {
                tooLong = tooLong || carried.size() + (data.size() - i) > maxLineBytes;
                if (tooLong)
                    carried.clear();
                else
                    carried.append(data.constData() + i, data.size() - i);
                break;
            }
            const qint64 k = static_cast<const char *>(p) - data.constData();
            const qint64 length = pos + k - lineStart;
            QByteArrayView text(data.constData() + i, k - i);
            if (tooLong || length > maxLineBytes) {
                text = {};
            } else if (!carried.isEmpty()) {
                carried.append(text);
                text = carried;
            }
            const bool goOn = visit(Line{lineStart, length, text});
            carried.clear();
            tooLong = false;
            lineStart = pos + k + 1;
            i = k + 1;
            if (!goOn)
                return lineStart;
        }
        pos += data.size();
    }
    return lineStart;
}

} // namespace jumo
