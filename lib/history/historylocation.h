// Where a history is kept: an SQLite file (the default, one per station in the log
// folder) or a PostgreSQL database that several stations share ("postgresql://HOST/DB").
#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace jumo {

struct HistoryLocation
{
    Q_DECLARE_TR_FUNCTIONS(jumo::HistoryLocation)

public:
    enum class Kind { Sqlite, Postgres };

    Kind kind = Kind::Sqlite;
    QString path;          // Sqlite: the file
    QString host;          // Postgres: server, port, database, user, password
    int port = 5432;
    QString database;
    QString username;
    // Never from the command line or a URL: a password in argv can be read by every
    // local user and stays in shell histories. From a file, JUMO_HISTORY_PASSWORD, or
    // else PostgreSQL's own ~/.pgpass and PGPASSWORD.
    QString password;

    static HistoryLocation file(const QString &path);
    // The station's file in a folder: FOLDER/history-STATION.sqlite. The station name is
    // one a station file accepts (safe in file names).
    static QString defaultFile(const QString &folder, const QString &station);
    // "postgresql://[USER@]HOST[:PORT]/DB" (or postgres://); anything without a scheme is
    // an SQLite file. A password in the URL is refused.
    static std::optional<HistoryLocation> parse(const QString &text, QString *error);

    // As the programs' command lines give it: the URL or file, a user name that replaces
    // the URL's (empty: keep it), the password from a file or else JUMO_HISTORY_PASSWORD.
    struct Options
    {
        QString url;
        QString username;
        QString passwordFile;
    };
    static std::optional<HistoryLocation> fromOptions(const Options &options, QString *error);

    // For people and logs, never with the password: the file, or "postgresql://user@host:5432/db".
    QString display() const;
};

} // namespace jumo
