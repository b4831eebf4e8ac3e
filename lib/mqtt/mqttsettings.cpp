#include "mqtt/mqttsettings.h"

#include "protocol/maskedaddress.h"
#include "protocol/regularfile.h"

#include <QUrl>

namespace jumo {

std::optional<MqttSettings> MqttSettings::fromUrl(const QString &text, QString *error)
{
    const QString withScheme = text.contains(QLatin1String("://")) ? text : QStringLiteral("mqtt://") + text;
    const QUrl url(withScheme, QUrl::StrictMode);
    const QString scheme = url.scheme().toLower();
    auto fail = [&](const QString &why) -> std::optional<MqttSettings> {
        // Never a password in a message (it would end up in logs).
        const QString shown = url.isValid() ? url.toString(QUrl::RemovePassword) : maskedAddress(text);
        if (error)
            *error = tr("'%1' is no broker address: %2 (use mqtt://[USER@]HOST[:PORT] or mqtts://...)").arg(shown, why);
        return std::nullopt;
    };
    if (!url.isValid()) {
        // Qt's reason goes on with "; source was ..." and the address, password and all.
        return fail(url.errorString().section(QLatin1String("; source was"), 0, 0));
    }
    if (scheme != QLatin1String("mqtt") && scheme != QLatin1String("mqtts"))
        return fail(tr("unknown scheme '%1'").arg(url.scheme()));
    if (url.host().isEmpty())
        return fail(tr("no host"));
    if (!url.password().isEmpty())
        return fail(tr("a password in the address can be read by every user of this computer; "
                       "use a password file or JUMO_MQTT_PASSWORD"));
    if (!url.path().isEmpty() && url.path() != QLatin1String("/"))
        return fail(tr("an address has no path"));
    if (url.hasQuery() || url.hasFragment())
        return fail(tr("an address has no query"));
    MqttSettings settings;
    settings.tls = scheme == QLatin1String("mqtts");
    settings.host = url.host();
    const int port = url.port(settings.tls ? 8883 : 1883);
    if (port < 1 || port > 65535)
        return fail(tr("port out of range"));
    settings.port = quint16(port);
    settings.username = url.userName();
    return settings;
}

QString MqttSettings::url() const
{
    const QString host = this->host.contains(QLatin1Char(':')) ? QStringLiteral("[%1]").arg(this->host) : this->host;
    return QStringLiteral("%1://%2%3:%4")
            .arg(tls ? QStringLiteral("mqtts") : QStringLiteral("mqtt"),
                 username.isEmpty() ? QString() : username + QLatin1Char('@'), host)
            .arg(port);
}

std::optional<MqttSettings> MqttSettings::fromOptions(const Options &options, QString *error)
{
    auto refuse = [error](const QString &why) {
        if (error)
            *error = why;
        return std::nullopt;
    };
    std::optional<MqttSettings> broker = fromUrl(options.url, error);
    if (!broker)
        return std::nullopt;
    if (!options.username.isEmpty())
        broker->username = options.username;
    if (!options.passwordFile.isEmpty()) {
        const std::optional<QString> password = passwordFromFile(options.passwordFile, error);
        if (!password)
            return std::nullopt;
        broker->password = *password;
    } else {
        broker->password = qEnvironmentVariable("JUMO_MQTT_PASSWORD");
    }
    if (!broker->password.isEmpty() && broker->username.isEmpty())
        return refuse(tr("a password needs a user name: mqtt://USER@HOST or --username"));
    if ((!options.caFile.isEmpty() || !options.certFile.isEmpty() || !options.keyFile.isEmpty()) && !broker->tls)
        return refuse(tr("TLS files need an mqtts:// broker"));
    if (options.certFile.isEmpty() != options.keyFile.isEmpty())
        return refuse(tr("--tls-cert and --tls-key go together"));
    broker->caFile = options.caFile;
    broker->certFile = options.certFile;
    broker->keyFile = options.keyFile;
    return broker;
}

std::optional<QString> MqttSettings::passwordFromFile(const QString &path, QString *error)
{
    QString why;
    const std::optional<QString> password = RegularFile::firstLine(path, &why);
    if (!password && error)
        *error = tr("cannot read the password file %1").arg(why);
    return password;
}

} // namespace jumo
