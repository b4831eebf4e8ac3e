#include "bus/bus.h"

#include "bus/linetiming.h"
#include "protocol/rtuframe.h"

#include <QLoggingCategory>

#include <algorithm>
#include <atomic>

Q_LOGGING_CATEGORY(lcBus, "jumo.bus", QtWarningMsg)

namespace jumo {

namespace {

constexpr int busyRetryDelayMs = 100;
constexpr int sweepIntervalMs = 250;
constexpr qint64 initialAllowanceMs = 10000;

} // namespace

Bus::Bus(QObject *parent) : Bus(nullptr, nullptr, parent)
{
}

Bus::Bus(Clock *clock, LineConnection::TransportFactory transport, QObject *parent)
    : DeviceSource(parent), m_ownClock(clock ? nullptr : std::make_unique<SteadyClock>()),
      m_clock(clock ? clock : m_ownClock.get()), m_line(m_clock, std::move(transport), this)
{
    qRegisterMetaType<jumo::ModbusResult>();
    qRegisterMetaType<jumo::WriteOutcome>();
    connect(&m_line, &LineConnection::stateChanged, this, &Bus::onStateChanged);
    connect(&m_line, &LineConnection::lost, this, &Bus::onLineLost);
    connect(&m_line, &LineConnection::resultReady, this, &Bus::onResult);
    connect(&m_identities, &DeviceIdentities::changed, this, &Bus::onIdentityChanged);
    m_lineSince = QDateTime::currentDateTime();
    m_shown = std::make_unique<ShownViews>([this](DeviceId id, const QSet<QString> &shown) {
        m_scheduler.setShown(id, shown);
        m_store.setClasses(id, m_scheduler.entryClasses(id));
        updateAllowance(id);
        schedule(now());
    });
}

void Bus::setIdentityCheck(const QList<std::shared_ptr<const RegisterMap>> &families)
{
    m_identities.setFamilies(families);
}

void Bus::onIdentityChanged(DeviceId id)
{
    const qint64 t = now();
    switch (m_identities.state(id)) {
    case DeviceIdentities::State::Confirmed:
        // What a device that was not this one lacked says nothing about this one.
        m_scheduler.forgetUnavailable(id);
        requestCycle(id);   // its values count from now: read them at once
        break;
    case DeviceIdentities::State::Refused:
        if (const QStringList changed = m_store.invalidate(id, ReadError::WrongDevice, t); !changed.isEmpty())
            emit entriesUpdated(id, changed);
        break;
    case DeviceIdentities::State::Unconfirmed:
        break;   // gone: the loss has made its values unknown already
    }
    emitCondition(id);
}

Bus::~Bus()
{
    // The line closes with the bus; nobody may hear of what that aborts.
    blockSignals(true);
    m_line.disconnect(this);
}

void Bus::setSettings(const BusSettings &settings)
{
    m_settings = settings;
    const std::optional<LineAddress> address = LineAddress::parse(settings.portName, nullptr);
    m_lineKind = address ? address->kind : LineAddress::Kind::Serial;
    m_scheduler.setLineFormat(settings.format);
    for (DeviceId id : m_scheduler.devices())
        m_store.setClasses(id, m_scheduler.entryClasses(id));
}

bool Bus::open()
{
    // Opened again while connected: the old transport goes with its request.
    loseInFlight(tr("the line was reopened"));
    m_identities.forgetAll();
    m_line.setSettings(m_settings);
    return m_line.open();
}

void Bus::close()
{
    m_line.close();
    // The request under way ends now (a write as unknown): the transport says so only
    // from the event loop, when whoever closed the line may be gone (a CLI on a signal).
    // Then the queue, with what its transaction asked next.
    loseInFlight(tr("the line was closed"));
    abortQueued(tr("the line was closed"));
    invalidateAll(ReadError::LineClosed);
    m_identities.forgetAll();
}

void Bus::onStateChanged(LineState state)
{
    m_lineSince = QDateTime::currentDateTime();
    if (state == LineState::Connected) {
        loseInFlight(tr("the line was reopened"));
        m_wakeAtMs = -1;
        m_scheduler.restart(now());
        if (!m_sweeping) {
            m_sweeping = true;
            m_clock->callAt(now() + sweepIntervalMs, this, [this] { sweep(); });
        }
        schedule(now());
    }
    emit stateChanged(state);
    for (DeviceId id : m_scheduler.devices())
        emitCondition(id);
}

void Bus::onLineLost(const QString &reason)
{
    qCWarning(lcBus).noquote() << reason;
    // The request under way is lost with the line (a write: unknown), said before the
    // loss itself: whoever ends on the loss has its outcome and audit record first. Then
    // the queue, with what its transaction asked next (a repeat of a write).
    loseInFlight(reason);
    abortQueued(reason);
    invalidateAll(ReadError::LineLost);
    m_identities.forgetAll();
    emit lineError(reason);
}

void Bus::abortQueued(const QString &reason)
{
    const Transaction *inFlight = m_inFlight ? m_inFlight->turn.transaction : nullptr;
    // Asked for before the loss: reported, never replayed later.
    const std::vector<std::unique_ptr<Transaction>> queued = m_scheduler.takeQueued(inFlight);
    for (const auto &t : queued)
        t->abort(reason);
}

void Bus::invalidateAll(ReadError reason)
{
    const qint64 t = now();
    for (DeviceId id : m_scheduler.devices()) {
        const QStringList changed = m_store.invalidate(id, reason, t);
        if (!changed.isEmpty())
            emit entriesUpdated(id, changed);
    }
}

DeviceId Bus::addDevice(std::shared_ptr<const RegisterMap> map, quint8 address)
{
    // Unique in the process, not only on this line: a station with several lines keys its
    // pages, tiles and publications by device id.
    static std::atomic<DeviceId> nextDeviceId{1};
    const DeviceId id = nextDeviceId++;
    m_scheduler.addDevice(id, map, address, now());
    m_store.addDevice(id, map);
    m_store.setAllowance(id, initialAllowanceMs);
    m_store.setClasses(id, m_scheduler.entryClasses(id));
    m_offlineSince.remove(id);
    for (const QString &e : m_scheduler.device(id)->plan.errors)
        qCWarning(lcBus).noquote() << e;
    schedule(now());
    return id;
}

void Bus::removeDevice(DeviceId id)
{
    const Transaction *inFlight = m_inFlight ? m_inFlight->turn.transaction : nullptr;
    m_scheduler.forgetDevice(id, inFlight);
    if (inFlight)
        m_forgetAfterFlight << id;
    m_scheduler.removeDevice(id);
    m_store.removeDevice(id);
    m_shown->forgetDevice(id);
    m_offlineSince.remove(id);
    m_identities.removeDevice(id);
}

std::shared_ptr<const RegisterMap> Bus::deviceMap(DeviceId id) const
{
    const Scheduler::DeviceInfo *d = m_scheduler.device(id);
    return d ? d->map : nullptr;
}

quint8 Bus::deviceAddress(DeviceId id) const
{
    const Scheduler::DeviceInfo *d = m_scheduler.device(id);
    return d ? d->address : 0;
}

QString Bus::deviceName(DeviceId id) const
{
    const Scheduler::DeviceInfo *d = m_scheduler.device(id);
    return d ? QStringLiteral("%1@%2").arg(d->map->family).arg(d->address) : QString();
}

void Bus::setPollEntries(DeviceId id, const QStringList &ids)
{
    m_scheduler.setPollEntries(id, ids);
    m_store.setClasses(id, m_scheduler.entryClasses(id));
    if (const Scheduler::DeviceInfo *d = m_scheduler.device(id)) {
        for (const QString &e : d->plan.errors)
            qCWarning(lcBus).noquote() << e;
    }
    schedule(now());
}

QStringList Bus::pollEntries(DeviceId id) const
{
    return m_scheduler.pollEntries(id);
}

void Bus::setPollInterval(DeviceId id, int ms)
{
    m_scheduler.setPollInterval(id, ms);
    updateAllowance(id);
    schedule(now());
}

void Bus::setPolling(bool on)
{
    m_scheduler.setPolling(on);
    schedule(now());
}

void Bus::requestCycle(DeviceId id)
{
    if (!m_scheduler.contains(id))
        return;
    if (!m_scheduler.requestCycle(id, now())) {
        // Nothing to read: the cycle is over before it began.
        m_clock->callSoon(this, [this, id] { emit pollCycleFinished(id, 0); });
        return;
    }
    schedule(now());
}

const EntryState *Bus::entryState(DeviceId id, const QString &entryId) const
{
    return m_store.state(id, entryId);
}

PollClass Bus::pollClass(DeviceId id, const QString &entryId) const
{
    return m_scheduler.entryClasses(id).value(entryId, PollClass::Live);
}

const DeviceStatistics *Bus::statistics(DeviceId id) const
{
    return m_store.statistics(id);
}

bool Bus::isOnline(DeviceId id) const
{
    const Scheduler::DeviceInfo *d = m_scheduler.device(id);
    return d && d->online;
}

int Bus::backoffMs(DeviceId id) const
{
    const Scheduler::DeviceInfo *d = m_scheduler.device(id);
    return d ? d->backoffMs : 0;
}

const ReadPlan *Bus::plan(DeviceId id) const
{
    const Scheduler::DeviceInfo *d = m_scheduler.device(id);
    return d ? &d->plan : nullptr;
}

DeviceCondition Bus::condition(DeviceId id) const
{
    DeviceCondition c;
    switch (state()) {
    case LineState::Lost:
        c.state = DeviceCondition::State::LineLost;
        c.since = m_lineSince;
        break;
    case LineState::Disconnected:
        c.state = DeviceCondition::State::Disconnected;
        c.since = m_lineSince;
        break;
    case LineState::Connected:
        if (isOnline(id)) {
            switch (m_identities.state(id)) {
            case DeviceIdentities::State::Confirmed:
                c.state = DeviceCondition::State::Online;
                c.since = m_lineSince;
                break;
            case DeviceIdentities::State::Unconfirmed:
                c.state = DeviceCondition::State::Identifying;
                c.since = m_lineSince;
                c.detail = m_identities.reason(id);
                break;
            case DeviceIdentities::State::Refused:
                c.state = DeviceCondition::State::WrongDevice;
                c.since = m_identities.since(id);
                c.detail = m_identities.reason(id);
                break;
            }
        } else {
            c.state = DeviceCondition::State::Offline;
            c.since = m_offlineSince.value(id, m_lineSince);
        }
        break;
    }
    return c;
}

void Bus::emitCondition(DeviceId id)
{
    emit conditionChanged(id, condition(id));
}

void Bus::setOnline(DeviceId id, bool online)
{
    if (online) {
        m_offlineSince.remove(id);
        qCInfo(lcBus).noquote() << deviceName(id) << "online";
    } else {
        m_offlineSince.insert(id, QDateTime::currentDateTime());
        qCInfo(lcBus).noquote() << deviceName(id) << "offline";
        m_identities.forget(id);   // whatever answers next is checked again
    }
    emit onlineChanged(id, online);
    emitCondition(id);
}

void Bus::updateAllowance(DeviceId id)
{
    if (!m_scheduler.contains(id))
        return;
    // Current for about twice the age its class is read at, and a second: a value older
    // than that was missed by a read that should have come.
    for (PollClass c : {PollClass::Alarm, PollClass::Live, PollClass::Setting})
        m_store.setAllowance(id, c, m_scheduler.allowanceMs(id, c));
    m_store.setShownLive(id, m_scheduler.shownLive(id), m_scheduler.shownAllowanceMs(id));
}

double Bus::interFrameDelayMs() const
{
    return LineTiming::interFrameDelayMs(m_settings.format);
}

int Bus::requestTimeoutMs(const ProtocolInfo &protocol, int requestBytes, int replyBytes) const
{
    if (m_settings.timeoutMs > 0)
        return m_settings.timeoutMs;
    // Over TCP the baud rate is the gateway's serial side: its timing, and the network's.
    const int margin = m_lineKind == LineAddress::Kind::Serial ? 0 : LineTiming::networkMarginMs;
    return LineTiming::timeoutMs(m_settings.format, requestBytes, replyBytes, protocol, m_settings.minimumResponseTimeMs)
            + margin;
}

int Bus::quickProbeTimeoutMs(const ProtocolInfo &protocol, int requestBytes, int replyBytes) const
{
    const int margin = m_lineKind == LineAddress::Kind::Serial ? 0 : LineTiming::networkMarginMs;
    const int quick = LineTiming::timeoutMs(m_settings.format, requestBytes, replyBytes, LineTiming::quickTiming(protocol),
                                            m_settings.minimumResponseTimeMs)
            + margin;
    return std::min(quick, requestTimeoutMs(protocol, requestBytes, replyBytes));
}

void Bus::finishLater(int ticket, const WriteOutcome &outcome)
{
    m_clock->callSoon(this, [this, ticket, outcome] { emit writeFinished(ticket, outcome); });
}

void Bus::refuseLater(int ticket, WriteOutcome::Result result, const QString &message)
{
    WriteOutcome outcome;
    outcome.result = result;
    outcome.message = message;
    finishLater(ticket, outcome);
}

int Bus::write(DeviceId id, const QString &entryId, const QString &value, bool verify, Lane lane)
{
    return m_requests.write(id, entryId, value, verify, lane);
}

int Bus::writeBits(DeviceId id, const QString &entryId, const QHash<QString, bool> &bits, Lane lane)
{
    return m_requests.writeBits(id, entryId, bits, lane);
}

int Bus::writeBroadcast(const QString &family, const QString &entryId, const QString &value)
{
    return m_requests.writeBroadcast(family, entryId, value);
}

QString Bus::setHold(DeviceId id, const QString &entryId, const QString &value, int intervalMs)
{
    return m_requests.setHold(id, entryId, value, intervalMs);
}

int Bus::probe(quint8 slave, quint16 address, quint16 count, const ProtocolInfo &timing)
{
    return m_requests.probe(slave, address, count, timing, false);
}

int Bus::quickProbe(quint8 slave, quint16 address, quint16 count, const ProtocolInfo &timing)
{
    return m_requests.probe(slave, address, count, timing, true);
}

int Bus::readEntries(DeviceId id, const QStringList &entryIds)
{
    return m_requests.readEntries(id, entryIds);
}

void Bus::cancel(int ticket)
{
    const Transaction *inFlight = m_inFlight ? m_inFlight->turn.transaction : nullptr;
    const std::vector<std::unique_ptr<Transaction>> dropped = m_scheduler.takeTicket(ticket, inFlight);
    for (const auto &t : dropped)
        t->abort(tr("cancelled"));
}

void Bus::schedule(qint64 atMs)
{
    if (state() != LineState::Connected)
        return;
    if (m_wakeAtMs >= 0 && m_wakeAtMs <= atMs)
        return;   // an earlier call is on its way
    m_wakeAtMs = atMs;
    m_clock->callAt(atMs, this, [this, atMs] {
        if (m_wakeAtMs == atMs)
            dispatch();
    });
}

void Bus::dispatch()
{
    m_wakeAtMs = -1;
    if (state() != LineState::Connected || m_inFlight || !m_line.transport())
        return;
    const qint64 t = now();
    Scheduler::Turn turn = m_scheduler.next(t);
    if (turn.kind == Scheduler::Turn::Kind::Idle) {
        if (turn.wakeAtMs >= 0)
            schedule(turn.wakeAtMs);
        return;
    }
    const bool untrusted = turn.request.slave != 0 && !m_identities.isTrusted(turn.device);
    if (turn.request.isWrite() && (m_settings.readOnly || untrusted)) {
        // Never reached through the public API; this is the last line of defence.
        if (turn.transaction) {
            turn.transaction->abort(m_settings.readOnly ? tr("read-only mode")
                                                        : tr("the device's identity is not confirmed"));
            m_scheduler.transactionFinished(turn.transaction);
        }
        if (turn.kind == Scheduler::Turn::Kind::Hold) {
            // Never quietly: whoever set the hold believes the device keeps the value.
            m_scheduler.clearHold(turn.device, turn.holdEntry);
            const QString reason = m_settings.readOnly
                    ? tr("read-only mode")
                    : tr("%1 is not confirmed to be a %2 (it is checked again when it answers); set the hold again "
                         "once it is")
                              .arg(deviceName(turn.device), deviceMap(turn.device) ? deviceMap(turn.device)->family : QString());
            qCWarning(lcBus).noquote() << "hold of" << deviceName(turn.device) << turn.holdEntry << "stopped:" << reason;
            emit holdStopped(turn.device, turn.holdEntry, reason);
        }
        schedule(t);
        return;
    }
    turn.request.timeoutMs = isQuickProbe(turn) ? quickProbeTimeoutMs(turn.timing, turn.request.requestBytes(), turn.request.replyBytes())
                                   : requestTimeoutMs(turn.timing, turn.request.requestBytes(), turn.request.replyBytes());
    if (DeviceStatistics *s = m_store.statistics(turn.device))
        ++s->requests;
    m_scheduler.sent(turn.request, t);
    m_inFlight = InFlight{turn, t};
    m_line.transport()->send(turn.request);
}

void Bus::onResult(const ModbusResult &result)
{
    if (!m_inFlight)
        return;
    const InFlight flight = *m_inFlight;
    m_inFlight.reset();
    const qint64 t = now();
    const double roundTrip = double(t - flight.sentMs);
    m_store.count(flight.turn.device, result, roundTrip);
    m_strayReplies += quint64(std::max(0, result.crcErrors) + std::max(0, result.mismatches)
                              + std::max(0, result.unframedReceptions))
            + (result.status == ModbusResult::Status::BadReply ? 1 : 0);
    recordTraffic(flight, result, roundTrip);
    setQuietAfter(flight, result, t);
    m_scheduler.charge(flight.turn, std::max(t, m_scheduler.quietUntil()) - flight.sentMs);

    switch (flight.turn.kind) {
    case Scheduler::Turn::Kind::Poll:
    case Scheduler::Turn::Kind::Keepalive:
        applyPoll(flight.turn, result, t);
        break;
    case Scheduler::Turn::Kind::Transaction: {
        Transaction *transaction = flight.turn.transaction;
        if (flight.turn.request.isWrite() && result.status != ModbusResult::Status::LineDown)
            refreshSettingsAfterWrite(flight.turn);
        if (transaction->onResult(result, m_settings.retries) == Transaction::Next::RetryAfterQuiet
            && result.status == ModbusResult::Status::Exception)
            m_scheduler.setQuietUntil(t + busyRetryDelayMs);
        m_scheduler.transactionFinished(transaction);
        break;
    }
    case Scheduler::Turn::Kind::Hold:
        if (!result.answered() || result.status == ModbusResult::Status::Exception)
            qCWarning(lcBus).noquote() << "hold write to" << deviceName(flight.turn.device) << flight.turn.holdEntry
                                       << "failed:" << result.errorText;
        break;
    case Scheduler::Turn::Kind::Idle:
        break;
    }
    for (DeviceId id : std::exchange(m_forgetAfterFlight, {}))
        m_scheduler.forgetDevice(id, nullptr);
    schedule(t);
}

void Bus::loseInFlight(const QString &reason)
{
    if (!m_inFlight)
        return;
    // The transport it went out on is gone without an answer: the request may have
    // reached the device (a write's outcome is unknown), as when the line goes down.
    ModbusResult result;
    result.status = ModbusResult::Status::LineDown;
    result.errorText = reason;
    onResult(result);
}

void Bus::refreshSettingsAfterWrite(const Scheduler::Turn &turn)
{
    // A write may change more than its own word (a configuration, a parameter set): the
    // device's settings are read at once, not in a minute.
    const qint64 t = now();
    if (!turn.request.isBroadcast()) {
        m_scheduler.refreshSettings(turn.device, t);
        return;
    }
    for (DeviceId id : m_scheduler.devices())
        m_scheduler.refreshSettings(id, t);
}

void Bus::recordTraffic(const InFlight &flight, const ModbusResult &result, double roundTripMs)
{
    TrafficRecord record;
    record.timeMs = flight.sentMs;
    record.slave = flight.turn.request.slave;
    record.request = RtuFrame::build(record.slave, flight.turn.request.pdu());
    record.reply = result.replyFrame;
    record.roundTripMs = roundTripMs;
    if (result.status == ModbusResult::Status::Exception) {
        // What the code means to this family ("exception 2, illegal data address"), as
        // writes say it: a bare number tells the status bar's reader nothing.
        const std::shared_ptr<const RegisterMap> map = deviceMap(flight.turn.device);
        record.error = map ? tr("exception %1, %2").arg(result.exceptionCode).arg(map->exceptionMeaning(result.exceptionCode))
                           : tr("exception %1").arg(result.exceptionCode);
    } else if (result.status != ModbusResult::Status::Ok) {
        record.error = result.errorText;
    }
    emit traffic(record);
}

void Bus::setQuietAfter(const InFlight &flight, const ModbusResult &result, qint64 now)
{
    m_scheduler.setQuietUntil(now + LineTiming::quietAfterMs(m_settings.format, flight.turn.request, result,
                                                             flight.turn.timing, m_settings.minimumResponseTimeMs,
                                                             isQuickProbe(flight.turn) ? LineTiming::LateAnswer::Harmless
                                                                   : LineTiming::LateAnswer::Guarded));
}

void Bus::applyPoll(const Scheduler::Turn &turn, const ModbusResult &result, qint64 now)
{
    const Scheduler::PollOutcome out = m_scheduler.pollFinished(turn, result, m_settings.retries, now);
    QStringList changed;
    const bool trusted = m_identities.isTrusted(turn.device);
    // Answers of a device not (yet) known to be what the map says tell nothing of it.
    const ReadError untrusted = m_identities.state(turn.device) == DeviceIdentities::State::Refused
            ? ReadError::WrongDevice
            : ReadError::Unconfirmed;
    if (out.store && trusted)
        changed += m_store.store(turn.device, out.entries, turn.request.start, result.words, now);
    else if (out.store)
        changed += m_store.fail(turn.device, out.entries, untrusted, 0, now);
    if (out.failure)
        changed += m_store.fail(turn.device, out.entries, *out.failure, out.exceptionCode, now);
    if (!out.unavailable.isEmpty() && !trusted) {
        changed += m_store.fail(turn.device, out.unavailable, untrusted, 0, now);
    } else if (!out.unavailable.isEmpty()) {
        for (const RegisterEntry *e : out.unavailable)
            qCInfo(lcBus).noquote() << deviceName(turn.device) << e->id << formatAddress(e->address)
                                    << "is not available on this device (exception 02)";
        changed += m_store.fail(turn.device, out.unavailable, ReadError::NotAvailable, 2, now);
    }
    if (out.online && !*out.online)
        changed += m_store.invalidate(turn.device, ReadError::DeviceOffline, now);
    if (!changed.isEmpty()) {
        changed.removeDuplicates();
        emit entriesUpdated(turn.device, changed);
    }
    if (out.online)
        setOnline(turn.device, *out.online);
    // Heard: it answered (a timeout or a gateway's exception is no sign of the device).
    const bool answered = result.status == ModbusResult::Status::Ok
            || (result.status == ModbusResult::Status::Exception && !result.isGatewayException());
    if (answered && isOnline(turn.device))
        m_identities.heard(turn.device);
    if (out.cycleMs) {
        if (DeviceStatistics *s = m_store.statistics(turn.device)) {
            ++s->cycles;
            s->lastCycleMs = *out.cycleMs;
        }
        updateAllowance(turn.device);
        emit pollCycleFinished(turn.device, *out.cycleMs);
    }
}

void Bus::sweep()
{
    if (state() != LineState::Connected) {
        m_sweeping = false;
        return;
    }
    const qint64 t = now();
    for (DeviceId id : m_scheduler.devices()) {
        const QStringList stale = m_store.sweep(id, t);
        if (!stale.isEmpty())
            emit entriesUpdated(id, stale);
    }
    m_clock->callAt(t + sweepIntervalMs, this, [this] { sweep(); });
}

} // namespace jumo
