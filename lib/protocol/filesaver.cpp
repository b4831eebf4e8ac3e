#include "protocol/filesaver.h"

#include <QFile>
#include <QSaveFile>

#include <sys/stat.h>

namespace jumo {

bool FileSaver::save(const QString &path, const QByteArray &data, QString *error)
{
    // A FIFO or a device (/dev/null, as root) would be replaced by a file of that name.
    struct stat info = {};
    if (::stat(QFile::encodeName(path).constData(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode)) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, tr("not a regular file"));
        return false;
    }
    QSaveFile file(path);
    // Unbuffered: QSaveFile notices a failed write only in its own writeData(); a write
    // that fails later, while a buffer is flushed in commit(), would still be committed
    // (an empty file in place of the old one on a full disk, Qt 6.4).
    bool ok = file.open(QIODevice::WriteOnly | QIODevice::Unbuffered);
    qint64 written = 0;
    while (ok && written < data.size()) {
        const qint64 n = file.write(data.constData() + written, data.size() - written);
        ok = n > 0;
        written += std::max<qint64>(n, 0);
    }
    const QString reason = file.errorString();
    if (ok && file.commit())
        return true;
    file.cancelWriting();
    if (error)
        *error = tr("cannot write %1: %2").arg(path, ok ? file.errorString() : reason);
    return false;
}

} // namespace jumo
