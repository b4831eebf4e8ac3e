#include "bus/bus.h"

#include "bus/linetiming.h"
#include "bus/readtransaction.h"
#include "bus/writetransaction.h"
#include "protocol/bitwrite.h"
#include "protocol/rtuframe.h"

#include <QLoggingCategory>

#include <algorithm>

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
    : QObject(parent), m_ownClock(clock ? nullptr : std::make_unique<SteadyClock>()),
      m_clock(clock ? clock : m_ownClock.get()), m_line(m_clock, std::move(transport), this)
{
    qRegisterMetaType<jumo::ModbusResult>();
    qRegisterMetaType<jumo::WriteOutcome>();
    connect(&m_line, &LineConnection::stateChanged, this, &Bus::onStateChanged);
    connect(&m_line, &LineConnection::lost, this, &Bus::onLineLost);
    connect(&m_line, &LineConnection::resultReady, this, &Bus::onResult);
    m_lineSince = QDateTime::currentDateTime();
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
}

bool Bus::open()
{
    m_line.setSettings(m_settings);
    return m_line.open();
}

void Bus::close()
{
    m_line.close();
    abortQueued(tr("the line was closed"));
    invalidateAll(ReadError::LineClosed);
}

void Bus::onStateChanged(LineState state)
{
    m_lineSince = QDateTime::currentDateTime();
    if (state == LineState::Connected) {
        if (m_inFlight && m_inFlight->turn.transaction) {
            // The transport it went out on is gone without an answer.
            m_inFlight->turn.transaction->abort(tr("the line was reopened"));
            m_scheduler.transactionFinished(m_inFlight->turn.transaction);
        }
        m_inFlight.reset();
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
    abortQueued(reason);
    invalidateAll(ReadError::LineLost);
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
    const DeviceId id = m_nextDeviceId++;
    m_scheduler.addDevice(id, map, address, now());
    m_store.addDevice(id, map);
    m_store.setAllowance(id, initialAllowanceMs);
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
    m_offlineSince.remove(id);
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
    if (const Scheduler::DeviceInfo *d = m_scheduler.device(id)) {
        for (const QString &e : d->plan.errors)
            qCWarning(lcBus).noquote() << e;
    }
    schedule(now());
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
            c.state = DeviceCondition::State::Online;
            c.since = m_lineSince;
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
    }
    emit onlineChanged(id, online);
    emitCondition(id);
}

void Bus::updateAllowance(DeviceId id)
{
    const Scheduler::DeviceInfo *d = m_scheduler.device(id);
    if (!d)
        return;
    // Current for two cycles and a second: a value older than that was missed by a cycle
    // that should have read it.
    const qint64 expected = std::max<qint64>(d->intervalMs, qint64(d->lastCycleMs));
    m_store.setAllowance(id, std::max<qint64>(2 * expected, 2000) + 1000);
}

double Bus::interFrameDelayMs() const
{
    // QModbusRtuSerialClient waits 3.5 characters before each request, at least 2 ms.
    return std::max(2.0, m_settings.format.frameGapMs());
}

