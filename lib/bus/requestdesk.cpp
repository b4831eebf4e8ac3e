#include "bus/requestdesk.h"

#include "bus/bus.h"
#include "bus/readtransaction.h"
#include "bus/writetransaction.h"
#include "protocol/bitwrite.h"

namespace jumo {

bool RequestDesk::mayWrite(int ticket, const RegisterMap *map, const QString &entryId)
{
    if (m_bus.m_settings.readOnly) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::ReadOnlyMode, Bus::tr("read-only mode: %1 was not written").arg(entryId));
        return false;
    }
    if (!map) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::Invalid, Bus::tr("unknown device"));
        return false;
    }
    if (!map->entry(entryId)) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::Invalid, Bus::tr("'%1' is not an entry of %2").arg(entryId, map->family));
        return false;
    }
    return true;
}

bool RequestDesk::trusted(int ticket, DeviceId id)
{
    const DeviceIdentities &identities = m_bus.m_identities;
    switch (identities.state(id)) {
    case DeviceIdentities::State::Confirmed:
        return true;
    case DeviceIdentities::State::Refused:
        m_bus.refuseLater(ticket, WriteOutcome::Result::NotSent,
                          Bus::tr("not written: %1").arg(identities.reason(id)));
        return false;
    case DeviceIdentities::State::Unconfirmed:
        break;
    }
    m_bus.refuseLater(ticket, WriteOutcome::Result::NotSent,
                      Bus::tr("not written: %1 is not yet confirmed to be a %2 (its identity is checked when it answers)")
                              .arg(m_bus.deviceName(id), m_bus.deviceMap(id) ? m_bus.deviceMap(id)->family : QString()));
    return false;
}

int RequestDesk::write(DeviceId id, const QString &entryId, const QString &value, bool verify, Transaction::Lane lane)
{
    const int ticket = m_bus.nextTicket();
    const EntryState *previous = m_bus.entryState(id, entryId);
    emit m_bus.writeRequested(ticket, m_bus.deviceName(id), entryId, value,
                        previous && previous->hasValue() ? previous->value.display : QString());
    const std::shared_ptr<const RegisterMap> map = m_bus.deviceMap(id);
    if (!mayWrite(ticket, map.get(), entryId))
        return ticket;
    const RegisterEntry &entry = *map->entry(entryId);
    const EncodeResult encoded = ValueCodec::encode(entry, *map, value);
    if (!encoded.ok()) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::Invalid, encoded.error);
        return ticket;
    }
    if (!trusted(ticket, id))
        return ticket;
    if (encoded.words.size() > map->protocol.effectiveMaxWriteWords()) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::Invalid, Bus::tr("'%1' needs more words than one write may carry").arg(entryId));
        return ticket;
    }
    if (m_bus.state() != LineState::Connected) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::NotSent, Bus::tr("not written: the line is not connected"));
        return ticket;
    }
    m_bus.m_scheduler.enqueue(WriteTransaction::value(ticket, lane, {id, m_bus.deviceAddress(id)}, map, entry, encoded.words, verify,
                                                [this, ticket](const WriteOutcome &o) { m_bus.finishLater(ticket, o); }));
    m_bus.schedule(m_bus.now());
    return ticket;
}

int RequestDesk::writeBits(DeviceId id, const QString &entryId, const QHash<QString, bool> &bits, Transaction::Lane lane)
{
    const int ticket = m_bus.nextTicket();
    const std::shared_ptr<const RegisterMap> map = m_bus.deviceMap(id);
    QStringList asked;
    for (auto it = bits.cbegin(); it != bits.cend(); ++it)
        asked << QStringLiteral("%1.%2=%3").arg(entryId, it.key()).arg(*it ? 1 : 0);
    asked.sort();
    const EntryState *previous = m_bus.entryState(id, entryId);
    emit m_bus.writeRequested(ticket, m_bus.deviceName(id), entryId, asked.join(QLatin1Char(' ')),
                        previous && previous->hasValue() ? previous->value.display : QString());
    if (!mayWrite(ticket, map.get(), entryId))
        return ticket;
    QString error;
    const std::optional<BitWrite> change = BitWrite::make(*map, *map->entry(entryId), bits, &error);
    if (!change) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::Invalid, error);
        return ticket;
    }
    if (!trusted(ticket, id))
        return ticket;
    if (m_bus.state() != LineState::Connected) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::NotSent, Bus::tr("not written: the line is not connected"));
        return ticket;
    }
    m_bus.m_scheduler.enqueue(WriteTransaction::bits(ticket, lane, {id, m_bus.deviceAddress(id)}, map, *change,
                                               [this, ticket](const WriteOutcome &o) { m_bus.finishLater(ticket, o); }));
    m_bus.schedule(m_bus.now());
    return ticket;
}

