// jumoctl history: the recorded values of a device's entries over a time span, with
// their state and validity, read from a station's history (its SQLite file in the log
// folder, or a database named by URL) without opening a line.
#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QStringList>
#include <QTextStream>

#include <optional>

namespace jumo {

class FamilyRegistry;

class HistoryCommands
{
    Q_DECLARE_TR_FUNCTIONS(jumo::HistoryCommands)

public:
    HistoryCommands(const FamilyRegistry &registry, QTextStream &out, QTextStream &err);

    // 0 with the records; 1 when the history cannot be read or holds nothing of the
    // device; 2 for wrong arguments, and a file that is no JUMO history or a damaged one;
    // 128 + the signal's number after SIGINT, SIGTERM, SIGHUP or SIGPIPE.
    int history(const QStringList &arguments);

    // "2026-12-03T08:00" (local time unless it names its offset or Z), "now", or a time
    // before now: "-90s", "-15m", "-2h", "-7d". A local time the clocks skip is an error;
    // of one they show twice, the first, and note says so.
    static std::optional<QDateTime> parseTime(const QString &text, const QDateTime &now, QString *error,
                                              QString *note);

private:
    // "jumoctl history: interrupted: WHAT WAS DONE" and the like.
    static QString signalSummary(int signal, const QString &done);

    const FamilyRegistry &m_registry;
    QTextStream &m_out;
    QTextStream &m_err;
};

} // namespace jumo
