// jumo-publisher's work, as a library so tests can run it in-process: reads the command
// line, makes sure no station of its name is online at the broker (unless told to take
// over), opens each line read-only with identity checks, and publishes the station
// through a StationPublisher until stop() (SIGTERM, SIGINT, SIGHUP).
#pragma once

#include "bus/stationconfig.h"
#include "mqtt/namecheck.h"
#include "mqtt/stationpublisher.h"

#include <QCoreApplication>
#include <QObject>
#include <QTextStream>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

namespace jumo {

class Bus;
class FamilyRegistry;

class PublisherProgram : public QObject
{
    Q_OBJECT

public:
    PublisherProgram(QTextStream &out, QTextStream &err, QObject *parent = nullptr);
    ~PublisherProgram() override;

    // Returns an exit code when the arguments end the program (errors, --help), or
    // nullopt when it runs on the event loop; finished() follows then.
    std::optional<int> run(const QStringList &arguments);
    // A clean stop: "stopped" is published, then finished(exitCode).
    void stop(int exitCode = 0);

    // The exit code when a station of the name is online (or took over): a service
    // manager must not start it again and again (RestartPreventExitStatus=2).
    static constexpr int nameTakenExitCode = 2;

    StationPublisher *publisher() const { return m_publisher.get(); }

signals:
    void finished(int exitCode);

private:
    std::optional<int> openLines(const QList<LineConfig> &lines);
    // After the name check: the lines opened and the station published.
    void begin();
    void retryClosedLines();

    QTextStream &m_out;
    QTextStream &m_err;
    std::unique_ptr<FamilyRegistry> m_registry;
    std::vector<std::unique_ptr<Bus>> m_buses;
    QHash<QString, QStringList> m_poll;   // family -> the entries its devices' polls read (none: all)
    std::unique_ptr<StationPublisher> m_publisher;
    std::unique_ptr<NameCheck> m_nameCheck;
    QList<LineConfig> m_lineConfigs;
    bool m_takeOver = false;
    QTimer m_retry;   // lines whose port did not open at the start
    bool m_stopping = false;
    int m_stopExitCode = 0;
};

} // namespace jumo