int RequestDesk::writeBroadcast(const QString &family, const QString &entryId, const QString &value)
{
    const int ticket = m_bus.nextTicket();
    emit m_bus.writeRequested(ticket, QStringLiteral("%1@0").arg(family), entryId, value, QString());
    std::shared_ptr<const RegisterMap> map;
    QList<WriteTransaction::Target> targets;
    for (DeviceId id : m_bus.m_scheduler.devices()) {
        const Scheduler::DeviceInfo *d = m_bus.m_scheduler.device(id);
        if (d->map->family == family) {
            map = d->map;
            targets << WriteTransaction::Target{id, d->address};
        }
    }
    if (m_bus.m_settings.readOnly) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::ReadOnlyMode, Bus::tr("read-only mode: %1 was not written").arg(entryId));
        return ticket;
    }
    if (m_bus.lineKind() == LineAddress::Kind::ModbusTcp) {
        // Gateways differ in what they make of unit id 0: some pass it on as a broadcast,
        // some answer it themselves, some drop it or wait for a reply that never comes.
        // Nothing tells which one this is, so no broadcast goes out through one.
        m_bus.refuseLater(ticket, WriteOutcome::Result::Invalid,
                          Bus::tr("not broadcast: a Modbus TCP gateway's handling of address 0 differs from "
                                  "gateway to gateway; write to each device instead"));
        return ticket;
    }
    for (DeviceId id : m_bus.m_scheduler.devices()) {
        const Scheduler::DeviceInfo *d = m_bus.m_scheduler.device(id);
        if (d->map->family != family) {
            // Address 0 reaches every device: the same address means something else to
            // another family (a command word, perhaps).
            m_bus.refuseLater(ticket, WriteOutcome::Result::Invalid,
                        Bus::tr("not broadcast: the line also has a %1 device at address %2, which would take the same "
                           "words as something else")
                                .arg(d->map->family)
                                .arg(d->address));
            return ticket;
        }
    }
    for (const WriteTransaction::Target &target : std::as_const(targets)) {
        if (!m_bus.m_identities.isTrusted(target.device)) {
            m_bus.refuseLater(ticket, WriteOutcome::Result::NotSent,
                              Bus::tr("not broadcast: %1 is not confirmed to be a %2")
                                      .arg(m_bus.deviceName(target.device), family));
            return ticket;
        }
    }
    if (!map || !map->protocol.broadcast) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::Invalid,
                    Bus::tr("no %1 device on this line to read a broadcast back from").arg(family));
        return ticket;
    }
    if (!mayWrite(ticket, map.get(), entryId))
        return ticket;
    const RegisterEntry &entry = *map->entry(entryId);
    const EncodeResult encoded = ValueCodec::encode(entry, *map, value);
    if (!encoded.ok()) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::Invalid, encoded.error);
        return ticket;
    }
    if (m_bus.state() != LineState::Connected) {
        m_bus.refuseLater(ticket, WriteOutcome::Result::NotSent, Bus::tr("not written: the line is not connected"));
        return ticket;
    }
    m_bus.m_scheduler.enqueue(WriteTransaction::broadcast(ticket, map, entry, encoded.words, targets,
                                                    [this, ticket](const WriteOutcome &o) { m_bus.finishLater(ticket, o); }));
    m_bus.schedule(m_bus.now());
    return ticket;
}

