#include "bus/lineconnection.h"

#include "bus/lineaddress.h"
#include "bus/rtutcptransport.h"
#include "bus/rtutransport.h"
#include "bus/tcptransport.h"

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcBus)

namespace jumo {

LineConnection::LineConnection(Clock *clock, TransportFactory factory, QObject *parent)
    : QObject(parent), m_clock(clock), m_factory(factory ? std::move(factory) : TransportFactory(&transportFor))
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

namespace {

// A line address that cannot be parsed: open() says why, nothing is sent.
class RefusedTransport final : public Transport
{
public:
    explicit RefusedTransport(const QString &reason) : m_reason(reason) { }
    bool open(QString *error) override
    {
        if (error)
            *error = m_reason;
        return false;
    }
    void close() override { }
    bool isOpen() const override { return false; }
    void send(const ModbusRequest &) override
    {
        ModbusResult result;
        result.status = ModbusResult::Status::LineDown;
        result.errorText = m_reason;
        QMetaObject::invokeMethod(this, [this, result] { emit finished(result); }, Qt::QueuedConnection);
    }
    double interFrameDelayMs() const override { return 0; }

private:
    QString m_reason;
};

} // namespace

std::unique_ptr<Transport> LineConnection::transportFor(const BusSettings &settings)
{
    QString error;
    const std::optional<LineAddress> address = LineAddress::parse(settings.portName, &error);
    if (!address)
        return std::make_unique<RefusedTransport>(error);
    switch (address->kind) {
    case LineAddress::Kind::Serial:
        return serialTransport(settings);
    case LineAddress::Kind::ModbusTcp:
        return std::make_unique<TcpTransport>(*address, settings.format);
    case LineAddress::Kind::RtuOverTcp:
        return std::make_unique<RtuTcpTransport>(*address, settings.format);
    }
    return serialTransport(settings);
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
    connect(m_transport.get(), &Transport::opened, this, &LineConnection::onOpened);
    QString error;
    if (!m_transport->open(&error)) {
        m_lastError = tr("cannot open %1: %2").arg(m_settings.portName, error);
        return false;
    }
    // A line being brought back stays lost until its connection stands; one the user
    // opens counts as connected while it connects (requests wait in the transport), and
    // a connection that fails is a loss like any other.
    if (m_state == LineState::Lost && m_transport->isConnecting())
        return true;
    m_lastError.clear();
    setState(LineState::Connected);
    return true;
}

void LineConnection::onOpened()
{
    if (m_state != LineState::Lost)
        return;
    m_lastError.clear();
    qCInfo(lcBus).noquote() << "line" << m_settings.portName << "is back";
    setState(LineState::Connected);
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
    if (m_state == LineState::Lost) {
        // An attempt to bring it back failed while connecting: try again later.
        m_lastError = tr("line lost: %1").arg(reason);
        scheduleReconnect();
        return;
    }
    if (m_state != LineState::Connected)
        return;
    m_lastError = tr("line lost: %1").arg(reason);
    setState(LineState::Lost);
    emit lost(m_lastError);
    scheduleReconnect();
}

void LineConnection::scheduleReconnect()
{
    const quint64 generation = ++m_generation;
    m_clock->callAt(m_clock->nowMs() + m_settings.reconnectIntervalMs, this,
                    [this, generation] { tryReconnect(generation); });
}

void LineConnection::tryReconnect(quint64 generation)
{
    if (generation != m_generation || m_state != LineState::Lost)
        return;
    if (open()) {
        if (m_state == LineState::Connected)
            qCInfo(lcBus).noquote() << "line" << m_settings.portName << "is back";
        return;   // else opened() or lost() follows
    }
    scheduleReconnect();
}

} // namespace jumo
