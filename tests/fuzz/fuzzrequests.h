// What the network fuzz targets share: a request made from six input bytes (address,
// kind, start, count or value) as the bus sends them, and the PDU a reply taken as good
// for it must have carried.
#pragma once

#include "bus/modbusrequest.h"

#include <cstdint>

namespace jumo::fuzz {

inline ModbusRequest requestOf(const uint8_t *head)
{
    const quint8 slave = quint8(head[0] % 247 + 1);
    const quint16 start = quint16(head[2] << 8 | head[3]);
    const quint16 value = quint16(head[4] << 8 | head[5]);
    switch (head[1] % 3) {
    case 0:
        return ModbusRequest::read(slave, start, quint16(value % 125 + 1));
    case 1:
        return ModbusRequest::write(slave, start, {value});
    default: {
        QList<quint16> words;
        for (int i = 0; i < value % 8 + 2; ++i)
            words << quint16(value + i);
        return ModbusRequest::write(slave, start, words);
    }
    }
}

// A read's words as they were received, or a write's echo (function, start and the
// value for 0x06 or the count for 0x10).
inline QByteArray acceptedPdu(const ModbusRequest &request, const ModbusResult &result)
{
    if (request.isWrite())
        return request.pdu().left(5);
    QByteArray pdu(1, char(request.function));
    pdu.append(char(2 * result.words.size()));
    for (quint16 w : result.words)
        pdu.append(char(w >> 8)).append(char(w));
    return pdu;
}

} // namespace jumo::fuzz
