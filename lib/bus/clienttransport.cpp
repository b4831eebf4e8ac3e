#include "bus/clienttransport.h"

#include <QLoggingCategory>
#include <QScopedValueRollback>

Q_DECLARE_LOGGING_CATEGORY(lcBus)

namespace jumo {

namespace {

constexpr int rejectLogIntervalMs = 60 * 1000;

} // namespace

ClientTransport::ClientTransport(QObject *parent) : Transport(parent)
{
    m_replyTimer.setSingleShot(true);
    m_replyTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_replyTimer, &QTimer::timeout, this, &ClientTransport::onReplyTimeout);
}

bool ClientTransport::open(QString *error)
{
    if (m_state != State::Closed)
        closeLink();
    m_replyTimer.stop();
    ++m_opened;
    m_state = State::Connecting;
    switch (openLink(error)) {
    case Link::Failed:
        m_state = State::Closed;
        return false;
    case Link::Open:
        m_state = State::Open;
        return true;
    case Link::Connecting:
        break;
    }
    return true;
}

void ClientTransport::close()
{
    shutDown(tr("the line was closed"));
}

void ClientTransport::shutDown(const QString &reason)
{
    m_state = State::Closed;
    m_replyTimer.stop();
    closeLink();
    if (m_request) {
        // Queued: whoever closes (or hears of the loss) goes on first. Not after the
        // transport was opened again: it would end the new connection's request.
        m_request.reset();
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = reason;
        emitLater(result);
    }
}

void ClientTransport::send(const ModbusRequest &request)
{
    const QScopedValueRollback inSend(m_inSend, true);
    if (m_request) {
        // One at a time: the bus never sends while a request is under way.
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = tr("a request was sent while another was under way");
        deliver(result);
        return;
    }
    m_request = request;
    m_transmitted = false;
    if (m_state == State::Closed) {
        fail(ModbusResult::Status::LineDown, tr("not connected to %1").arg(peer()));
        return;
    }
    if (m_state == State::Open) {
        m_transmitted = true;
        transmit(request);
    }
    // Connecting: linkUp() sends it; its timeout starts when it goes out.
}

ModbusResult ClientTransport::timedOut(const ModbusRequest &request)
{
    ModbusResult result;
    result.status = ModbusResult::Status::Timeout;
    result.errorText = tr("no reply within %1 ms").arg(request.timeoutMs);
    return result;
}

void ClientTransport::linkUp()
{
    if (m_state != State::Connecting)
        return;
    m_state = State::Open;
    emit opened();
    if (m_request && !m_transmitted && m_state == State::Open) {
        m_transmitted = true;
        transmit(*m_request);
    }
}

void ClientTransport::linkDown(const QString &reason)
{
    if (m_state == State::Closed)
        return;
    qCInfo(lcBus).noquote() << peer() << "lost:" << reason;
    shutDown(reason);
    emit lost(reason);
}

void ClientTransport::relink(const QString &reason)
{
    if (m_state == State::Closed)
        return;
    qCInfo(lcBus).noquote() << peer() << "connection made anew:" << reason;
    closeLink();
    m_state = State::Connecting;
    // A request under way already went out on the old connection: it ends by its result
    // or its timer; one sent from now on waits for the new connection.
    QString error;
    switch (openLink(&error)) {
    case Link::Failed:
        linkDown(error);
        break;
    case Link::Open:
        m_state = State::Open;
        break;
    case Link::Connecting:
        break;
    }
}

void ClientTransport::startReplyTimer(int ms)
{
    m_replyTimer.start(ms);
}

void ClientTransport::onReplyTimeout()
{
    if (!m_request)
        return;
    const ModbusRequest request = *m_request;
    complete(timedOut(request));
}

void ClientTransport::complete(const ModbusResult &result)
{
    if (!m_request)
        return;
    m_request.reset();
    m_transmitted = false;
    m_replyTimer.stop();
    deliver(result);
}

void ClientTransport::fail(ModbusResult::Status status, const QString &reason)
{
    ModbusResult result;
    result.status = status;
    result.errorText = reason;
    complete(result);
}

void ClientTransport::deliver(const ModbusResult &result)
{
    if (m_inSend)
        emitLater(result);
    else
        emit finished(result);
}

void ClientTransport::emitLater(const ModbusResult &result)
{
    QMetaObject::invokeMethod(
            this,
            [this, result, opened = m_opened] {
                if (opened == m_opened)
                    emit finished(result);
            },
            Qt::QueuedConnection);
}

void ClientTransport::noteRejected(const QString &what)
{
    if (m_lastRejectLog.isValid() && m_lastRejectLog.elapsed() < rejectLogIntervalMs) {
        ++m_rejectsUnlogged;
        return;
    }
    if (m_rejectsUnlogged > 0)
        qCWarning(lcBus).noquote() << peer() + QStringLiteral(": not taken:") << what
                                   << QStringLiteral("(and %1 more since the last such message)").arg(m_rejectsUnlogged);
    else
        qCWarning(lcBus).noquote() << peer() + QStringLiteral(": not taken:") << what;
    m_rejectsUnlogged = 0;
    m_lastRejectLog.start();
}

} // namespace jumo
