#include "logs/writeaudit.h"

namespace jumo {

WriteAudit::WriteAudit(Bus *bus, EventLog *log, QObject *parent) : QObject(parent), m_log(log)
{
    connect(bus, &Bus::writeRequested, this,
            [this](int ticket, const QString &device, const QString &entry, const QString &value, const QString &previous) {
                m_pending.insert(ticket, Pending{device, entry, value, previous});
            });
    connect(bus, &Bus::writeFinished, this, [this](int ticket, const WriteOutcome &outcome) {
        const auto it = m_pending.constFind(ticket);
        if (it == m_pending.cend())
            return;
        m_log->append(QJsonObject{{"device", m_prefix + it->device},
                                  {"entry", it->entry},
                                  {"old", it->previous},
                                  {"new", it->value},
                                  {"result", outcome.resultName()},
                                  {"message", outcome.message}});
        m_pending.erase(it);
    });
}

QStringList WriteAudit::columns()
{
    return {QStringLiteral("time"), QStringLiteral("device"), QStringLiteral("entry"), QStringLiteral("old"),
            QStringLiteral("new"), QStringLiteral("result"), QStringLiteral("message")};
}

} // namespace jumo