int Bus::requestTimeoutMs(const ProtocolInfo &protocol, int requestBytes, int replyBytes) const
{
    if (m_settings.timeoutMs > 0)
        return m_settings.timeoutMs;
    return LineTiming::timeoutMs(m_settings.format, requestBytes, replyBytes, protocol, m_settings.minimumResponseTimeMs);
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

bool Bus::mayWrite(int ticket, const RegisterMap *map, const QString &entryId)
{
    if (m_settings.readOnly) {
        refuseLater(ticket, WriteOutcome::Result::ReadOnlyMode, tr("read-only mode: %1 was not written").arg(entryId));
        return false;
    }
    if (!map) {
        refuseLater(ticket, WriteOutcome::Result::Invalid, tr("unknown device"));
        return false;
    }
    if (!map->entry(entryId)) {
        refuseLater(ticket, WriteOutcome::Result::Invalid, tr("'%1' is not an entry of %2").arg(entryId, map->family));
        return false;
    }
    return true;
}

int Bus::write(DeviceId id, const QString &entryId, const QString &value, bool verify, Lane lane)
{
    const int ticket = nextTicket();
    const EntryState *previous = entryState(id, entryId);
    emit writeRequested(ticket, deviceName(id), entryId, value,
                        previous && previous->hasValue() ? previous->value.display : QString());
    const std::shared_ptr<const RegisterMap> map = deviceMap(id);
    if (!mayWrite(ticket, map.get(), entryId))
        return ticket;
    const RegisterEntry &entry = *map->entry(entryId);
    const EncodeResult encoded = ValueCodec::encode(entry, *map, value);
    if (!encoded.ok()) {
        refuseLater(ticket, WriteOutcome::Result::Invalid, encoded.error);
        return ticket;
    }
    if (encoded.words.size() > map->protocol.effectiveMaxWriteWords()) {
        refuseLater(ticket, WriteOutcome::Result::Invalid, tr("'%1' needs more words than one write may carry").arg(entryId));
        return ticket;
    }
    if (state() != LineState::Connected) {
        refuseLater(ticket, WriteOutcome::Result::NotSent, tr("not written: the line is not connected"));
        return ticket;
    }
    m_scheduler.enqueue(WriteTransaction::value(ticket, lane, {id, deviceAddress(id)}, map, entry, encoded.words, verify,
                                                [this, ticket](const WriteOutcome &o) { finishLater(ticket, o); }));
    schedule(now());
    return ticket;
}

int Bus::writeBits(DeviceId id, const QString &entryId, const QHash<QString, bool> &bits, Lane lane)
{
    const int ticket = nextTicket();
    const std::shared_ptr<const RegisterMap> map = deviceMap(id);
    QStringList asked;
    for (auto it = bits.cbegin(); it != bits.cend(); ++it)
        asked << QStringLiteral("%1.%2=%3").arg(entryId, it.key()).arg(*it ? 1 : 0);
    asked.sort();
    const EntryState *previous = entryState(id, entryId);
    emit writeRequested(ticket, deviceName(id), entryId, asked.join(QLatin1Char(' ')),
                        previous && previous->hasValue() ? previous->value.display : QString());
    if (!mayWrite(ticket, map.get(), entryId))
        return ticket;
    QString error;
    const std::optional<BitWrite> change = BitWrite::make(*map, *map->entry(entryId), bits, &error);
    if (!change) {
        refuseLater(ticket, WriteOutcome::Result::Invalid, error);
        return ticket;
    }
    if (state() != LineState::Connected) {
        refuseLater(ticket, WriteOutcome::Result::NotSent, tr("not written: the line is not connected"));
        return ticket;
    }
    m_scheduler.enqueue(WriteTransaction::bits(ticket, lane, {id, deviceAddress(id)}, map, *change,
                                               [this, ticket](const WriteOutcome &o) { finishLater(ticket, o); }));
    schedule(now());
    return ticket;
}

int Bus::writeBroadcast(const QString &family, const QString &entryId, const QString &value)
{
    const int ticket = nextTicket();
    emit writeRequested(ticket, QStringLiteral("%1@0").arg(family), entryId, value, QString());
    std::shared_ptr<const RegisterMap> map;
    QList<WriteTransaction::Target> targets;
    for (DeviceId id : m_scheduler.devices()) {
        const Scheduler::DeviceInfo *d = m_scheduler.device(id);
        if (d->map->family == family) {
            map = d->map;
            targets << WriteTransaction::Target{id, d->address};
        }
    }
    if (m_settings.readOnly) {
        refuseLater(ticket, WriteOutcome::Result::ReadOnlyMode, tr("read-only mode: %1 was not written").arg(entryId));
        return ticket;
    }
    for (DeviceId id : m_scheduler.devices()) {
        const Scheduler::DeviceInfo *d = m_scheduler.device(id);
        if (d->map->family != family) {
            // Address 0 reaches every device: the same address means something else to
            // another family (a command word, perhaps).
            refuseLater(ticket, WriteOutcome::Result::Invalid,
                        tr("not broadcast: the line also has a %1 device at address %2, which would take the same "
                           "words as something else")
                                .arg(d->map->family)
                                .arg(d->address));
            return ticket;
        }
    }
    if (!map || !map->protocol.broadcast) {
        refuseLater(ticket, WriteOutcome::Result::Invalid,
                    tr("no %1 device on this line to read a broadcast back from").arg(family));
        return ticket;
    }
    if (!mayWrite(ticket, map.get(), entryId))
        return ticket;
    const RegisterEntry &entry = *map->entry(entryId);
    const EncodeResult encoded = ValueCodec::encode(entry, *map, value);
    if (!encoded.ok()) {
        refuseLater(ticket, WriteOutcome::Result::Invalid, encoded.error);
        return ticket;
    }
    if (state() != LineState::Connected) {
        refuseLater(ticket, WriteOutcome::Result::NotSent, tr("not written: the line is not connected"));
        return ticket;
    }
    m_scheduler.enqueue(WriteTransaction::broadcast(ticket, map, entry, encoded.words, targets,
                                                    [this, ticket](const WriteOutcome &o) { finishLater(ticket, o); }));
    schedule(now());
    return ticket;
}

QString Bus::setHold(DeviceId id, const QString &entryId, const QString &value, int intervalMs)
{
    if (m_settings.readOnly)
        return tr("read-only mode: nothing is written");
    const std::shared_ptr<const RegisterMap> map = deviceMap(id);
    if (!map)
        return tr("unknown device");
    if (value.isEmpty()) {
        m_scheduler.clearHold(id, entryId);
        return {};
    }
    const RegisterEntry *entry = map->entry(entryId);
    if (!entry)
        return tr("'%1' is not an entry of %2").arg(entryId, map->family);
    if (entry->storage == Storage::Eeprom)
        return tr("'%1' is stored in EEPROM, which wears out after about 10,000 writes: it is never rewritten "
                  "cyclically").arg(entryId);
    if (entry->storage != Storage::Ram || entry->isAction())
        return tr("only RAM values can be held, '%1' is not one").arg(entryId);
    const EncodeResult encoded = ValueCodec::encode(*entry, *map, value);
    if (!encoded.ok())
        return encoded.error;
    m_scheduler.setHold(id, entryId, encoded.words, intervalMs);
    schedule(now());
    return {};
}

int Bus::probe(quint8 slave, quint16 address, quint16 count, const ProtocolInfo &timing)
{
    const int ticket = nextTicket();
    auto report = [this, ticket](const ModbusResult &r) {
        m_clock->callSoon(this, [this, ticket, r] {
            emit probeFinished(ticket, r.words, !r.answered(), r.status == ModbusResult::Status::Exception ? r.exceptionCode : 0);
        });
    };
    if (state() != LineState::Connected) {
        report(ModbusResult{});
        return ticket;
    }
    // Repeated once: a single lost reply must not hide a device.
    m_scheduler.enqueue(std::make_unique<ReadTransaction>(ticket, Lane::Job, -1, ModbusRequest::read(slave, address, count),
                                                          timing, 2, report));
    schedule(now());
    return ticket;
}

int Bus::readEntries(DeviceId id, const QStringList &entryIds)
{
    const int ticket = nextTicket();
    const std::shared_ptr<const RegisterMap> map = deviceMap(id);
    struct Progress
    {
        int remaining = 0;
        QStringList failed;
    };
    auto progress = std::make_shared<Progress>();
    auto done = [this, ticket, progress] {
        m_clock->callSoon(this, [this, ticket, progress] { emit entriesRead(ticket, progress->failed); });
    };
    if (!map || state() != LineState::Connected) {
        progress->failed = entryIds;
        done();
        return ticket;
    }
    const ReadPlan plan = ReadPlanner::plan(*map, entryIds);
    for (const QString &e : entryIds) {
        const RegisterEntry *entry = map->entry(e);
        if (!entry || !entry->isReadable())
            progress->failed << e;
    }
    progress->remaining = int(plan.blocks.size());
    if (plan.blocks.isEmpty())
        done();
    for (const ReadBlock &block : plan.blocks) {
        auto finished = [this, id, block, progress, done](const ModbusResult &r) {
            const qint64 t = now();
            QStringList changed;
            if (r.status == ModbusResult::Status::Ok) {
                changed = m_store.store(id, block.entries, block.start, r.words, t);
            } else {
                const ReadError error = r.status == ModbusResult::Status::Exception ? ReadError::Exception
                        : r.status == ModbusResult::Status::LineDown               ? ReadError::LineLost
                                                                                    : ReadError::Timeout;
                changed = m_store.fail(id, block.entries, error, r.exceptionCode, t);
                for (const RegisterEntry *e : block.entries)
                    progress->failed << e->id;
            }
            if (!changed.isEmpty())
                emit entriesUpdated(id, changed);
            if (--progress->remaining == 0)
                done();
        };
        m_scheduler.enqueue(std::make_unique<ReadTransaction>(ticket, Lane::Job, id,
                                                              ModbusRequest::read(deviceAddress(id), block.start, block.count),
                                                              map->protocol, m_settings.retries + 1, finished));
    }
    schedule(now());
    return ticket;
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
    if (turn.request.isWrite() && m_settings.readOnly) {
        // Never reached through the public API; this is the last line of defence.
        if (turn.transaction) {
            turn.transaction->abort(tr("read-only mode"));
            m_scheduler.transactionFinished(turn.transaction);
        }
        if (turn.kind == Scheduler::Turn::Kind::Hold)
            m_scheduler.clearHold(turn.device, turn.holdEntry);
        schedule(t);
        return;
    }
    turn.request.timeoutMs = requestTimeoutMs(turn.timing, turn.request.requestBytes(), turn.request.replyBytes());
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
    countResult(flight.turn.device, result, roundTrip);
    recordTraffic(flight, result, roundTrip);
    setQuietAfter(flight, result, t);

    switch (flight.turn.kind) {
    case Scheduler::Turn::Kind::Poll:
    case Scheduler::Turn::Kind::Keepalive:
        applyPoll(flight.turn, result, t);
        break;
    case Scheduler::Turn::Kind::Transaction: {
        Transaction *transaction = flight.turn.transaction;
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

void Bus::countResult(DeviceId device, const ModbusResult &result, double roundTripMs)
{
    DeviceStatistics *s = m_store.statistics(device);
    if (!s)
        return;
    s->crcErrors += result.crcErrors;
    s->mismatches += result.mismatches;
    switch (result.status) {
    case ModbusResult::Status::Ok:
        s->addRoundTrip(roundTripMs);
        break;
    case ModbusResult::Status::Exception:
        ++s->exceptions[result.exceptionCode];
        s->addRoundTrip(roundTripMs);
        break;
    case ModbusResult::Status::Timeout:
        ++s->timeouts;
        break;
    case ModbusResult::Status::BadReply:
        ++s->mismatches;
        break;
    case ModbusResult::Status::LineDown:
        break;
    }
}

void Bus::recordTraffic(const InFlight &flight, const ModbusResult &result, double roundTripMs)
{
    TrafficRecord record;
    record.timeMs = flight.sentMs;
    record.slave = flight.turn.request.slave;
    record.request = RtuFrame::build(record.slave, flight.turn.request.pdu());
    record.reply = result.replyFrame;
    record.roundTripMs = roundTripMs;
    if (result.status != ModbusResult::Status::Ok)
        record.error = result.status == ModbusResult::Status::Exception
                ? tr("exception %1").arg(result.exceptionCode)
                : result.errorText;
    emit traffic(record);
}

void Bus::setQuietAfter(const InFlight &flight, const ModbusResult &result, qint64 now)
{
    const ModbusRequest &r = flight.turn.request;
    qint64 quiet = 0;
    if (result.status == ModbusResult::Status::Timeout || result.status == ModbusResult::Status::BadReply) {
        // After a lost reply, wait as long again as the timeout, so a late answer cannot
        // be taken for the next request's (Qt clears its buffer right before each send).
        quiet = now + std::max(r.timeoutMs, LineTiming::timeoutMs(m_settings.format, r.requestBytes(), r.replyBytes(),
                                                                   flight.turn.timing, m_settings.minimumResponseTimeMs));
    } else {
        // After a reply the other devices need the family's turnaround time.
        quiet = now + qint64(std::max(0.0, flight.turn.timing.turnaroundMs - interFrameDelayMs()) + 0.5);
    }
    if (r.isBroadcast() && result.status == ModbusResult::Status::Ok) {
        // Qt calls a broadcast done when its bytes reach the driver, not the wire; the
        // devices then need their time before anyone may talk again.
        const double wire = m_settings.format.wireTimeMs(r.requestBytes());
        quiet = now + qint64(wire + std::max(100.0, flight.turn.timing.processingTimeMaxMs + m_settings.minimumResponseTimeMs));
    }
    m_scheduler.setQuietUntil(quiet);
}

void Bus::applyPoll(const Scheduler::Turn &turn, const ModbusResult &result, qint64 now)
{
    const Scheduler::PollOutcome out = m_scheduler.pollFinished(turn, result, m_settings.retries, now);
    QStringList changed;
    if (out.store)
        changed += m_store.store(turn.device, out.entries, turn.request.start, result.words, now);
    if (out.failure)
        changed += m_store.fail(turn.device, out.entries, *out.failure, out.exceptionCode, now);
    if (!out.unavailable.isEmpty()) {
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
