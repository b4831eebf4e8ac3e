// The commissioning report of one device as HTML: identity, every parameter, the live
// values at the time, the active alarms, and the writes of the session. The HMI and
// jumoctl print it as HTML or, through QTextDocument, as PDF.
#pragma once

#include "bus/entrystate.h"
#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonObject>

#include <functional>

namespace jumo {

class CommissioningReport
{
    Q_DECLARE_TR_FUNCTIONS(jumo::CommissioningReport)

public:
    using StateLookup = std::function<const EntryState *(const QString &entryId)>;

    CommissioningReport(const RegisterMap &map, quint8 address, StateLookup states);

    // Audit records (see WriteAudit) of this device to list as the session's writes.
    void setWrites(const QList<QJsonObject> &writes) { m_writes = writes; }
    void setTime(const QDateTime &time) { m_time = time; }

    QString html() const;

private:
    QString valueText(const RegisterEntry &entry) const;

    const RegisterMap &m_map;
    quint8 m_address;
    StateLookup m_states;
    QList<QJsonObject> m_writes;
    QDateTime m_time = QDateTime::currentDateTime();
};

} // namespace jumo
