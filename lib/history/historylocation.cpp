#include "history/historylocation.h"

#include "protocol/maskedaddress.h"
#include "protocol/regularfile.h"

#include <QDir>
#include <QUrl>

namespace jumo {

namespace {

bool hasScheme(const QString &text)
{
    return text.contains(QLatin1String("://"));
}

} // namespace

HistoryLocation HistoryLocation::file(const QString &path)
{
    HistoryLocation location;
    location.kind = Kind::Sqlite;
    location.path = path;
    return location;
}

QString HistoryLocation::defaultFile(const QString &folder, const QString &station)
{
    return QDir(folder).filePath(QStringLiteral("history-%1.sqlite").arg(station));
}

std::optional<HistoryLocation> HistoryLocation::parse(const QString &text, QString *error)
{
    auto fail = [&](const QString &why) -> std::optional<HistoryLocation> {
        if (error)
            *error = tr("'%1' is no history database: %2 (use postgresql://[USER@]HOST[:PORT]/DATABASE or a file)")
                             .arg(maskedAddress(text), why);
        return std::nullopt;
    };
    if (text.isEmpty())
        return fail(tr("empty"));
    if (!hasScheme(text))
        return file(text);
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid())
        return fail(url.errorString().section(QLatin1String("; source was"), 0, 0));
    const QString scheme = url.scheme().toLower();
    if (scheme != QLatin1String("postgresql") && scheme != QLatin1String("postgres"))
        return fail(tr("unknown scheme '%1'").arg(url.scheme()));
    if (!url.password().isEmpty())
        return fail(tr("a password in the address can be read by every user of this computer; "
                       "use a password file or JUMO_HISTORY_PASSWORD"));
    if (url.host().isEmpty())
        return fail(tr("no host"));
    const QString database = url.path().mid(1);
    if (database.isEmpty() || database.contains(QLatin1Char('/')))
        return fail(tr("name one database: postgresql://HOST/DATABASE"));
    if (url.hasQuery() || url.hasFragment())
        return fail(tr("an address has no query"));
    const int port = url.port(5432);
    if (port < 1 || port > 65535)
        return fail(tr("port out of range"));
    HistoryLocation location;
    location.kind = Kind::Postgres;
    location.host = url.host();
    location.port = port;
    location.database = database;
    location.username = url.userName();
    return location;
}

std::optional<HistoryLocation> HistoryLocation::fromOptions(const Options &options, QString *error)
{
    std::optional<HistoryLocation> location = parse(options.url, error);
    if (!location)
        return std::nullopt;
    if (location->kind == Kind::Sqlite) {
        if (!options.username.isEmpty() || !options.passwordFile.isEmpty()) {
            if (error)
                *error = tr("a user and a password are for a PostgreSQL database, not for the file %1")
                                 .arg(location->path);
            return std::nullopt;
        }
        return location;
    }
    if (!options.username.isEmpty())
        location->username = options.username;
    if (!options.passwordFile.isEmpty()) {
        QString why;
        const std::optional<QString> password = RegularFile::firstLine(options.passwordFile, &why);
        if (!password) {
            if (error)
                *error = tr("cannot read the password file %1").arg(why);
            return std::nullopt;
        }
        location->password = *password;
    } else {
        location->password = qEnvironmentVariable("JUMO_HISTORY_PASSWORD");
    }
    return location;
}

QString HistoryLocation::display() const
{
    if (kind == Kind::Sqlite)
        return path;
    const QString shownHost = host.contains(QLatin1Char(':')) ? QStringLiteral("[%1]").arg(host) : host;
    return QStringLiteral("postgresql://%1%2:%3/%4")
            .arg(username.isEmpty() ? QString() : username + QLatin1Char('@'), shownHost)
            .arg(port)
            .arg(database);
}

} // namespace jumo