QString RequestDesk::setHold(DeviceId id, const QString &entryId, const QString &value, int intervalMs)
{
    if (m_bus.m_settings.readOnly)
        return Bus::tr("read-only mode: nothing is written");
    const std::shared_ptr<const RegisterMap> map = m_bus.deviceMap(id);
    if (!map)
        return Bus::tr("unknown device");
    if (value.isEmpty()) {
        m_bus.m_scheduler.clearHold(id, entryId);
        return {};
    }
    const RegisterEntry *entry = map->entry(entryId);
    if (!entry)
        return Bus::tr("'%1' is not an entry of %2").arg(entryId, map->family);
    if (entry->storage == Storage::Eeprom)
        return Bus::tr("'%1' is stored in EEPROM, which wears out after about 10,000 writes: it is never rewritten "
                  "cyclically").arg(entryId);
    if (entry->storage != Storage::Ram || entry->isAction())
        return Bus::tr("only RAM values can be held, '%1' is not one").arg(entryId);
    const EncodeResult encoded = ValueCodec::encode(*entry, *map, value);
    if (!encoded.ok())
        return encoded.error;
    if (!m_bus.m_identities.isTrusted(id))
        return Bus::tr("not held: %1 is not confirmed to be a %2").arg(m_bus.deviceName(id), map->family);
    m_bus.m_scheduler.setHold(id, entryId, encoded.words, intervalMs);
    m_bus.schedule(m_bus.now());
    return {};
}

int RequestDesk::probe(quint8 slave, quint16 address, quint16 count, const ProtocolInfo &timing, bool quick)
{
    const int ticket = m_bus.nextTicket();
    auto report = [this, ticket](const ModbusResult &r) {
        m_bus.m_clock->callSoon(&m_bus, [this, ticket, r] {
            emit m_bus.probeFinished(ticket, r.words, !r.answered(), r.answered() && r.status == ModbusResult::Status::Exception ? r.exceptionCode : 0);
        });
    };
    if (m_bus.state() != LineState::Connected) {
        report(ModbusResult{});
        return ticket;
    }
    // Repeated once: a single lost reply must not hide a device. A quick probe is not: a
    // late answer is heard, and the scan probes that address again at the full timeout.
    auto read = std::make_unique<ReadTransaction>(ticket, Transaction::Lane::Job, -1,
                                                  ModbusRequest::read(slave, address, count), timing, 2, report);
    if (quick)
        read->setQuickProbe();
    m_bus.m_scheduler.enqueue(std::move(read));
    m_bus.schedule(m_bus.now());
    return ticket;
}

int RequestDesk::readEntries(DeviceId id, const QStringList &entryIds)
{
    const int ticket = m_bus.nextTicket();
    const std::shared_ptr<const RegisterMap> map = m_bus.deviceMap(id);
    struct Progress
    {
        int remaining = 0;
        QStringList failed;
    };
    auto progress = std::make_shared<Progress>();
    auto done = [this, ticket, progress] {
        m_bus.m_clock->callSoon(&m_bus, [this, ticket, progress] { emit m_bus.entriesRead(ticket, progress->failed); });
    };
    if (!map || m_bus.state() != LineState::Connected) {
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
            const qint64 t = m_bus.now();
            QStringList changed;
            if (r.status == ModbusResult::Status::Ok) {
                changed = m_bus.m_store.store(id, block.entries, block.start, r.words, t);
            } else {
                const ReadError error = r.status == ModbusResult::Status::Exception ? ReadError::Exception
                        : r.status == ModbusResult::Status::LineDown               ? ReadError::LineLost
                                                                                    : ReadError::Timeout;
                changed = m_bus.m_store.fail(id, block.entries, error, r.exceptionCode, t);
                for (const RegisterEntry *e : block.entries)
                    progress->failed << e->id;
            }
            if (!changed.isEmpty())
                emit m_bus.entriesUpdated(id, changed);
            if (--progress->remaining == 0)
                done();
        };
        m_bus.m_scheduler.enqueue(std::make_unique<ReadTransaction>(ticket, Transaction::Lane::Job, id,
                                                              ModbusRequest::read(m_bus.deviceAddress(id), block.start, block.count),
                                                              map->protocol, m_bus.m_settings.retries + 1, finished));
    }
    m_bus.schedule(m_bus.now());
    return ticket;
}

} // namespace jumo
