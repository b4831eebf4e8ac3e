// How to reach an MQTT broker: host, port, TLS files, user and password, the client id
// and keepalive. Parsed from "mqtt://[USER@]HOST[:PORT]" or "mqtts://..." (TLS, 8883).
#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace jumo {

struct MqttSettings
{
    Q_DECLARE_TR_FUNCTIONS(jumo::MqttSettings)

public:
    QString host;
    quint16 port = 1883;
    bool tls = false;
    QString username;
    // Never from the command line: a password in argv can be read by every local user
    // (ps, /proc/PID/cmdline) and stays in shell histories; see passwordFromFile().
    QString password;
    QString caFile;     // TLS: the CA that signed the broker's certificate (empty: the system's)
    QString certFile;   // TLS: an optional client certificate and its key
    QString keyFile;
    QString clientId;   // empty: made from the program's name, the host and the process
    int keepAliveS = 10;

    // "mqtt://[USER@]HOST[:PORT]", "mqtts://..." (TLS, default port 8883); a bare host
    // is taken as mqtt://. IPv6 hosts in brackets.
    static std::optional<MqttSettings> fromUrl(const QString &url, QString *error);
    // The broker as people read it in logs ("mqtts://user@host:8883"), never the password.
    QString url() const;
    // The first line of a file, without its line end; nullopt with the reason on error.
    static std::optional<QString> passwordFromFile(const QString &path, QString *error);

    // The broker as the programs' command lines give it: the URL, a user name that
    // replaces the URL's (empty: keep it), the password from a file or else from
    // JUMO_MQTT_PASSWORD, and TLS files (only with mqtts://, a certificate with its key).
    struct Options
    {
        QString url;
        QString username;
        QString passwordFile;
        QString caFile;
        QString certFile;
        QString keyFile;
    };
    static std::optional<MqttSettings> fromOptions(const Options &options, QString *error);
};

} // namespace jumo
