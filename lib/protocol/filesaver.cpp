#include "protocol/filesaver.h"

#include <QFile>

#include <sys/stat.h>

namespace jumo {

FileSaver::FileSaver(const QString &path) : m_path(path), m_file(path)
{
    // A FIFO or a device (/dev/null, as root) would be replaced by a file of that name.
    struct stat info = {};
    if (::stat(QFile::encodeName(path).constData(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode)) {
        m_reason = tr("not a regular file");
        return;
    }
    // Unbuffered: QSaveFile notices a failed write only in its own writeData(); a write
    // that fails later, while a buffer is flushed in commit(), would still be committed
    // (an empty file in place of the old one on a full disk, Qt 6.4).
    m_ok = m_file.open(QIODevice::WriteOnly | QIODevice::Unbuffered);
    if (!m_ok)
        m_reason = m_file.errorString();
}

FileSaver::~FileSaver()
{
    if (m_file.isOpen())
        m_file.cancelWriting();
}

bool FileSaver::write(QByteArrayView data)
{
    qint64 written = 0;
    while (m_ok && written < data.size()) {
        const qint64 n = m_file.write(data.constData() + written, data.size() - written);
        m_ok = n > 0;
        written += std::max<qint64>(n, 0);
    }
    if (!m_ok && m_reason.isEmpty())
        m_reason = m_file.errorString();
    return m_ok;
}

bool FileSaver::commit(QString *error)
{
    if (m_ok && m_file.commit())
        return true;
    if (m_ok)
        m_reason = m_file.errorString();
    m_file.cancelWriting();
    m_ok = false;
    if (error)
        *error = tr("cannot write %1: %2").arg(m_path, m_reason);
    return false;
}

bool FileSaver::save(const QString &path, const QByteArray &data, QString *error)
{
    FileSaver file(path);
    file.write(data);
    return file.commit(error);
}

} // namespace jumo
