#include "bus/bus.h"

#include "bus/linetiming.h"
#include "protocol/rtuframe.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QModbusReply>
#include <QModbusRtuSerialClient>
#include <QVariant>

#include <algorithm>

Q_LOGGING_CATEGORY(lcBus, "jumo.bus", QtWarningMsg)

namespace jumo {

namespace {

constexpr int busyRetryDelayMs = 100;
constexpr int failuresBeforeOffline = 2;   // blocks that failed after all retries
constexpr int firstBackoffMs = 1000;
constexpr int maximumBackoffMs = 30000;
constexpr int busyExceptionCode = 6;

QByteArray readPdu(quint16 start, quint16 count)
{
    QByteArray pdu(1, char(0x03));
    pdu.append(char(start >> 8)).append(char(start)).append(char(count >> 8)).append(char(count));
    return pdu;
}

QByteArray writePdu(quint16 start, const QList<quint16> &words)
{
    QByteArray pdu;
    if (words.size() == 1) {
        pdu.append(char(0x06)).append(char(start >> 8)).append(char(start));
        pdu.append(char(words[0] >> 8)).append(char(words[0]));
        return pdu;
    }
    pdu.append(char(0x10)).append(char(start >> 8)).append(char(start));
    pdu.append(char(words.size() >> 8)).append(char(words.size())).append(char(words.size() * 2));
    for (quint16 w : words)
        pdu.append(char(w >> 8)).append(char(w));
    return pdu;
}

} // namespace

Bus::Bus(QObject *parent) : QObject(parent)
{
    m_clock.start();
    m_dispatchTimer.setSingleShot(true);
    m_dispatchTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_dispatchTimer, &QTimer::timeout, this, &Bus::dispatch);
    connect(&m_reconnectTimer, &QTimer::timeout, this, &Bus::tryReconnect);
}

Bus::~Bus()
{
    if (m_client) {
        // Replies still queued finish as aborted while the client closes; nobody may
        // hear of it any more.
        blockSignals(true);
        m_client->disconnect(this);
        const QList<QModbusReply *> replies = m_client->findChildren<QModbusReply *>();
        for (QModbusReply *reply : replies)
            reply->disconnect(this);
        m_client->disconnectDevice();
    }
}

void Bus::setSettings(const BusSettings &settings)
{
    m_settings = settings;
}

bool Bus::open()
{
    if (!m_client) {
        m_client = new QModbusRtuSerialClient(this);
        connect(m_client, &QModbusDevice::errorOccurred, this, &Bus::onErrorOccurred);
    }
    if (m_client->state() != QModbusDevice::UnconnectedState)
        m_client->disconnectDevice();
    const LineFormat &f = m_settings.format;
    m_client->setConnectionParameter(QModbusDevice::SerialPortNameParameter, m_settings.portName);
    m_client->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, f.baudRate);
    m_client->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    // Qt's default parity is Even: always set it.
    m_client->setConnectionParameter(QModbusDevice::SerialParityParameter, f.parity);
    m_client->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, f.stopBits);
    m_client->setNumberOfRetries(0);   // retries are the scheduler's, after a quiet gap
    m_client->setInterFrameDelay(0);   // the minimum: 3.5 characters, at least 2 ms
    if (!m_client->connectDevice() || m_client->state() != QModbusDevice::ConnectedState) {
        m_lastError = tr("cannot open %1: %2").arg(m_settings.portName, m_client->errorString());
        m_client->disconnectDevice();
        return false;
    }
    m_lastError.clear();
    m_reconnectTimer.stop();
    m_writeQueue.clear();   // nothing asked for before this open is sent now
    m_probeQueue.clear();
    for (DeviceState &d : m_devices) {
        d.blockIndex = -1;
        d.nextDueMs = now();
    }
    setState(LineState::Connected);
    schedule();
    return true;
}

void Bus::close()
{
    m_reconnectTimer.stop();
    m_dispatchTimer.stop();
    // Disconnected first: whatever listeners ask for while the client aborts its reply
    // is refused at once and cannot wait in a queue for the next open().
    setState(LineState::Disconnected);
    if (m_client)
        m_client->disconnectDevice();
    m_inFlight = false;
    failAllWrites(tr("the line was closed"));
}

void Bus::setState(LineState state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged(state);
}

