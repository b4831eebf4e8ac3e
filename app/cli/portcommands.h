// jumoctl ports: the serial ports under their stable by-id names, with the adapter's
// description and serial number, the device each is now, and whether it can be opened
// (and if not, why and what to do).
#pragma once

#include <QCoreApplication>
#include <QStringList>
#include <QTextStream>

namespace jumo {

class PortCommands
{
    Q_DECLARE_TR_FUNCTIONS(jumo::PortCommands)

public:
    PortCommands(QTextStream &out, QTextStream &err);

    int ports(const QStringList &arguments);

private:
    QTextStream &m_out;
    QTextStream &m_err;
};

} // namespace jumo
