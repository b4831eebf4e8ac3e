#include "bus/modbusrequest.h"

#include "bus/linetiming.h"

namespace jumo {

ModbusRequest ModbusRequest::read(quint8 slave, quint16 start, quint16 count)
{
    ModbusRequest r;
    r.slave = slave;
    r.function = Function::ReadHolding;
    r.start = start;
    r.count = count;
    return r;
}

ModbusRequest ModbusRequest::write(quint8 slave, quint16 start, const QList<quint16> &words)
{
    ModbusRequest r;
    r.slave = slave;
    r.function = words.size() == 1 ? Function::WriteSingle : Function::WriteMultiple;
    r.start = start;
    r.count = quint16(words.size());
    r.words = words;
    return r;
}

QByteArray ModbusRequest::pdu() const
{
    QByteArray pdu(1, char(function));
    pdu.append(char(start >> 8)).append(char(start));
    switch (function) {
    case Function::ReadHolding:
        pdu.append(char(count >> 8)).append(char(count));
        break;
    case Function::WriteSingle:
        pdu.append(char(words.value(0) >> 8)).append(char(words.value(0)));
        break;
    case Function::WriteMultiple:
        pdu.append(char(words.size() >> 8)).append(char(words.size())).append(char(words.size() * 2));
        for (quint16 w : words)
            pdu.append(char(w >> 8)).append(char(w));
        break;
    }
    return pdu;
}

int ModbusRequest::replyBytes() const
{
    return isWrite() ? LineTiming::writeReplyBytes : LineTiming::readReplyBytes(count);
}

} // namespace jumo
