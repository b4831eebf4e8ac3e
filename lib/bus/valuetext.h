// How a value and its validity read for a person, the same in every view: the live
// table, tiles, control texts, the report. A current value shows with its unit; a stale
// one too, marked; an unknown one shows no number at all, only why it is unknown.
#pragma once

#include "bus/entrystate.h"
#include "protocol/registermap.h"

#include <QCoreApplication>

namespace jumo {

class ValueText
{
    Q_DECLARE_TR_FUNCTIONS(jumo::ValueText)

public:
    // The value with its unit, or the "no value" mark when it is unknown.
    // Numbers with the entry's precision in the locale's way ("91,9 V" in German).
    static QString value(const EntryState *state, const RegisterEntry &entry);
    // The same without the unit, for a table with a unit column.
    static QString number(const EntryState *state, const RegisterEntry &entry);
    // The unit column: the symbol, or a mark that the device's configuration decides it.
    static QString unit(const RegisterEntry &entry);
    // What decides a configured unit, for a tooltip; empty for a fixed unit.
    static QString unitNote(const RegisterEntry &entry, const RegisterMap &map);
    // "OK", the error value's wording, "Stale (12 s old)", or why the value is unknown.
    static QString status(const EntryState *state, const RegisterMap &map, qint64 nowMs);
    // Why a value is unknown, in a few words ("Line lost", "Device not answering").
    static QString reason(ReadError error, int exceptionCode, const RegisterMap &map);
    // The mark shown instead of a number when there is none.
    static QString noValue();
    static Validity validity(const EntryState *state) { return state ? state->validity : Validity::Unknown; }
};

} // namespace jumo
