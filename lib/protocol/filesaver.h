// Files that cannot lie, in the manner of Qt Creator's FileSaver: a whole file is
// written to a temporary file beside it, every write checked, synced, and put in the
// file's place only when all of it is on disk. On any failure (disk full, permission,
// a folder in the way) the previous file is left byte for byte as it was.
#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QCoreApplication>
#include <QSaveFile>
#include <QString>

namespace jumo {

class FileSaver
{
    Q_DECLARE_TR_FUNCTIONS(jumo::FileSaver)

public:
    // A file written in parts (an export of a large log): write() as often as needed,
    // then commit(). Destroyed without a commit, nothing replaces the previous file.
    explicit FileSaver(const QString &path);
    ~FileSaver();
    FileSaver(const FileSaver &) = delete;
    FileSaver &operator=(const FileSaver &) = delete;

    // false once any write failed; later writes are ignored.
    bool write(QByteArrayView data);
    // On failure: false, and "cannot write PATH: reason" in error.
    bool commit(QString *error);

    // The whole file at once.
    static bool save(const QString &path, const QByteArray &data, QString *error);

private:
    QString m_path;
    QSaveFile m_file;
    bool m_ok = false;
    QString m_reason;
};

} // namespace jumo
