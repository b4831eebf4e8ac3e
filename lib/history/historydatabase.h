// One Qt SQL connection to a history on the thread that makes it: opening (WAL for
// SQLite), the schema (the same tables in SQLite and PostgreSQL), the station's
// bookkeeping, and errors worded for people. The one place that knows the two dialects.
#pragma once

#include "history/historylocation.h"

#include <QCoreApplication>
#include <QSqlDatabase>
#include <QString>

#include <optional>

class QSqlError;
class QSqlQuery;

namespace jumo {

class HistoryDatabase
{
    Q_DECLARE_TR_FUNCTIONS(jumo::HistoryDatabase)

public:
    static constexpr int schemaVersion = 1;

    // Why the last open or query failed, for a caller that answers each differently
    // (jumoctl's exit code): the history could not be reached or used, or what was opened
    // is no JUMO history, or a damaged one.
    enum class Fault { None, Unavailable, NotAHistory, Damaged };

    // How a read-only connection treats an SQLite file in WAL mode. Beside its writer (a
    // store's own trends) it shares the writer's -wal and -shm files, made where missing.
    // From outside (jumoctl, a copy of a history) it never leaves a file beside the
    // history: it shares them where a writer left them, and else reads the file as is.
    enum class ReadAccess { BesideWriter, FromOutside };

    explicit HistoryDatabase(const HistoryLocation &location, ReadAccess readAccess = ReadAccess::BesideWriter);
    ~HistoryDatabase();
    HistoryDatabase(const HistoryDatabase &) = delete;
    HistoryDatabase &operator=(const HistoryDatabase &) = delete;

    // Writable: makes the file (and its folder) or the tables where they are missing.
    // Read-only: an SQLite file must exist and hold a history: every table and column
    // this version reads, and its schema version.
    bool open(bool writable, QString *error);
    void close();
    bool isOpen() const;
    QSqlDatabase &database() { return m_db; }
    const HistoryLocation &location() const { return m_location; }
    bool isPostgres() const { return m_location.kind == HistoryLocation::Kind::Postgres; }

    Fault fault() const { return m_fault; }

    // "cannot write the history postgresql://...: WHY"; sets fault().
    QString failure(const QString &doing, const QSqlError &error);
    // A query on this connection, forward only.
    QSqlQuery query() const;
    bool exec(const QString &sql, QString *error);

    // The store's bookkeeping, per station: "rolled:hall-3" and the like.
    std::optional<QString> meta(const QString &name, QString *error);
    bool setMeta(const QString &name, const QString &value, QString *error);

    // Inserts of that many rows, replacing a row of the same series and time (the same
    // statement in both dialects).
    static QString upsertRaw(int rows);
    static QString upsertMinute(int rows);

private:
    bool createSchema(QString *error);
    bool checkSchema(QString *error);
    // A read-only SQLite file: an SQLite database, whole; walMode from its header.
    bool checkFileHeader(int fd, bool *walMode, QString *error);
    bool refuse(Fault fault, const QString &message, QString *error);
    bool checkSchemaVersionOrSet(QString *error);

    HistoryLocation m_location;
    QString m_connectionName;
    QSqlDatabase m_db;
    ReadAccess m_readAccess;
    bool m_immutable = false;   // opened as a file nobody writes
    Fault m_fault = Fault::None;
};

} // namespace jumo
