#include "models/devicetitle.h"

namespace jumo {

QString DeviceTitle::brief(const RegisterMap &map, quint8 address)
{
    return tr("%1 @ %2").arg(map.shortName).arg(address);
}

QString DeviceTitle::full(const RegisterMap &map, quint8 address, const QString &line)
{
    return line.isEmpty() ? tr("%1 at address %2").arg(map.shortName).arg(address)
                          : tr("%1 at address %2 on line %3").arg(map.shortName).arg(address).arg(line);
}

} // namespace jumo
