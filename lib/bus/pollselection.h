// What a station polls of a family's devices when not every readable entry: a control
// room that needs an alarm within a second cannot wait for whole maps of 31 devices
// (about 6 s a round at 38400 baud). Entry ids and two words: "faceplate" (what the
// overview faceplate shows, scales its bars by and takes its mode and program state from)
// and "alarms" (every readable bit field with an alarm or warning bit).
#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <optional>

namespace jumo {

class FamilyRegistry;
class RegisterMap;

struct PollSelection
{
    Q_DECLARE_TR_FUNCTIONS(jumo::PollSelection)

public:
    QString family;
    QStringList entries;   // readable entry ids, in address order, each once

    // "WORD[,WORD...]" for the map: the readable entries it names, or nullopt and why.
    static std::optional<QStringList> expand(const RegisterMap &map, const QStringList &words, QString *error);
    // "FAMILY:WORD[,WORD...]", the family a known one.
    static std::optional<PollSelection> parse(const QString &text, const FamilyRegistry &registry, QString *error);
};

} // namespace jumo
