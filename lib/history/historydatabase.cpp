#include "history/historydatabase.h"

#include "protocol/regularfile.h"

#include <QAtomicInteger>
#include <QDir>
#include <QFileInfo>
#include <QSqlError>
#include <QSqlQuery>
#include <QSqlRecord>
#include <QUrl>
#include <QVariant>

#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace jumo {

namespace {

QString nextConnectionName()
{
    static QAtomicInteger<quint64> counter;
    return QStringLiteral("jumo-history-%1").arg(counter.fetchAndAddRelaxed(1));
}

// The tables, in both dialects. Samples are keyed by series and time, so a series'
// samples lie together and a query of one entry reads one range of the key.
QStringList schemaStatements(bool postgres)
{
    const QString key = postgres ? QStringLiteral("BIGSERIAL PRIMARY KEY") : QStringLiteral("INTEGER PRIMARY KEY");
    const QString compact = postgres ? QString() : QStringLiteral(" WITHOUT ROWID");
    return {
        QStringLiteral("CREATE TABLE IF NOT EXISTS history_meta (name TEXT PRIMARY KEY, value TEXT NOT NULL)"),
        QStringLiteral("CREATE TABLE IF NOT EXISTS history_series (id %1, station TEXT NOT NULL, line TEXT NOT NULL, "
                       "device TEXT NOT NULL, entry TEXT NOT NULL, is_number SMALLINT NOT NULL, unit TEXT NOT NULL, "
                       "UNIQUE (station, line, device, entry))")
                .arg(key),
        QStringLiteral("CREATE TABLE IF NOT EXISTS history_raw (series BIGINT NOT NULL, t BIGINT NOT NULL, "
                       "state SMALLINT NOT NULL, value DOUBLE PRECISION, text_value TEXT, PRIMARY KEY (series, t))%1")
                .arg(compact),
        QStringLiteral("CREATE TABLE IF NOT EXISTS history_minute (series BIGINT NOT NULL, t BIGINT NOT NULL, "
                       "state SMALLINT NOT NULL, value DOUBLE PRECISION, minimum DOUBLE PRECISION, "
                       "maximum DOUBLE PRECISION, mean DOUBLE PRECISION, text_value TEXT, PRIMARY KEY (series, t))%1")
                .arg(compact),
    };
}

// The tables and the columns a reader needs (schemaStatements makes them).
const QList<std::pair<QString, QStringList>> &readColumns()
{
    static const QList<std::pair<QString, QStringList>> tables{
        {QStringLiteral("history_meta"), {QStringLiteral("name"), QStringLiteral("value")}},
        {QStringLiteral("history_series"),
         {QStringLiteral("id"), QStringLiteral("station"), QStringLiteral("line"), QStringLiteral("device"),
          QStringLiteral("entry"), QStringLiteral("is_number"), QStringLiteral("unit")}},
        {QStringLiteral("history_raw"),
         {QStringLiteral("series"), QStringLiteral("t"), QStringLiteral("state"), QStringLiteral("value"),
          QStringLiteral("text_value")}},
        {QStringLiteral("history_minute"),
         {QStringLiteral("series"), QStringLiteral("t"), QStringLiteral("state"), QStringLiteral("value"),
          QStringLiteral("minimum"), QStringLiteral("maximum"), QStringLiteral("mean"), QStringLiteral("text_value")}},
    };
    return tables;
}

QString upsert(const QString &table, const QStringList &columns, int rows)
{
    const QString row = QLatin1Char('(') + QStringList(columns.size(), QStringLiteral("?")).join(QLatin1Char(',')) + QLatin1Char(')');
    QStringList updates;
    for (const QString &c : columns.mid(2))
        updates << QStringLiteral("%1 = excluded.%1").arg(c);
    return QStringLiteral("INSERT INTO %1 (%2) VALUES %3 ON CONFLICT (series, t) DO UPDATE SET %4")
            .arg(table, columns.join(QStringLiteral(", ")), QStringList(rows, row).join(QLatin1Char(',')),
                 updates.join(QStringLiteral(", ")));
}

} // namespace

HistoryDatabase::HistoryDatabase(const HistoryLocation &location, ReadAccess readAccess)
    : m_location(location), m_connectionName(nextConnectionName()), m_readAccess(readAccess)
{
}

HistoryDatabase::~HistoryDatabase()
{
    close();
}

