// One file of an event log, open for reading at any position from any thread (pread,
// no shared file position). The open file follows its rename by a rotation and stays
// readable after a rotation removed it, so positions of its lines stay valid.
#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <functional>
#include <memory>

namespace jumo {

class LogFile
{
public:
    // A complete line: its position and length (without the newline), and its bytes,
    // which are left empty for a line longer than maxLineBytes.
    struct Line
    {
        qint64 offset;
        qint64 length;
        QByteArrayView text;
    };
    // Gets each line; false stops after it.
    using LineVisitor = std::function<bool(const Line &line)>;

    static constexpr qint64 maxLineBytes = 1024 * 1024;

    // A regular file (never waits on a FIFO); null with "PATH: reason" in error.
    static std::shared_ptr<const LogFile> open(const QString &path, QString *error);
    ~LogFile();
    LogFile(const LogFile &) = delete;
    LogFile &operator=(const LogFile &) = delete;

    QString path() const { return m_path; }   // the name it was opened by
    qint64 size() const;
    // Whether path leads to this very file (not to one made since, nor to none).
    bool isAt(const QString &path) const;
    // At most length bytes from offset; fewer at the end of the file or on an error.
    QByteArray read(qint64 offset, qint64 length) const;

    // The end (just after the newline) of the last complete line before end; 0 if none.
    qint64 lastLineEnd(qint64 end) const;
    // The lines that end before cursor (a line end, as lastLineEnd gives), newest first,
    // as far back as about chunkBytes reach (a longer line is read whole). Returns the
    // cursor for the next call: 0 once the start of the file is reached.
    qint64 linesBefore(qint64 cursor, qint64 chunkBytes, const LineVisitor &visit) const;
    // The complete lines from start (a line start) before end, in order. Returns the end
    // of the last of them (after its newline), or start when there is none.
    qint64 linesFrom(qint64 start, qint64 end, const LineVisitor &visit) const;

private:
    LogFile(int fd, const QString &path);

    int m_fd;
    QString m_path;
    quint64 m_device = 0;
    quint64 m_inode = 0;
};

} // namespace jumo
