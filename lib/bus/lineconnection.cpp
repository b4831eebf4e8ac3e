#include "bus/lineconnection.h"

#include "bus/rtutransport.h"

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcBus)

namespace jumo {

LineConnection::LineConnection(Clock *clock, TransportFactory factory, QObject *parent)
    : QObject(parent), m_clock(clock), m_factory(factory ? std::move(factory) : TransportFactory(&serialTransport))
{
}

LineConnection::~LineConnection()
{
    if (m_transport) {
        m_transport->disconnect(this);
        m_transport->close();
    }
}

std::unique_ptr<Transport> LineConnection::serialTransport(const BusSettings &settings)
{
    return std::make_unique<RtuTransport>(settings.portName, settings.format);
}

bool LineConnection::open()
{
    ++m_generation;
    if (m_transport) {
        m_transport->disconnect(this);
        m_transport->close();
        m_transport.reset();
    }
    m_transport = m_factory(m_settings);
    connect(m_transport.get(), &Transport::finished, this, &LineConnection::resultReady);
    connect(m_transport.get(), &Transport::lost, this, &LineConnection::onLost);
    QString error;
    if (!m_transport->open(&error)) {
        m_lastError = tr("cannot open %1: %2").arg(m_settings.portName, error);
        return false;
    }
    m_lastError.clear();
    setState(LineState::Connected);
    return true;
}

void LineConnection::close()
{
    ++m_generation;
    // Disconnected first: whatever listeners ask for while the transport aborts its
    // request is refused at once and cannot wait for the next open().
    setState(LineState::Disconnected);
    if (m_transport)
        m_transport->close();
}

void LineConnection::setState(LineState state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged(state);
}

void LineConnection::onLost(const QString &reason)
{
    if (m_state != LineState::Connected)
        return;
    m_lastError = tr("line lost: %1").arg(reason);
    setState(LineState::Lost);
    emit lost(m_lastError);
    const quint64 generation = ++m_generation;
    m_clock->callAt(m_clock->nowMs() + m_settings.reconnectIntervalMs, this,
                    [this, generation] { tryReconnect(generation); });
}

void LineConnection::tryReconnect(quint64 generation)
{
    if (generation != m_generation || m_state != LineState::Lost)
        return;
    if (open()) {
        qCInfo(lcBus).noquote() << "line" << m_settings.portName << "is back";
        return;
    }
    const quint64 next = ++m_generation;
    m_clock->callAt(m_clock->nowMs() + m_settings.reconnectIntervalMs, this, [this, next] { tryReconnect(next); });
}

} // namespace jumo
