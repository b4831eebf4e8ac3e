// How to reach a serial line: port, baud and format, timing overrides, read-only mode.
#pragma once

#include "protocol/lineformat.h"

#include <QString>

namespace jumo {

struct BusSettings
{
    QString portName;
    LineFormat format;
    int timeoutMs = 0;               // 0: derived per request from the families' timing
    int minimumResponseTimeMs = 0;   // as configured in the devices (0..500 ms)
    int retries = 2;                 // done by the scheduler, after a quiet gap
    bool readOnly = false;           // no write frame ever reaches the line
    int reconnectIntervalMs = 1000;
};

} // namespace jumo
