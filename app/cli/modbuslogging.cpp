#include "modbuslogging.h"

#include <QLoggingCategory>

namespace jumo {

void showModbusLogging(bool verbose)
{
    QLoggingCategory::setFilterRules(verbose ? QStringLiteral("qt.modbus*=true\njumo.bus*=true")
                                             : QStringLiteral("qt.modbus*=false"));
}

} // namespace jumo
