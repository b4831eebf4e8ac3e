#include "models/bitstates.h"

#include "protocol/bitwrite.h"

namespace jumo {

QList<BitStateReading> readBitStates(const DeviceSource &devices, DeviceId device, const RegisterEntry &entry)
{
    QList<BitStateReading> out;
    const auto map = devices.deviceMap(device);
    if (!map)
        return out;
    for (const BitDefinition *bit : BitWrite::switchableBits(entry)) {
        BitStateReading reading;
        reading.bit = bit;
        const auto [source, sourceBit] = BitWrite::reportOf(*map, entry, *bit);
        if (source) {
            reading.reportedIn = source->id + QLatin1Char('.') + sourceBit->id;
            if (const EntryState *s = devices.entryState(device, source->id); s && s->hasValue()) {
                reading.validity = s->validity;
                if (s->validity != Validity::Unknown)
                    reading.state = (s->value.raw & sourceBit->mask()) ? AlarmBitsModel::BitState::On
                                                                       : AlarmBitsModel::BitState::Off;
            }
        }
        out << reading;
    }
    return out;
}

} // namespace jumo