void Bus::onErrorOccurred(QModbusDevice::Error error)
{
    if (m_state != LineState::Connected)
        return;
    if (error != QModbusDevice::ConnectionError && error != QModbusDevice::ReadError
        && error != QModbusDevice::WriteError)
        return;
    // An unplugged adapter keeps the client "connected" and can flood errors: close on
    // the first one, fail what was asked for, and come back when the port returns.
    m_lastError = tr("line lost: %1").arg(m_client->errorString());
    qCWarning(lcBus).noquote() << m_lastError;
    setState(LineState::Lost);
    m_client->disconnectDevice();
    m_inFlight = false;
    failAllWrites(m_lastError);
    emit lineError(m_lastError);
    m_reconnectTimer.start(m_settings.reconnectIntervalMs);
}

void Bus::tryReconnect()
{
    if (m_state != LineState::Lost)
        return;
    if (open())
        qCInfo(lcBus).noquote() << "line" << m_settings.portName << "is back";
}

void Bus::failAllWrites(const QString &reason)
{
    // Writes asked for before a loss are reported failed and never replayed later.
    const QQueue<Job> writes = std::exchange(m_writeQueue, {});
    for (const Job &job : writes) {
        if (job.ticket > 0 && job.kind != JobKind::Hold)
            queueImmediateOutcome(job.ticket, WriteOutcome::Result::Failed, reason);
    }
    const QQueue<Job> probes = std::exchange(m_probeQueue, {});
    for (const Job &job : probes) {
        QMetaObject::invokeMethod(this, [this, ticket = job.ticket] { emit probeFinished(ticket, {}, true, 0); },
                                  Qt::QueuedConnection);
    }
}

DeviceId Bus::addDevice(std::shared_ptr<const RegisterMap> map, quint8 address)
{
    const DeviceId id = m_nextDeviceId++;
    DeviceState &d = m_devices[id];
    d.map = std::move(map);
    d.address = address;
    d.nextDueMs = now();
    replan(d);
    schedule();
    return id;
}

void Bus::removeDevice(DeviceId id)
{
    m_devices.remove(id);
}

std::shared_ptr<const RegisterMap> Bus::deviceMap(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? nullptr : it->map;
}

quint8 Bus::deviceAddress(DeviceId id) const
{
    return m_devices.value(id).address;
}

void Bus::replan(DeviceState &device)
{
    device.plan = ReadPlanner::plan(*device.map, device.pollIds);
    for (const QString &e : device.plan.errors)
        qCWarning(lcBus).noquote() << e;
    device.blockIndex = -1;
}

void Bus::setPollEntries(DeviceId id, const QStringList &ids)
{
    if (!m_devices.contains(id))
        return;
    m_devices[id].pollIds = ids;
    replan(m_devices[id]);
    schedule();
}

void Bus::setPollInterval(DeviceId id, int ms)
{
    if (m_devices.contains(id))
        m_devices[id].intervalMs = std::max(0, ms);
    schedule();
}

void Bus::setPolling(bool on)
{
    m_polling = on;
    schedule();
}

void Bus::requestCycle(DeviceId id)
{
    if (!m_devices.contains(id))
        return;
    DeviceState &d = m_devices[id];
    if (d.plan.blocks.isEmpty()) {
        // Nothing to read: the cycle is over before it began.
        QMetaObject::invokeMethod(this, [this, id] { emit pollCycleFinished(id, 0); }, Qt::QueuedConnection);
        return;
    }
    d.cycleRequested = true;
    d.nextDueMs = std::min(d.nextDueMs, now());
    schedule();
}

const EntryState *Bus::entryState(DeviceId id, const QString &entryId) const
{
    const auto it = m_devices.constFind(id);
    if (it == m_devices.cend())
        return nullptr;
    const auto v = it->values.constFind(entryId);
    return v == it->values.cend() ? nullptr : &*v;
}

const DeviceStatistics *Bus::statistics(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? nullptr : &it->stats;
}

const ReadPlan *Bus::plan(DeviceId id) const
{
    const auto it = m_devices.constFind(id);
    return it == m_devices.cend() ? nullptr : &it->plan;
}

