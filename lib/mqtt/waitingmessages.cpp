#include "mqtt/waitingmessages.h"

namespace jumo {

bool WaitingMessages::keep(const QString &device, TopicScheme::Kind kind, const QString &entry,
                           const QByteArray &payload)
{
    auto it = m_byDevice.find(device);
    if (it != m_byDevice.end()) {
        for (qsizetype i = 0; i < it->size(); ++i) {
            if (it->at(i).kind == kind && it->at(i).entry == entry) {
                m_bytes -= it->at(i).payload.size();
                --m_messages;
                it->removeAt(i);
                break;
            }
        }
        if (it->isEmpty())
            m_byDevice.erase(it);
    }
    if (payload.isEmpty())
        return true;
    if (m_messages >= m_maxMessages || m_bytes + payload.size() > m_maxBytes)
        return false;
    m_byDevice[device].append({kind, entry, payload});
    ++m_messages;
    m_bytes += payload.size();
    return true;
}

QList<WaitingMessages::Message> WaitingMessages::take(const QString &device)
{
    const QList<Message> taken = m_byDevice.take(device);
    m_messages -= int(taken.size());
    for (const Message &m : taken)
        m_bytes -= m.payload.size();
    return taken;
}

} // namespace jumo
