// A device's parameters saved to a file: every readable and writable parameter of its
// family with the device's identity and the time, to compare and restore later.
// The JSON format is documented in resources/maps/README.md ("Parameter files").
#pragma once

#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QMap>

#include <optional>

namespace jumo {

struct ParameterDifference
{
    QString id;
    QString label;
    QString unit;
    QString oldValue;   // the device (or the first file), exact as the codec takes it
    QString newValue;   // the file (or the second file), exact
    QString oldDisplay; // as a person reads them ("33.3" for 33.2999992)
    QString newDisplay;
    bool newHeld = true;  // false: the file (the second set) holds no value for this entry
};

class ParameterSet
{
    Q_DECLARE_TR_FUNCTIONS(jumo::ParameterSet)

public:
    static constexpr int formatVersion = 1;

    QString family;
    int address = 0;
    QDateTime time;
    QString softwareVersion;             // empty where the family has none
    QMap<QString, QString> identity;     // entry id -> value as shown
    QMap<QString, QString> values;       // entry id -> value as text, as the codec takes it

    // The entries a parameter set holds: readable and writable values that configure the
    // device, not commands, outputs or overrides.
    static QStringList parameterIds(const RegisterMap &map);
    static bool isParameter(const RegisterEntry &entry);

    QByteArray toJson() const;
    static std::optional<ParameterSet> fromJson(const QByteArray &json, QString *error);

    // Why this set cannot go to a device of that family and software version; empty if
    // it can. Versions match when their first two dot-separated parts do ("123.01.x").
    QString incompatibility(const RegisterMap &map, const QString &deviceSoftwareVersion) const;

    // What differs from another set (this one is "old"), compared word by word as the
    // device stores the values, so 12.34 and 12.3400002 are the same.
    QList<ParameterDifference> differences(const ParameterSet &other, const RegisterMap &map) const;
    // The differences a restore writes: only those the file holds a value for. An entry the
    // file lacks (a partial or hand-made file) is shown by a compare and left alone.
    static QList<ParameterDifference> toRestore(const QList<ParameterDifference> &differences);
};

} // namespace jumo