bool Bus::isOnline(DeviceId id) const
{
    return m_devices.value(id).online;
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

void Bus::queueImmediateOutcome(int ticket, WriteOutcome::Result result, const QString &message)
{
    WriteOutcome outcome;
    outcome.result = result;
    outcome.message = message;
    QMetaObject::invokeMethod(this, [this, ticket, outcome] { emit writeFinished(ticket, outcome); },
                              Qt::QueuedConnection);
}

std::optional<Bus::Job> Bus::makeWriteJob(int ticket, const std::shared_ptr<const RegisterMap> &map,
                                           const QString &entryId, const QString &value)
{
    if (m_settings.readOnly) {
        queueImmediateOutcome(ticket, WriteOutcome::Result::ReadOnlyMode,
                              tr("read-only mode: %1 was not written").arg(entryId));
        return std::nullopt;
    }
    const RegisterEntry *entry = map ? map->entry(entryId) : nullptr;
    if (!entry) {
        queueImmediateOutcome(ticket, WriteOutcome::Result::Invalid,
                              map ? tr("'%1' is not an entry of %2").arg(entryId, map->family) : tr("unknown device"));
        return std::nullopt;
    }
    const EncodeResult encoded = ValueCodec::encode(*entry, *map, value);
    if (!encoded.ok()) {
        queueImmediateOutcome(ticket, WriteOutcome::Result::Invalid, encoded.error);
        return std::nullopt;
    }
    if (encoded.words.size() > map->protocol.effectiveMaxWriteWords()) {
        queueImmediateOutcome(ticket, WriteOutcome::Result::Invalid,
                              tr("'%1' needs more words than one write may carry").arg(entryId));
        return std::nullopt;
    }
    if (m_state != LineState::Connected) {
        queueImmediateOutcome(ticket, WriteOutcome::Result::Failed, tr("the line is not connected"));
        return std::nullopt;
    }
    Job job;
    job.kind = JobKind::Write;
    job.ticket = ticket;
    job.start = entry->address;
    job.count = quint16(encoded.words.size());
    job.words = encoded.words;
    job.map = map;
    job.entry = entry;
    job.timing = map->protocol;
    return job;
}

int Bus::write(DeviceId id, const QString &entryId, const QString &value, bool verify)
{
    const int ticket = m_nextTicket++;
    const auto it = m_devices.constFind(id);
    const EntryState *previous = entryState(id, entryId);
    emit writeRequested(ticket,
                        it == m_devices.cend() ? QString() : QStringLiteral("%1@%2").arg(it->map->family).arg(it->address),
                        entryId, value, previous && previous->hasValue() ? previous->value.display : QString());
    std::optional<Job> job = makeWriteJob(ticket, it == m_devices.cend() ? nullptr : it->map, entryId, value);
    if (!job)
        return ticket;
    job->device = id;
    job->slave = it->address;
    job->verify = verify;
    m_writeQueue.enqueue(*job);
    schedule();
    return ticket;
}

int Bus::writeBroadcast(const QString &family, const QString &entryId, const QString &value)
{
    const int ticket = m_nextTicket++;
    emit writeRequested(ticket, QStringLiteral("%1@0").arg(family), entryId, value, QString());
    std::shared_ptr<const RegisterMap> map;
    QList<DeviceId> targets;
    for (auto it = m_devices.cbegin(); it != m_devices.cend(); ++it) {
        if (it->map->family == family) {
            map = it->map;
            targets << it.key();
        }
    }
    for (auto it = m_devices.cbegin(); it != m_devices.cend(); ++it) {
        if (!m_settings.readOnly && it->map->family != family) {
            // Address 0 reaches every device: the same address means something else to
            // another family (a command word, perhaps).
            queueImmediateOutcome(ticket, WriteOutcome::Result::Invalid,
                                  tr("not broadcast: the line also has a %1 device at address %2, which would take the "
                                     "same words as something else")
                                          .arg(it->map->family)
                                          .arg(it->address));
            return ticket;
        }
    }
    if (!m_settings.readOnly && (!map || !map->protocol.broadcast)) {
        queueImmediateOutcome(ticket, WriteOutcome::Result::Invalid,
                              tr("no %1 device on this line to read a broadcast back from").arg(family));
        return ticket;
    }
    std::optional<Job> job = makeWriteJob(ticket, map, entryId, value);
    if (!job)
        return ticket;
    job->slave = 0;
    job->broadcast = true;
    job->family = family;
    job->readBackDevices = targets;
    m_writeQueue.enqueue(*job);
    schedule();
    return ticket;
}

QString Bus::setHold(DeviceId id, const QString &entryId, const QString &value, int intervalMs)
{
    if (m_settings.readOnly)
        return tr("read-only mode: nothing is written");
    if (!m_devices.contains(id))
        return tr("unknown device");
    DeviceState &d = m_devices[id];
    if (value.isEmpty()) {
        d.holds.remove(entryId);
        return {};
    }
    const RegisterEntry *entry = d.map->entry(entryId);
    if (!entry)
        return tr("'%1' is not an entry of %2").arg(entryId, d.map->family);
    if (entry->storage == Storage::Eeprom)
        return tr("'%1' is stored in EEPROM, which wears out after about 10,000 writes: it is never rewritten "
                  "cyclically").arg(entryId);
    if (entry->storage != Storage::Ram)
        return tr("only RAM values can be held, '%1' is not one").arg(entryId);
    const EncodeResult encoded = ValueCodec::encode(*entry, *d.map, value);
    if (!encoded.ok())
        return encoded.error;
    d.holds.insert(entryId, HoldState{encoded.words, std::max(200, intervalMs), -1});
    schedule();
    return {};
}

int Bus::probe(quint8 slave, quint16 address, quint16 count, const ProtocolInfo &timing)
{
    Job job;
    job.kind = JobKind::Probe;
    job.ticket = m_nextTicket++;
    job.slave = slave;
    job.start = address;
    job.count = count;
    job.timing = timing;
    if (m_state != LineState::Connected) {
        QMetaObject::invokeMethod(this, [this, ticket = job.ticket] { emit probeFinished(ticket, {}, true, 0); },
                                  Qt::QueuedConnection);
        return job.ticket;
    }
    m_probeQueue.enqueue(job);
    schedule();
    return job.ticket;
}

void Bus::schedule(int delayMs)
{
    if (m_state != LineState::Connected || m_inFlight)
        return;
    const int current = m_dispatchTimer.isActive() ? m_dispatchTimer.remainingTime() : -1;
    if (current < 0 || delayMs < current)
        m_dispatchTimer.start(std::max(0, delayMs));
}

void Bus::dispatch()
{
    if (m_state != LineState::Connected || m_inFlight)
        return;
    const qint64 t = now();
    if (t < m_quietUntilMs) {
        schedule(int(m_quietUntilMs - t));
        return;
    }
    if (!m_writeQueue.isEmpty()) {
        send(m_writeQueue.dequeue());
        return;
    }
    for (auto it = m_devices.begin(); it != m_devices.end(); ++it) {
        for (auto h = it->holds.begin(); h != it->holds.end(); ++h) {
            if (h->lastSentMs < 0 || t - h->lastSentMs >= h->intervalMs) {
                h->lastSentMs = t;
                Job job;
                job.kind = JobKind::Hold;
                job.device = it.key();
                job.slave = it->address;
                job.map = it->map;
                job.entry = it->map->entry(h.key());
                job.start = job.entry->address;
                job.count = quint16(h->words.size());
                job.words = h->words;
                job.timing = it->map->protocol;
                send(job);
                return;
            }
        }
    }
    if (!m_probeQueue.isEmpty()) {
        send(m_probeQueue.dequeue());
        return;
    }
    Job job;
    qint64 earliest = -1;
    if (pickPollJob(job, t, earliest)) {
        send(job);
        return;
    }
    qint64 next = earliest;
    for (const DeviceState &d : std::as_const(m_devices)) {
        for (const HoldState &h : d.holds) {
            const qint64 due = h.lastSentMs + h.intervalMs;
            next = next < 0 ? due : std::min(next, due);
        }
    }
    if (next >= 0)
        schedule(int(std::max<qint64>(1, next - t)));
}

bool Bus::pickPollJob(Job &job, qint64 now, qint64 &earliestDue)
{
    if (m_devices.isEmpty())
        return false;
    // Round-robin by request: each device in turn gets one block, so a long cycle of one
    // device never holds up the others.
    QList<DeviceId> order = m_devices.keys();
    const auto split = std::upper_bound(order.begin(), order.end(), m_roundRobin);
    std::rotate(order.begin(), split, order.end());
    for (DeviceId id : std::as_const(order)) {
        DeviceState &d = m_devices[id];
        if (d.plan.blocks.isEmpty())
            continue;
        const bool wanted = m_polling || d.cycleRequested;
        if (d.blockIndex < 0) {
            if (!wanted)
                continue;
            if (now < d.nextDueMs) {
                earliestDue = earliestDue < 0 ? d.nextDueMs : std::min(earliestDue, d.nextDueMs);
                continue;
            }
            d.blockIndex = 0;
            d.cycleStartMs = now;
        }
        const ReadBlock &block = d.plan.blocks.at(d.blockIndex);
        job = Job();
        job.kind = JobKind::Poll;
        job.device = id;
        job.slave = d.address;
        job.start = block.start;
        job.count = block.count;
        job.timing = d.map->protocol;
        m_roundRobin = id;
        return true;
    }
    return false;
}

void Bus::send(Job job)
{
    const bool isWrite = job.kind == JobKind::Write || job.kind == JobKind::Hold;
    if (isWrite && m_settings.readOnly) {
        // Never reached through the public API; this is the last line of defence.
        if (job.kind == JobKind::Write)
            finishWrite(job, {WriteOutcome::Result::ReadOnlyMode, tr("read-only mode"), 0, {}});
        schedule();
        return;
    }
    ++job.attempts;
    const QByteArray pdu = isWrite ? writePdu(job.start, job.words) : readPdu(job.start, job.count);
    const int requestBytes = int(pdu.size()) + 3;
    const int replyBytes = isWrite ? LineTiming::writeReplyBytes : LineTiming::readReplyBytes(job.count);
    m_client->setTimeout(requestTimeoutMs(job.timing, requestBytes, replyBytes));

    QModbusReply *reply = nullptr;
    if (isWrite) {
        QModbusDataUnit unit(QModbusDataUnit::HoldingRegisters, job.start, job.words);
        // One value goes out as 0x06, more as 0x10; floats and 32-bit values are two
        // words and so always one atomic 0x10 request.
        reply = m_client->sendWriteRequest(unit, job.slave);
    } else {
        reply = m_client->sendReadRequest(QModbusDataUnit(QModbusDataUnit::HoldingRegisters, job.start, job.count),
                                          job.slave);
    }
    if (m_devices.contains(job.device))
        ++m_devices[job.device].stats.requests;
    const qint64 sentMs = now();
    if (!reply) {
        TrafficRecord record{sentMs, job.slave, RtuFrame::build(job.slave, pdu), {}, 0, m_client->errorString()};
        emit traffic(record);
        m_inFlight = true;   // handled below as a failed request
        QMetaObject::invokeMethod(this, [this, job, sentMs] { onReplyFinished(nullptr, job, sentMs); },
                                  Qt::QueuedConnection);
        return;
    }
    m_inFlight = true;
    if (reply->isFinished()) {
        // A broadcast is finished once sent; handle it after this call returns.
        QMetaObject::invokeMethod(this, [this, reply, job, sentMs] { onReplyFinished(reply, job, sentMs); },
                                  Qt::QueuedConnection);
        return;
    }
    connect(reply, &QModbusReply::finished, this, [this, reply, job, sentMs] { onReplyFinished(reply, job, sentMs); });
}

void Bus::onReplyFinished(QModbusReply *reply, Job job, qint64 sentMs)
{
    m_inFlight = false;
    const qint64 t = now();
    const double roundTrip = double(t - sentMs);
    const bool isWrite = job.kind == JobKind::Write || job.kind == JobKind::Hold;
    DeviceState *device = m_devices.contains(job.device) ? &m_devices[job.device] : nullptr;

    QModbusDevice::Error error = reply ? reply->error() : QModbusDevice::ConnectionError;
    int exceptionCode = 0;
    QList<quint16> words;
    QString problem;
    if (reply) {
        reply->deleteLater();
        const QList<QModbusDevice::IntermediateError> intermediate = reply->intermediateErrors();
        if (device) {
            device->stats.crcErrors += int(intermediate.count(QModbusDevice::ResponseCrcError));
            device->stats.mismatches += int(intermediate.count(QModbusDevice::ResponseRequestMismatch));
        }
        if (error == QModbusDevice::NoError && !isWrite && job.slave != 0) {
            const QModbusDataUnit unit = reply->result();
            // A reply of the wrong size is someone else's answer: never decode it.
            if (unit.valueCount() != job.count || unit.startAddress() != job.start) {
                error = QModbusDevice::UnknownError;
                problem = tr("reply of %1 words where %2 were asked for").arg(unit.valueCount()).arg(job.count);
                if (device)
                    ++device->stats.mismatches;
            } else {
                words = unit.values();
            }
        } else if (error == QModbusDevice::ProtocolError) {
            exceptionCode = int(reply->rawResult().exceptionCode());
            if (device)
                ++device->stats.exceptions[exceptionCode];
        } else if (error == QModbusDevice::TimeoutError && device) {
            ++device->stats.timeouts;
        }
        if (problem.isEmpty() && error != QModbusDevice::NoError)
            problem = reply->errorString();
        const QModbusResponse raw = reply->rawResult();
        TrafficRecord record;
        record.timeMs = sentMs;
        record.slave = job.slave;
        record.request = RtuFrame::build(job.slave, isWrite ? writePdu(job.start, job.words) : readPdu(job.start, job.count));
        if (raw.isValid() || raw.isException()) {
            QByteArray pdu(1, char(raw.functionCode() | (raw.isException() ? 0x80 : 0)));
            pdu += raw.data();
            record.reply = RtuFrame::build(job.slave, pdu);
        }
        record.roundTripMs = roundTrip;
        record.error = error == QModbusDevice::NoError ? QString() : problem;
        emit traffic(record);
    }
    const bool answered = error == QModbusDevice::NoError || error == QModbusDevice::ProtocolError;
    if (device && answered && job.slave != 0)
        device->stats.addRoundTrip(roundTrip);

    // After a reply the other devices need the family's turnaround time; after a lost
    // reply, wait as long again as the timeout so a late answer cannot be taken for the
    // next request's (Qt clears its buffer right before each send).
    if (error == QModbusDevice::TimeoutError || error == QModbusDevice::UnknownError)
        m_quietUntilMs = t + std::max(requestTimeoutMs(job.timing, 8, LineTiming::readReplyBytes(job.count)),
                                      LineTiming::timeoutMs(m_settings.format, 8, LineTiming::readReplyBytes(job.count),
                                                            job.timing, m_settings.minimumResponseTimeMs));
    else
        m_quietUntilMs = t + qint64(std::max(0.0, job.timing.turnaroundMs - interFrameDelayMs()) + 0.5);

    const bool lineDown = !reply || error == QModbusDevice::ReplyAbortedError || error == QModbusDevice::ConnectionError
            || m_state != LineState::Connected;
    const bool busy = error == QModbusDevice::ProtocolError && exceptionCode == busyExceptionCode && device
            && device->map->exceptions.contains(busyExceptionCode);
    const bool retryable = !lineDown && job.slave != 0 && job.kind != JobKind::Probe && job.kind != JobKind::Hold
            && (error == QModbusDevice::TimeoutError || error == QModbusDevice::UnknownError || busy);
    if (busy)
        m_quietUntilMs = std::max(m_quietUntilMs, t + busyRetryDelayMs);
    if (retryable && job.kind == JobKind::Poll && device && device->online
        && ++device->blockAttempts <= m_settings.retries) {
        // The block stays current; the device's next turn repeats it.
        qCDebug(lcBus) << "retry" << job.slave << formatAddress(job.start) << problem;
        schedule();
        return;
    }
    if (retryable && job.kind != JobKind::Poll && job.attempts <= m_settings.retries) {
        qCDebug(lcBus) << "retry" << job.slave << formatAddress(job.start) << problem;
        m_writeQueue.prepend(job);
        schedule();
        return;
    }
    if (device && job.kind == JobKind::Poll)
        device->blockAttempts = 0;

    if (job.broadcast && job.kind == JobKind::Write && error == QModbusDevice::NoError) {
        // Qt calls a broadcast done when its bytes reach the driver, not the wire; the
        // devices then need their time before anyone may talk again.
        const double wire = m_settings.format.wireTimeMs(int(writePdu(job.start, job.words).size()) + 3);
        m_quietUntilMs = t + qint64(wire + std::max(100.0, job.timing.processingTimeMaxMs + m_settings.minimumResponseTimeMs));
    }

    switch (job.kind) {
    case JobKind::Poll:
        if (!device)
            break;
        if (error == QModbusDevice::NoError)
            completePoll(job, words);
        else
            failPoll(job, lineDown ? ReadError::Disconnected
                                   : error == QModbusDevice::ProtocolError ? ReadError::Exception
                                   : error == QModbusDevice::UnknownError ? ReadError::Mismatch : ReadError::Timeout,
                     exceptionCode);
        break;
    case JobKind::Probe:
        emit probeFinished(job.ticket, words, !answered, exceptionCode);
        break;
    case JobKind::Hold:
        if (!answered)
            qCWarning(lcBus) << "hold write to" << job.slave << formatAddress(job.start) << "failed:" << problem;
        break;
    case JobKind::Write:
        if (error == QModbusDevice::NoError) {
            continueAfterWrite(job);
        } else if (error == QModbusDevice::ProtocolError) {
            const QString meaning = device ? device->map->exceptionMeaning(exceptionCode)
                                           : tr("exception %1").arg(exceptionCode);
            QString message = tr("refused by the device: exception %1, %2").arg(exceptionCode).arg(meaning);
            if (job.entry && !job.entry->precondition.isEmpty())
                message += tr(" (precondition: %1)")
                                   .arg(QCoreApplication::translate("jumo::maps", job.entry->precondition.toUtf8().constData()));
            finishWrite(job, {WriteOutcome::Result::Refused, message, exceptionCode, {}});
        } else {
            finishWrite(job, {WriteOutcome::Result::Failed,
                              lineDown ? tr("the line was closed or lost while the write was under way: its outcome "
                                            "is unknown, read the value back")
                                       : tr("no answer: %1").arg(problem),
                              0, {}});
        }
        break;
    case JobKind::ReadBack:
        if (error == QModbusDevice::NoError)
            checkReadBack(job, words);
        else
            finishWrite(job, {WriteOutcome::Result::Failed,
                              tr("written, but the read-back failed: %1").arg(problem), exceptionCode, {}});
        break;
    }
    schedule();
}

QList<const RegisterEntry *> Bus::blockEntries(const DeviceState &d, const Job &job) const
{
    QList<const RegisterEntry *> out;
    for (const RegisterEntry &e : d.map->entries()) {
        if (e.address < job.start || e.lastAddress() > job.start + job.count - 1 || !e.isReadable())
            continue;
        // Aliases only when asked for by name: they repeat words read anyway.
        if (d.pollIds.isEmpty() ? !e.alias.isEmpty() : !d.pollIds.contains(e.id))
            continue;
        out << &e;
    }
    return out;
}

void Bus::completePoll(const Job &job, const QList<quint16> &words)
{
    if (words.size() != job.count) {   // e.g. address 0: "finished" without data
        failPoll(job, ReadError::Mismatch, 0);
        return;
    }
    DeviceState &d = m_devices[job.device];
    const qint64 t = now();
    QStringList updated;
    for (const RegisterEntry *entry : blockEntries(d, job)) {
        const RegisterEntry &e = *entry;
        EntryState &s = d.values[e.id];
        const auto first = words.cbegin() + (e.address - job.start);
        s.words = QList<quint16>(first, first + e.wordCount());
        s.value = ValueCodec::decode(e, *d.map, s.words);
        s.error = ReadError::None;
        s.exceptionCode = 0;
        s.updatedMs = t;
        s.goodMs = t;
        updated << e.id;
    }
    markSuccess(job.device, d);
    emit entriesUpdated(job.device, updated);
    if (d.blockIndex < 0)
        return;
    if (++d.blockIndex >= d.plan.blocks.size())
        finishCycle(job.device, d, t);
}

void Bus::failPoll(const Job &job, ReadError error, int exceptionCode)
{
    DeviceState &d = m_devices[job.device];
    const qint64 t = now();
    QStringList updated;
    for (const RegisterEntry *e : blockEntries(d, job)) {
        EntryState &s = d.values[e->id];
        s.error = error;   // the last good value stays, marked as no longer current
        s.exceptionCode = exceptionCode;
        s.updatedMs = t;
        updated << e->id;
    }
    emit entriesUpdated(job.device, updated);
    if (error == ReadError::Exception) {
        markSuccess(job.device, d);   // it answered: it is there
    } else {
        markFailure(job.device, d);
        if (!d.online) {
            if (d.blockIndex >= 0)
                finishCycle(job.device, d, t);
            d.nextDueMs = t + d.backoffMs;
            return;
        }
    }
    if (d.blockIndex < 0)
        return;
    if (++d.blockIndex >= d.plan.blocks.size())
        finishCycle(job.device, d, t);
}

void Bus::finishCycle(DeviceId id, DeviceState &d, qint64 now)
{
    const double cycleMs = double(now - d.cycleStartMs);
    d.blockIndex = -1;
    d.cycleRequested = false;
    ++d.stats.cycles;
    d.stats.lastCycleMs = cycleMs;
    if (d.online) {
        qint64 next = d.cycleStartMs + d.intervalMs;
        // IPC 300 and TYA 200 raise a bus error after 10 s without a telegram: never
        // leave one of them alone for more than half of that.
        if (d.map->protocol.busErrorTimeoutMs)
            next = std::min<qint64>(next, now + *d.map->protocol.busErrorTimeoutMs / 2);
        d.nextDueMs = std::max(next, now);
    }
    emit pollCycleFinished(id, cycleMs);
}

void Bus::markFailure(DeviceId id, DeviceState &d)
{
    ++d.consecutiveFailures;
    if (d.online && d.consecutiveFailures >= failuresBeforeOffline) {
        d.online = false;
        d.backoffMs = firstBackoffMs;
        qCInfo(lcBus) << "device" << d.address << "offline";
        emit onlineChanged(id, false);
    } else if (!d.online) {
        d.backoffMs = std::min(maximumBackoffMs, d.backoffMs * 2);
    }
}

void Bus::markSuccess(DeviceId id, DeviceState &d)
{
    d.consecutiveFailures = 0;
    if (!d.online) {
        d.online = true;
        d.backoffMs = 0;
        qCInfo(lcBus) << "device" << d.address << "online";
        emit onlineChanged(id, true);
    }
}

void Bus::continueAfterWrite(const Job &job)
{
    if (job.broadcast) {
        // Nobody answers a broadcast: read it back from every known device of the family.
        // Qt waits its turnaround delay (100 ms) before the next request.
        Job readBack = job;
        readBack.kind = JobKind::ReadBack;
        readBack.attempts = 0;
        if (readBack.readBackDevices.isEmpty() || !job.entry->isReadable() || job.entry->isCommand()) {
            finishWrite(job, {WriteOutcome::Result::Accepted, tr("broadcast sent; it cannot be read back"), 0, {}});
            return;
        }
        readBack.device = readBack.readBackDevices.takeFirst();
        readBack.slave = m_devices.value(readBack.device).address;
        m_writeQueue.prepend(readBack);
        return;
    }
    const bool command = job.entry->isCommand() || job.entry->activationMask.has_value();
    if (!job.verify || !job.entry->isReadable() || command) {
        finishWrite(job, {WriteOutcome::Result::Accepted,
                          job.entry->isReadable() && !command ? tr("written (not read back)")
                                                              : tr("acknowledged by the device; it cannot be read back"),
                          0, {}});
        return;
    }
    Job readBack = job;
    readBack.kind = JobKind::ReadBack;
    readBack.attempts = 0;
    m_writeQueue.prepend(readBack);
}

void Bus::checkReadBack(const Job &job, const QList<quint16> &words)
{
    const auto map = m_devices.contains(job.device) ? m_devices[job.device].map : nullptr;
    WriteOutcome outcome;
    if (map)
        outcome.readBack = ValueCodec::decode(*job.entry, *map, words);
    if (words == job.words) {
        outcome.result = WriteOutcome::Result::Confirmed;
        outcome.message = tr("confirmed by read-back: %1").arg(outcome.readBack.display);
    } else {
        outcome.result = WriteOutcome::Result::Mismatch;
        outcome.message = tr("written, but the device reads back %1").arg(outcome.readBack.display);
    }
    if (job.broadcast) {
        if (outcome.result == WriteOutcome::Result::Mismatch) {
            outcome.message = tr("broadcast not taken by the device at address %1: it reads back %2")
                                      .arg(job.slave)
                                      .arg(outcome.readBack.display);
            finishWrite(job, outcome);
            return;
        }
        if (!job.readBackDevices.isEmpty()) {
            Job next = job;
            next.device = next.readBackDevices.takeFirst();
            next.slave = m_devices.value(next.device).address;
            next.attempts = 0;
            m_writeQueue.prepend(next);
            return;
        }
        outcome.message = tr("broadcast confirmed by read-back from every device");
    }
    finishWrite(job, outcome);
}

void Bus::finishWrite(const Job &job, WriteOutcome outcome)
{
    emit writeFinished(job.ticket, outcome);
}

} // namespace jumo
