// The switchable bits of a bit field and their states as the device reports them: from
// the word itself when it is readable, else from the bits its map names as their state
// source ("stateFrom"). A bit whose word could not be read is unknown, neither on nor off.
#pragma once

#include "bus/devicesource.h"
#include "models/alarmbitsmodel.h"

namespace jumo {

struct BitStateReading
{
    const BitDefinition *bit = nullptr;
    AlarmBitsModel::BitState state = AlarmBitsModel::BitState::Unknown;
    Validity validity = Validity::Unknown;
    QString reportedIn;   // "binary_signal_1.digital_output", empty when nothing reports it
};

QList<BitStateReading> readBitStates(const DeviceSource &devices, DeviceId device, const RegisterEntry &entry);

} // namespace jumo