bool HistoryDatabase::open(bool writable, QString *error)
{
    close();
    m_fault = Fault::None;
    m_immutable = false;
    const bool postgres = isPostgres();
    m_db = QSqlDatabase::addDatabase(postgres ? QStringLiteral("QPSQL") : QStringLiteral("QSQLITE"), m_connectionName);
    if (!m_db.isValid()) {
        m_fault = Fault::Unavailable;
        if (error)
            *error = tr("cannot open the history %1: Qt's %2 driver is not installed (%3)")
                             .arg(m_location.display(), postgres ? QStringLiteral("QPSQL") : QStringLiteral("QSQLITE"),
                                  postgres ? QStringLiteral("libqt6sql6-psql") : QStringLiteral("libqt6sql6-sqlite"));
        close();
        return false;
    }
    if (postgres) {
        m_db.setHostName(m_location.host);
        m_db.setPort(m_location.port);
        m_db.setDatabaseName(m_location.database);
        m_db.setUserName(m_location.username);
        m_db.setPassword(m_location.password);
        m_db.setConnectOptions(QStringLiteral("connect_timeout=10"));
    } else {
        const QFileInfo info(m_location.path);
        if (!writable && !info.exists()) {
            m_fault = Fault::Unavailable;
            if (error)
                *error = tr("no history at %1").arg(m_location.path);
            close();
            return false;
        }
        if (info.exists() || info.isSymLink()) {
            // SQLite would block in open() on a FIFO, and read a device: regular files only.
            QString why;
            const int fd = RegularFile::openDescriptor(m_location.path, O_RDONLY, &why);
            if (fd < 0) {
                m_fault = Fault::Unavailable;
                if (error)
                    *error = why;
                close();
                return false;
            }
            bool walMode = false;
            const bool usable = writable || checkFileHeader(fd, &walMode, error);
            ::close(fd);
            if (!usable) {
                close();
                return false;
            }
            // In WAL mode even a read-only connection makes the -wal and -shm files where
            // they are missing, and leaves them. A reader from outside shares them where a
            // writer is at work (so it reads what was committed last), and else reads the
            // file as it is, touching nothing. A recorder that starts on the file while it
            // is read so may change pages under it: failure() says so.
            m_immutable = !writable && m_readAccess == ReadAccess::FromOutside && walMode
                    && !QFileInfo::exists(m_location.path + QLatin1String("-wal"));
        }
        if (writable)
            QDir().mkpath(info.absolutePath());
        if (m_immutable) {
            m_db.setDatabaseName(QUrl::fromLocalFile(info.absoluteFilePath()).toString(QUrl::FullyEncoded)
                                 + QLatin1String("?immutable=1"));
            m_db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_URI;QSQLITE_OPEN_READONLY"));
        } else {
            m_db.setDatabaseName(m_location.path);
            // A reader waits for a checkpoint rather than failing; never longer than this.
            m_db.setConnectOptions(writable ? QStringLiteral("QSQLITE_BUSY_TIMEOUT=10000")
                                            : QStringLiteral("QSQLITE_BUSY_TIMEOUT=10000;QSQLITE_OPEN_READONLY"));
        }
    }
    if (!m_db.open()) {
        if (error)
            *error = failure(tr("open"), m_db.lastError());
        close();
        return false;
    }
    if (!postgres && writable) {
        // WAL: readers (a trend, jumoctl) never wait for the writer, and a crash leaves
        // every committed transaction. FULL: a commit is on the disk when it returns.
        QSqlQuery mode = query();
        if (!mode.exec(QStringLiteral("PRAGMA journal_mode=WAL")) || !mode.next()
            || mode.value(0).toString().compare(QLatin1String("wal"), Qt::CaseInsensitive) != 0) {
            if (error)
                *error = failure(tr("open"), mode.lastError());
            close();
            return false;
        }
        if (!exec(QStringLiteral("PRAGMA synchronous=FULL"), error)) {
            close();
            return false;
        }
    }
    if (!(writable ? createSchema(error) : checkSchema(error))) {
        close();
        return false;
    }
    return true;
}

void HistoryDatabase::close()
{
    if (m_db.isValid()) {
        m_db.close();
        m_db = QSqlDatabase();
        QSqlDatabase::removeDatabase(m_connectionName);
    }
}

bool HistoryDatabase::isOpen() const
{
    return m_db.isValid() && m_db.isOpen();
}

QString HistoryDatabase::failure(const QString &doing, const QSqlError &error)
{
    m_fault = Fault::Unavailable;
    // SQLITE_CORRUPT (11, "database disk image is malformed") and SQLITE_NOTADB (26) with
    // their extended codes: the file, not the reading, is at fault.
    const int code = error.nativeErrorCode().toInt();
    if (!isPostgres() && ((code & 0xff) == 11 || (code & 0xff) == 26)) {
        if (m_immutable && QFileInfo::exists(m_location.path + QLatin1String("-wal"))) {
            return tr("the history %1 changed while it was read (a recorder started on it): read it again")
                    .arg(m_location.display());
        }
        m_fault = Fault::Damaged;
        return tr("%1 is damaged: %2").arg(m_location.display(), error.databaseText().trimmed());
    }
    QString why = error.databaseText().trimmed();
    if (why.isEmpty())
        why = error.driverText().trimmed();
    if (why.isEmpty())
        why = tr("unknown error");
    //: %1 is "open", "write", "read"; %2 the file or database; %3 the reason
    return tr("cannot %1 the history %2: %3").arg(doing, m_location.display(), why);
}

