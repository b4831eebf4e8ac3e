// Counters of one device on the line, shown in the HMI's traffic page and the CLI.
#pragma once

#include <QMap>

namespace jumo {

struct DeviceStatistics
{
    int requests = 0;
    int responses = 0;
    int timeouts = 0;
    int crcErrors = 0;
    int mismatches = 0;            // replies with the wrong length or for another request
    QMap<int, int> exceptions;     // code -> count
    double lastRoundTripMs = 0;
    double meanRoundTripMs = 0;    // over all answered requests
    int cycles = 0;
    double lastCycleMs = 0;

    void addRoundTrip(double ms)
    {
        lastRoundTripMs = ms;
        meanRoundTripMs += (ms - meanRoundTripMs) / ++responses;
    }
};

} // namespace jumo
