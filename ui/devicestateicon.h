// A device's state in a few pixels, for the device list: shape and colour together,
// never the colour alone (online: a green dot; alarm: a red dot with "!"; not answering
// or line lost: a grey dot with a cross; alarms unknown: a hollow ring with "?").
#pragma once

#include <QIcon>

namespace jumo {

struct DeviceCondition;

class DeviceStateIcon
{
public:
    enum class Kind { Online, Alarm, Unknown, Offline };

    static Kind kindOf(const DeviceCondition &condition, int activeAlarms, bool alarmsKnown);
    static QIcon icon(Kind kind);
};

} // namespace jumo