QSqlQuery HistoryDatabase::query() const
{
    QSqlQuery q(m_db);
    q.setForwardOnly(true);
    return q;
}

bool HistoryDatabase::exec(const QString &sql, QString *error)
{
    QSqlQuery q = query();
    if (q.exec(sql))
        return true;
    if (error)
        *error = failure(tr("write"), q.lastError());
    return false;
}

bool HistoryDatabase::createSchema(QString *error)
{
    // Two stations making the tables of one PostgreSQL database at once: the loser of the
    // race tries again and finds them.
    for (int attempt = 0;; ++attempt) {
        QString why;
        bool ok = m_db.transaction();
        for (const QString &statement : schemaStatements(isPostgres())) {
            if (!ok)
                break;
            ok = exec(statement, &why);
        }
        if (ok)
            ok = checkSchemaVersionOrSet(&why);
        if (ok && m_db.commit())
            return true;
        if (why.isEmpty())
            why = failure(tr("write"), m_db.lastError());
        m_db.rollback();
        if (attempt > 0 || !why.contains(QLatin1String("duplicate key"), Qt::CaseInsensitive)) {
            if (error)
                *error = why;
            return false;
        }
    }
}

bool HistoryDatabase::checkSchemaVersionOrSet(QString *error)
{
    const std::optional<QString> version = meta(QStringLiteral("schema"), error);
    if (!version)
        return false;
    if (version->isEmpty())
        return setMeta(QStringLiteral("schema"), QString::number(schemaVersion), error);
    if (version->toInt() > schemaVersion) {
        if (error)
            *error = tr("cannot use the history %1: it was written by a newer version (schema %2, this one knows %3)")
                             .arg(m_location.display(), *version)
                             .arg(schemaVersion);
        return false;
    }
    return true;
}

bool HistoryDatabase::checkFileHeader(int fd, bool *walMode, QString *error)
{
    // SQLite reads a file cut short as if the rest were zeros and fails only at the first
    // page it misses, or takes a file that is no database for an empty one: its header
    // says both at once (sqlite.org/fileformat.html, "The Database Header").
    struct stat status = {};
    if (::fstat(fd, &status) != 0)
        return true;   // SQLite's open says why
    const qint64 size = status.st_size;
    if (size == 0)
        return refuse(Fault::NotAHistory, tr("%1 is not a JUMO history file: it is empty").arg(m_location.display()),
                      error);
    unsigned char header[100] = {};
    if (size < qint64(sizeof header) || ::pread(fd, header, sizeof header, 0) != qint64(sizeof header)
        || std::memcmp(header, "SQLite format 3", 16) != 0) {
        return refuse(Fault::NotAHistory,
                      tr("%1 is not a JUMO history file: it is not an SQLite database").arg(m_location.display()),
                      error);
    }
    auto bigEndian = [&header](int at, int bytes) {
        quint32 value = 0;
        for (int i = 0; i < bytes; ++i)
            value = value << 8 | header[at + i];
        return value;
    };
    const quint32 pageSize = bigEndian(16, 2) == 1 ? 65536 : bigEndian(16, 2);
    if (pageSize < 512 || (pageSize & (pageSize - 1)) != 0) {
        return refuse(Fault::Damaged,
                      tr("%1 is damaged: its header names no page size (%2)").arg(m_location.display()).arg(pageSize),
                      error);
    }
    // The page count is valid where the write that set it also set its check. A file in
    // use has its newest pages in the -wal file beside it, and a checkpoint grows it page
    // by page: only a file nobody writes is measured.
    const qint64 pages = bigEndian(28, 4);
    const bool countValid = pages > 0 && bigEndian(24, 4) == bigEndian(92, 4);
    const bool settled = !QFileInfo::exists(m_location.path + QLatin1String("-wal"));
    // The versions that read and write it: 2, WAL.
    *walMode = header[18] == 2 && header[19] == 2;
    if (size % pageSize != 0) {
        return refuse(Fault::Damaged,
                      tr("%1 is damaged: it ends inside a page (%2 bytes, pages of %3): it was cut off")
                              .arg(m_location.display())
                              .arg(size)
                              .arg(pageSize),
                      error);
    }
    if (settled && countValid && size < pages * pageSize) {
        return refuse(Fault::Damaged,
                      tr("%1 is damaged: it ends after %2 bytes, where its header says %3: it was cut off")
                              .arg(m_location.display())
                              .arg(size)
                              .arg(pages * pageSize),
                      error);
    }
    return true;
}

