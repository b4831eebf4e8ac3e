// Qt's Modbus client logs every CRC error, timeout and frame it handles itself ("Discarding
// response with wrong CRC"). The tools report each outcome in their own words, so those
// lines are --verbose output, not noise on stderr. QT_LOGGING_RULES still overrides.
#pragma once

namespace jumo {

// verbose: Qt's Modbus categories (every level) and the bus's own notes on stderr;
// otherwise Qt's Modbus categories are silent.
void showModbusLogging(bool verbose);

} // namespace jumo
