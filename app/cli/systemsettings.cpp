#include "systemsettings.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSettings>

namespace jumo::SystemSettings {

namespace {

struct Reading
{
    Q_DECLARE_TR_FUNCTIONS(jumo::SystemSettings)

public:
    bool readOnly = false;
    QStringList warnings;

    static Reading read();
};

QString settingsPath()
{
    return QSettings(QSettings::SystemScope, QStringLiteral("jumo"), QStringLiteral("jumo-hmi")).fileName();
}

// readOnly, ReadOnly, read_only and readonly are one key to whoever typed them.
bool isReadOnlyKey(const QString &key)
{
    QString letters;
    for (const QChar c : key.section(QLatin1Char('/'), -1)) {
        if (c.isLetterOrNumber())
            letters += c.toLower();
    }
    return letters == QLatin1String("readonly");
}

Reading Reading::read()
{
    Reading r;
    const QString path = settingsPath();
    const QFileInfo info(path);
    // Checked before QSettings opens it: a FIFO would block, and QSettings takes a file
    // it cannot read for an empty one.
    if (info.exists() || info.isSymLink()) {
        if (!info.isFile() || !info.isReadable()) {
            r.readOnly = true;
            r.warnings << tr("%1 cannot be read (%2): read-only mode is on until it can")
                                  .arg(path, info.isDir() ? tr("it is a folder")
                                                 : !info.exists() ? tr("a link to nothing")
                                                 : !info.isFile() ? tr("it is no regular file")
                                                                  : tr("no permission"));
            return r;
        }
    }
    const QSettings settings(QSettings::SystemScope, QStringLiteral("jumo"), QStringLiteral("jumo-hmi"));
    if (settings.status() != QSettings::NoError) {
        r.readOnly = true;
        r.warnings << tr("%1 cannot be read (%2): read-only mode is on until it can")
                              .arg(path, settings.status() == QSettings::FormatError ? tr("malformed")
                                                                                     : tr("access error"));
        return r;
    }
    static const QStringList known{QStringLiteral("readOnly"), QStringLiteral("logs/maxFileMiB"),
                                   QStringLiteral("logs/keepFiles")};
    for (const QString &key : settings.allKeys()) {
        if (isReadOnlyKey(key)) {
            const QString value = settings.value(key).toString().trimmed().toLower();
            static const QStringList no{QStringLiteral("false"), QStringLiteral("0"), QStringLiteral("no"),
                                        QStringLiteral("off")};
            static const QStringList yes{QStringLiteral("true"), QStringLiteral("1"), QStringLiteral("yes"),
                                         QStringLiteral("on")};
            r.readOnly = r.readOnly || !no.contains(value);
            if (key != QLatin1String("readOnly"))
                r.warnings << tr("%1: '%2' is taken as readOnly").arg(path, key);
            if (!no.contains(value) && !yes.contains(value))
                r.warnings << tr("%1: '%2=%3' is no true or false: read-only mode is on")
                                      .arg(path, key, settings.value(key).toString());
        } else if (!known.contains(key)) {
            r.warnings << tr("%1: unknown key '%2' (known: %3)").arg(path, key, known.join(QStringLiteral(", ")));
        }
    }
    return r;
}

} // namespace

bool readOnly()
{
    return Reading::read().readOnly;
}

QStringList warnings()
{
    return Reading::read().warnings;
}

QString fileName()
{
    return settingsPath();
}

} // namespace jumo::SystemSettings