bool HistoryDatabase::refuse(Fault fault, const QString &message, QString *error)
{
    m_fault = fault;
    if (error)
        *error = message;
    return false;
}

bool HistoryDatabase::checkSchema(QString *error)
{
    // Every table and column a reader uses, so that a file of another program, or ours
    // with a table dropped or altered, is named as such instead of failing a query later.
    if (!isPostgres()) {
        // The columns below are read without a word on failure: a damaged schema says so first.
        QSqlQuery schema = query();
        if (!schema.exec(QStringLiteral("SELECT count(*) FROM sqlite_master"))) {
            if (error)
                *error = failure(tr("read"), schema.lastError());
            return false;
        }
    }
    QStringList damage;
    int found = 0;
    for (const auto &[table, columns] : readColumns()) {
        // The table as the connection finds it (PostgreSQL: on its search path); none
        // has no columns.
        const QSqlRecord record = m_db.record(table);
        if (record.isEmpty()) {
            damage << tr("no table %1").arg(table);
            continue;
        }
        ++found;
        QStringList lacking;
        for (const QString &column : columns) {
            if (!record.contains(column))
                lacking << column;
        }
        if (!lacking.isEmpty())
            damage << tr("the table %1 lacks the column(s) %2").arg(table, lacking.join(QStringLiteral(", ")));
    }
    if (found == 0) {
        return refuse(Fault::NotAHistory,
                      isPostgres() ? tr("%1 holds no JUMO history: none of the history's tables is there")
                                             .arg(m_location.display())
                                   : tr("%1 is not a JUMO history file: an SQLite database without the history's "
                                        "tables")
                                             .arg(m_location.display()),
                      error);
    }
    if (!damage.isEmpty())
        return refuse(Fault::Damaged,
                      tr("%1 is damaged: %2").arg(m_location.display(), damage.join(QStringLiteral("; "))), error);

    QSqlQuery q = query();
    if (!q.exec(QStringLiteral("SELECT value FROM history_meta WHERE name = 'schema'"))) {
        if (error)
            *error = failure(tr("read"), q.lastError());
        return false;
    }
    if (!q.next())
        return refuse(Fault::Damaged, tr("%1 is damaged: it names no schema version").arg(m_location.display()), error);
    bool number = false;
    const int version = q.value(0).toString().toInt(&number);
    if (!number || version < 1) {
        return refuse(Fault::Damaged,
                      tr("%1 is damaged: '%2' is no schema version").arg(m_location.display(), q.value(0).toString()),
                      error);
    }
    if (version > schemaVersion) {
        return refuse(Fault::Unavailable,
                      tr("cannot use the history %1: it was written by a newer version (schema %2, this one knows %3)")
                              .arg(m_location.display())
                              .arg(version)
                              .arg(schemaVersion),
                      error);
    }
    return true;
}

std::optional<QString> HistoryDatabase::meta(const QString &name, QString *error)
{
    QSqlQuery q = query();
    q.prepare(QStringLiteral("SELECT value FROM history_meta WHERE name = ?"));
    q.addBindValue(name);
    if (!q.exec()) {
        if (error)
            *error = failure(tr("read"), q.lastError());
        return std::nullopt;
    }
    return q.next() ? q.value(0).toString() : QString();
}

bool HistoryDatabase::setMeta(const QString &name, const QString &value, QString *error)
{
    QSqlQuery q = query();
    q.prepare(QStringLiteral("INSERT INTO history_meta (name, value) VALUES (?, ?) "
                             "ON CONFLICT (name) DO UPDATE SET value = excluded.value"));
    q.addBindValue(name);
    q.addBindValue(value);
    if (q.exec())
        return true;
    if (error)
        *error = failure(tr("write"), q.lastError());
    return false;
}

QString HistoryDatabase::upsertRaw(int rows)
{
    return upsert(QStringLiteral("history_raw"),
                  {QStringLiteral("series"), QStringLiteral("t"), QStringLiteral("state"), QStringLiteral("value"),
                   QStringLiteral("text_value")},
                  rows);
}

QString HistoryDatabase::upsertMinute(int rows)
{
    return upsert(QStringLiteral("history_minute"),
                  {QStringLiteral("series"), QStringLiteral("t"), QStringLiteral("state"), QStringLiteral("value"),
                   QStringLiteral("minimum"), QStringLiteral("maximum"), QStringLiteral("mean"),
                   QStringLiteral("text_value")},
                  rows);
}

} // namespace jumo
