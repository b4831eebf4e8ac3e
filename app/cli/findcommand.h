// jumoctl find: devices on a serial line whose baud rate, data format and addresses nobody
// knows. Tries every setting the families support (LineFinder), says what answers where
// ("at 19200 8E1: tya200 at address 4"), how long it took, and the options that reach
// what it found.
#pragma once

#include "bus/linefinder.h"

#include <QObject>
#include <QTextStream>

#include <memory>
#include <optional>

namespace jumo {

class Bus;
class FamilyRegistry;

class FindCommand : public QObject
{
    Q_OBJECT

public:
    FindCommand(const FamilyRegistry &registry, QTextStream &out, QTextStream &err, QObject *parent = nullptr);
    ~FindCommand() override;

    // An exit code when done at once (help, wrong arguments, a port that cannot be
    // opened), else nullopt and finished() later.
    std::optional<int> run(const QStringList &arguments);
    // SIGINT, SIGTERM, SIGHUP, SIGPIPE: the search stops after the probe under way and
    // says what it found so far.
    void interrupt(int signal);

signals:
    void finished(int exitCode);

private:
    void showProgress(const QString &text);
    void clearProgress();
    void onFound(const LineFinder::Finding &finding);
    void onFinished();
    QString settingName(const LineFormat &format) const;

    const FamilyRegistry &m_registry;
    QTextStream &m_out;
    QTextStream &m_err;
    std::unique_ptr<Bus> m_bus;
    std::unique_ptr<LineFinder> m_finder;
    QString m_trying;
    int m_first = 1;
    int m_last = 31;
    int m_progressWidth = 0;
    int m_interruptCode = 0;
    bool m_finished = false;
};

} // namespace jumo
