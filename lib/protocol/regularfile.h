// Reads files a user hands us (maps, parameter files, logs) without trusting what they
// are: only a regular file below a size limit is read. A FIFO, a device (a link to
// /dev/zero) or a socket is refused without blocking in open() or reading forever.
#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QFile>
#include <QString>

#include <optional>

namespace jumo {

class RegularFile
{
    Q_DECLARE_TR_FUNCTIONS(jumo::RegularFile)

public:
    static constexpr qint64 defaultLimit = 16 * 1024 * 1024;

    // The whole file; nullopt with "PATH: reason" in error when it cannot be read or is
    // no regular file of at most maxBytes. Qt resources (":/...") are read as they are.
    static std::optional<QByteArray> read(const QString &path, qint64 maxBytes = defaultLimit, QString *error = nullptr);
    // The first line without its line end, as UTF-8 (a password file); errors as read().
    static std::optional<QString> firstLine(const QString &path, QString *error = nullptr);
    // Opens a regular file for reading, or for appending (created when missing), into
    // file; false with the reason in error. Never blocks on a FIFO.
    static bool openForReading(QFile &file, const QString &path, QString *error);
    static bool openForAppending(QFile &file, const QString &path, QString *error);
    // The same for a plain descriptor (open(2) flags; O_CREAT creates with mode 0644):
    // the descriptor of a regular file, else -1 with the reason in error.
    static int openDescriptor(const QString &path, int flags, QString *error);
};

} // namespace jumo
