// Retained messages of devices whose info has not come yet: a broker sends a station's
// retained topics in an order of its own, so a device's values may come before the info
// that makes the device. Kept per device until the info comes or the message is cleared,
// within bounds: a flood of values of devices nobody announced cannot fill the viewer.
#pragma once

#include "mqtt/topicscheme.h"

#include <QHash>
#include <QList>

namespace jumo {

class WaitingMessages
{
public:
    struct Message
    {
        TopicScheme::Kind kind = TopicScheme::Kind::Value;
        QString entry;
        QByteArray payload;
    };

    WaitingMessages(int maxMessages, qint64 maxBytes) : m_maxMessages(maxMessages), m_maxBytes(maxBytes) { }

    // Keeps the message in place of one of the same kind and entry; an empty payload
    // only drops that one. False when the bounds do not allow it (it is dropped).
    bool keep(const QString &device, TopicScheme::Kind kind, const QString &entry, const QByteArray &payload);
    // The device's messages, in the order they came; none are kept for it afterwards.
    QList<Message> take(const QString &device);

    int messages() const { return m_messages; }
    qint64 bytes() const { return m_bytes; }

private:
    QHash<QString, QList<Message>> m_byDevice;
    int m_maxMessages;
    qint64 m_maxBytes;
    int m_messages = 0;
    qint64 m_bytes = 0;
};

} // namespace jumo
