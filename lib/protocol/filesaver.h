// Files that cannot lie, in the manner of Qt Creator's FileSaver: a whole file is
// written to a temporary file beside it, every write checked, synced, and put in the
// file's place only when all of it is on disk. On any failure (disk full, permission,
// a folder in the way) the previous file is left byte for byte as it was.
#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

namespace jumo {

class FileSaver
{
    Q_DECLARE_TR_FUNCTIONS(jumo::FileSaver)

public:
    // On failure: false, and "cannot write PATH: reason" in error.
    static bool save(const QString &path, const QByteArray &data, QString *error);
};

} // namespace jumo
