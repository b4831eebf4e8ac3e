#include "bus/rtustreamframer.h"

#include "bus/rtutransport.h"
#include "protocol/rtuframe.h"

namespace jumo {

QByteArray RtuStreamFramer::frame(const ModbusRequest &request, qint64 nowMs)
{
    holdUntil(request, nowMs);   // forgets what is no longer owed
    // Whatever came before answers nothing that is asked now.
    if (m_buffer.size() > m_heardBytes)
        ++m_unframed;
    m_buffer.clear();
    m_heardBytes = 0;
    if (request.isBroadcast())
        m_request.reset();   // nobody answers address 0
    else
        m_request = request;
    return RtuFrame::build(request.slave, request.pdu());
}

std::optional<ModbusResult> RtuStreamFramer::received(QByteArrayView bytes, qint64 nowMs)
{
    Q_UNUSED(nowMs)
    m_buffer.append(bytes.data(), bytes.size());
    if (m_buffer.size() > 2 * keptBytes) {
        const qsizetype dropped = m_buffer.size() - keptBytes;
        m_buffer.remove(0, dropped);
        m_heardBytes = std::max<qsizetype>(0, m_heardBytes - dropped);
    }
    settleOwed();
    if (!m_request)
        return std::nullopt;
    qsizetype skipped = 0;
    int crcErrors = 0;
    int mismatches = 0;
    const std::optional<qsizetype> length = findReply(*m_request, m_buffer, &skipped, &crcErrors, &mismatches);
    if (!length)
        return std::nullopt;
    ModbusResult result = resultOfFrame(*m_request, QByteArrayView(m_buffer).sliced(skipped, *length));
    result.crcErrors = crcErrors;
    result.mismatches = mismatches + m_lateReplies.take(m_request->slave);
    result.unframedReceptions = std::exchange(m_unframed, 0);
    m_buffer.remove(0, skipped + *length);
    m_heardBytes = std::max<qsizetype>(0, m_heardBytes - (skipped + *length));
    m_request.reset();
    return result;
}

ModbusResult RtuStreamFramer::timedOut(qint64 nowMs)
{
    ModbusResult result;
    result.status = ModbusResult::Status::Timeout;
    if (!m_request)
        return result;
    qsizetype skipped = 0;
    findReply(*m_request, m_buffer, &skipped, &result.crcErrors, &result.mismatches);
    result.mismatches += m_lateReplies.take(m_request->slave);
    result.unframedReceptions = std::exchange(m_unframed, 0)
            + (!m_buffer.isEmpty() && result.mismatches == 0 && result.crcErrors == 0 ? 1 : 0);
    m_heardBytes = m_buffer.size();
    if (m_buffer.isEmpty() && result.mismatches == 0)
        result.errorText = tr("no reply within %1 ms").arg(m_request->timeoutMs);
    else if (result.mismatches > 0)
        result.errorText = tr("no reply that fits the request within %1 ms (%n that did not fit dropped)", nullptr,
                              result.mismatches)
                                   .arg(m_request->timeoutMs);
    else
        result.errorText = tr("no complete reply within %1 ms (%2 byte(s) received: %3)")
                                   .arg(m_request->timeoutMs)
                                   .arg(m_buffer.size())
                                   .arg(QString::fromLatin1(RtuFrame::toHex(QByteArrayView(m_buffer).first(
                                           std::min<qsizetype>(m_buffer.size(), 16)))));
    m_owed.append({*m_request, nowMs + lateReplyMs});
    m_request.reset();
    return result;
}

qint64 RtuStreamFramer::holdUntil(const ModbusRequest &request, qint64 nowMs)
{
    m_owed.removeIf([nowMs](const Owed &owed) { return owed.untilMs <= nowMs; });
    qint64 until = nowMs;
    for (const Owed &owed : std::as_const(m_owed)) {
        // An exception answers any request of the function: the count does not tell them apart.
        if (owed.request.slave == request.slave && owed.request.function == request.function)
            until = std::max(until, owed.untilMs);
    }
    return until;
}

void RtuStreamFramer::reset()
{
    m_request.reset();
    m_buffer.clear();
    m_owed.clear();
    m_lateReplies.clear();
    m_unframed = 0;
    m_heardBytes = 0;
}

void RtuStreamFramer::settleOwed()
{
    for (qsizetype i = 0; i < m_owed.size();) {
        qsizetype skipped = 0;
        int ignored = 0;
        if (!findReply(m_owed[i].request, m_buffer, &skipped, &ignored)) {
            ++i;
            continue;
        }
        // It came after all, and is no answer to anything asked now. Counted with the
        // next result of its device (while a request of that device is under way, the
        // search for its reply counts it).
        if (!m_request || m_request->slave != m_owed[i].request.slave)
            ++m_lateReplies[m_owed[i].request.slave];
        m_owed.removeAt(i);
    }
}

std::optional<qsizetype> RtuStreamFramer::findReply(const ModbusRequest &request, const QByteArray &buffer,
                                                    qsizetype *skipped, int *crcErrors, int *mismatches)
{
    const quint8 function = quint8(request.function);
    // An adapter or device server that echoes what it sends: the request itself (a 0x06
    // reply is the request's echo by the standard, so it is the answer there). Made
    // once a byte could begin it.
    const bool mayEcho = request.function != ModbusRequest::Function::WriteSingle;
    QByteArray echo;
    int badFrames = 0;
    int otherFrames = 0;
    std::optional<qsizetype> foundAt;
    qsizetype foundLength = 0;
    for (qsizetype at = 0; at < buffer.size(); ++at) {
        const QByteArrayView head = QByteArrayView(buffer).sliced(at);
        if (quint8(head[0]) != request.slave)
            continue;
        if (head.size() < 2)
            break;
        const quint8 received = quint8(head[1]);
        if (mayEcho && received == function) {
            if (echo.isEmpty())
                echo = RtuFrame::build(request.slave, request.pdu());
            if (head.startsWith(echo)) {
                at += echo.size() - 1;
                continue;
            }
        }
        const bool ours = received == function || received == (function | 0x80);
        const std::optional<int> length = RtuFrame::expectedLength(head, RtuFrame::Direction::Response);
        if (!length || head.size() < *length) {
            if (ours)
                break;   // perhaps the reply, not complete yet
            continue;
        }
        if (*length < 0)
            continue;
        const QByteArrayView frame = head.first(*length);
        if (!RtuFrame::hasValidCrc(frame)) {
            if (ours)
                ++badFrames;   // garbled, or bytes that only looked like a reply: look further
            continue;
        }
        if (answers(request, frame)) {
            if (foundAt)
                ++otherFrames;   // a device answers once: the earlier one answered an earlier request
            foundAt = at;
            foundLength = *length;
        } else {
            ++otherFrames;   // this device's answer to something else
        }
        at += *length - 1;
    }
    *crcErrors = badFrames;
    if (mismatches)
        *mismatches = otherFrames;
    if (!foundAt)
        return std::nullopt;
    *skipped = *foundAt;
    return foundLength;
}

ModbusResult RtuStreamFramer::resultOfFrame(const ModbusRequest &request, QByteArrayView frame)
{
    return RtuTransport::resultOfResponse(request, frame.sliced(1, frame.size() - 3));
}

bool RtuStreamFramer::answers(const ModbusRequest &request, QByteArrayView frame)
{
    return frame.size() >= 4 && quint8(frame[0]) == request.slave
            && resultOfFrame(request, frame).status != ModbusResult::Status::BadReply;
}

} // namespace jumo
