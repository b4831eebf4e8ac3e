#include "bus/writetransaction.h"

namespace jumo {

namespace {

constexpr int busyExceptionCode = 6;

} // namespace

WriteTransaction::WriteTransaction(int ticket, Lane lane, Target target, std::shared_ptr<const RegisterMap> map,
                                   const RegisterEntry &entry, Finished finished)
    : Transaction(ticket, lane, target.device), m_target(target), m_map(std::move(map)), m_entry(&entry),
      m_finished(std::move(finished))
{
}

std::unique_ptr<WriteTransaction> WriteTransaction::value(int ticket, Lane lane, Target target,
                                                          std::shared_ptr<const RegisterMap> map,
                                                          const RegisterEntry &entry, QList<quint16> words, bool verify,
                                                          Finished finished)
{
    std::unique_ptr<WriteTransaction> t(new WriteTransaction(ticket, lane, target, std::move(map), entry, std::move(finished)));
    t->m_words = std::move(words);
    t->m_verify = verify;
    return t;
}

std::unique_ptr<WriteTransaction> WriteTransaction::bits(int ticket, Lane lane, Target target,
                                                         std::shared_ptr<const RegisterMap> map, const BitWrite &change,
                                                         Finished finished)
{
    std::unique_ptr<WriteTransaction> t(
            new WriteTransaction(ticket, lane, target, std::move(map), change.entry(), std::move(finished)));
    t->m_bitWrite = change;
    t->m_reads = change.sources();
    t->m_phase = t->m_reads.isEmpty() ? Phase::Write : Phase::PreRead;
    if (t->m_phase == Phase::Write)
        t->m_words = {change.compose({})};
    return t;
}

std::unique_ptr<WriteTransaction> WriteTransaction::broadcast(int ticket, std::shared_ptr<const RegisterMap> map,
                                                              const RegisterEntry &entry, QList<quint16> words,
                                                              QList<Target> readBack, Finished finished)
{
    std::unique_ptr<WriteTransaction> t(
            new WriteTransaction(ticket, Lane::Operator, Target{-1, 0}, std::move(map), entry, std::move(finished)));
    t->m_words = std::move(words);
    t->m_broadcast = true;
    // A removed device has no address any more: never read back from address 0.
    for (const Target &r : readBack) {
        if (r.slave != 0)
            t->m_readBackTargets << r;
    }
    return t;
}

std::optional<ModbusRequest> WriteTransaction::nextRequest() const
{
    switch (m_phase) {
    case Phase::PreRead:
        return ModbusRequest::read(m_target.slave, m_reads[m_readIndex]->address, quint16(m_reads[m_readIndex]->wordCount()));
    case Phase::Write:
        return ModbusRequest::write(m_broadcast ? 0 : m_target.slave, m_entry->address, m_words);
    case Phase::ReadBack:
        if (m_broadcast)
            return ModbusRequest::read(m_readBackTargets.first().slave, m_entry->address, quint16(m_entry->wordCount()));
        if (m_bitWrite)
            return ModbusRequest::read(m_target.slave, m_reads[m_readIndex]->address,
                                       quint16(m_reads[m_readIndex]->wordCount()));
        return ModbusRequest::read(m_target.slave, m_entry->address, quint16(m_entry->wordCount()));
    case Phase::Done:
        break;
    }
    return std::nullopt;
}

bool WriteTransaction::isBusy(const ModbusResult &result) const
{
    // "Busy" means the device did not carry the request out: repeating it is safe.
    return result.status == ModbusResult::Status::Exception && result.exceptionCode == busyExceptionCode
            && m_map->exceptions.contains(busyExceptionCode);
}

QString WriteTransaction::refusal(int exceptionCode) const
{
    QString message = tr("refused by the device: exception %1, %2").arg(exceptionCode).arg(m_map->exceptionMeaning(exceptionCode));
    if (!m_entry->precondition.isEmpty())
        message += tr(" (precondition: %1)")
                           .arg(QCoreApplication::translate("jumo::maps", m_entry->precondition.toUtf8().constData()));
    return message;
}

Transaction::Next WriteTransaction::onResult(const ModbusResult &result, int maxRetries)
{
    if (m_phase == Phase::Done)
        return Next::Continue;
    ++m_attempts;
    const bool lost = result.deviceSilent();
    const bool mayRepeatRead = (lost || isBusy(result)) && m_attempts <= maxRetries;

    switch (m_phase) {
    case Phase::PreRead:
        if (result.status == ModbusResult::Status::Ok) {
            m_readWords.insert(m_reads[m_readIndex]->id, result.words);
            m_attempts = 0;
            if (++m_readIndex >= m_reads.size()) {
                m_words = {m_bitWrite->compose(m_readWords)};
                startWrite();
            }
            return Next::Continue;
        }
        if (mayRepeatRead)
            return Next::RetryAfterQuiet;
        finish(WriteOutcome::Result::NotSent,
               result.status == ModbusResult::Status::LineDown
                       ? tr("not written: the line went down before the write")
                       : tr("not written: the state of the other bits could not be read (%1)")
                                 .arg(result.status == ModbusResult::Status::Exception
                                              ? tr("exception %1, %2").arg(result.exceptionCode).arg(m_map->exceptionMeaning(result.exceptionCode))
                                              : result.errorText));
        return Next::Continue;

    case Phase::Write:
        if (result.status == ModbusResult::Status::Ok) {
            afterWrite();
            return Next::Continue;
        }
        if (isBusy(result) && m_attempts <= maxRetries)
            return Next::RetryAfterQuiet;
        if (result.status == ModbusResult::Status::Exception
            && result.exceptionCode == ModbusResult::gatewayPathUnavailable) {
            // The gateway could not pass it on: the device never saw it.
            finish(WriteOutcome::Result::Refused,
                   tr("not written: the gateway could not reach the device (exception %1, %2); nothing was changed")
                           .arg(result.exceptionCode)
                           .arg(m_map->exceptionMeaning(result.exceptionCode)),
                   result.exceptionCode);
            return Next::Continue;
        }
        if (result.status == ModbusResult::Status::Exception
            && result.exceptionCode == ModbusResult::gatewayTargetFailed) {
            // The gateway sent it and heard nothing back: the device may have taken it.
            // The gateway has waited (and perhaps repeated) already: never sent again.
            finish(WriteOutcome::Result::Unknown,
                   tr("the gateway got no answer from the device (exception %1, %2): the write may or may not "
                      "have reached it; it is not sent again, check the device")
                           .arg(result.exceptionCode)
                           .arg(m_map->exceptionMeaning(result.exceptionCode)),
                   result.exceptionCode);
            return Next::Continue;
        }
        if (result.status == ModbusResult::Status::Exception) {
            finish(WriteOutcome::Result::Refused, refusal(result.exceptionCode), result.exceptionCode);
            return Next::Continue;
        }
        if (result.status == ModbusResult::Status::LineDown) {
            finish(WriteOutcome::Result::Unknown,
                   tr("the line was lost while the write was under way: its outcome is unknown, check the device"));
            return Next::Continue;
        }
        // A lost answer: a value may be sent again; an action may have been carried out
        // already and is never repeated.
        if (!m_entry->isAction() && !m_broadcast && m_attempts <= maxRetries)
            return Next::RetryAfterQuiet;
        // An answer that does not fit (another echo) is said as such: the device did answer.
        if (result.status == ModbusResult::Status::BadReply) {
            finish(WriteOutcome::Result::Unknown,
                   m_entry->isAction()
                           ? tr("an answer that does not fit the command (%1): it may or may not have been carried "
                                "out; it is not sent again, check the device")
                                     .arg(result.errorText)
                           : tr("no fitting answer after %n attempt(s) (the last: %1): the device may or may not have "
                                "taken the value, read it back",
                                nullptr, m_attempts)
                                     .arg(result.errorText));
            return Next::Continue;
        }
        finish(WriteOutcome::Result::Unknown,
               m_entry->isAction()
                       ? tr("no answer: the command may or may not have been carried out; it is not sent again, "
                            "check the device")
                       : tr("no answer after %n attempt(s): the device may or may not have taken the value, read it back",
                            nullptr, m_attempts));
        return Next::Continue;

    case Phase::ReadBack:
        if (result.status == ModbusResult::Status::Ok) {
            checkReadBack(result);
            return Next::Continue;
        }
        if (mayRepeatRead)
            return Next::RetryAfterQuiet;
        {
            const QString why = result.status == ModbusResult::Status::Exception
                    ? tr("exception %1, %2").arg(result.exceptionCode).arg(m_map->exceptionMeaning(result.exceptionCode))
                    : result.status == ModbusResult::Status::LineDown ? tr("the line went down") : result.errorText;
            finish(WriteOutcome::Result::Unverified,
                   m_broadcast ? tr("broadcast sent, but the device at address %1 could not be read back: %2")
                                         .arg(m_readBackTargets.first().slave)
                                         .arg(why)
                               : tr("written and acknowledged, but the read-back failed: %1").arg(why),
                   result.exceptionCode);
        }
        return Next::Continue;

    case Phase::Done:
        break;
    }
    return Next::Continue;
}

void WriteTransaction::startWrite()
{
    m_phase = Phase::Write;
    m_attempts = 0;
}

void WriteTransaction::afterWrite()
{
    m_attempts = 0;
    m_readIndex = 0;
    if (m_broadcast) {
        if (m_readBackTargets.isEmpty() || !m_entry->isReadable() || m_entry->isAction()) {
            finish(WriteOutcome::Result::Accepted, tr("broadcast sent; it cannot be read back"));
            return;
        }
        m_phase = Phase::ReadBack;
        return;
    }
    if (m_bitWrite) {
        m_reads = m_bitWrite->reporters();
        m_readWords.clear();
        if (m_reads.isEmpty()) {
            finish(WriteOutcome::Result::Accepted,
                   tr("acknowledged by the device; it does not report these bits, so they cannot be read back"));
            return;
        }
        m_phase = Phase::ReadBack;
        return;
    }
    if (!m_verify || !m_entry->isReadable() || m_entry->isAction()) {
        finish(WriteOutcome::Result::Accepted,
               m_entry->isReadable() && !m_entry->isAction() ? tr("written (not read back)")
                                                             : tr("acknowledged by the device; it cannot be read back"));
        return;
    }
    m_phase = Phase::ReadBack;
}

void WriteTransaction::checkReadBack(const ModbusResult &result)
{
    m_attempts = 0;
    if (m_bitWrite) {
        m_readWords.insert(m_reads[m_readIndex]->id, result.words);
        if (++m_readIndex < m_reads.size())
            return;
        if (m_bitWrite->shows(m_readWords))
            finish(WriteOutcome::Result::Confirmed, tr("confirmed by read-back: %1").arg(m_bitWrite->describe()));
        else
            finish(WriteOutcome::Result::Mismatch,
                   tr("written, but the device does not report %1").arg(m_bitWrite->describe()));
        return;
    }
    m_readBack = ValueCodec::decode(*m_entry, *m_map, result.words);
    const bool same = result.words == m_words;
    if (!m_broadcast) {
        if (same)
            finish(WriteOutcome::Result::Confirmed, tr("confirmed by read-back: %1").arg(m_readBack.display));
        else
            finish(WriteOutcome::Result::Mismatch, tr("written, but the device reads back %1").arg(m_readBack.display));
        return;
    }
    if (!same) {
        finish(WriteOutcome::Result::Mismatch, tr("broadcast not taken by the device at address %1: it reads back %2")
                                                       .arg(m_readBackTargets.first().slave)
                                                       .arg(m_readBack.display));
        return;
    }
    m_readBackTargets.removeFirst();
    ++m_confirmedBy;
    if (m_readBackTargets.isEmpty())
        finish(WriteOutcome::Result::Confirmed, tr("broadcast confirmed by read-back from every device"));
}

void WriteTransaction::abort(const QString &reason)
{
    switch (m_phase) {
    case Phase::PreRead:
        finish(WriteOutcome::Result::NotSent, tr("not written: %1").arg(reason));
        break;
    case Phase::Write:
        // Between attempts: an earlier one went out and its answer was lost.
        if (m_attempts == 0)
            finish(WriteOutcome::Result::NotSent, tr("not written: %1").arg(reason));
        else
            finish(WriteOutcome::Result::Unknown, tr("no answer, and then %1: the outcome is unknown, check the device")
                                                          .arg(reason));
        break;
    case Phase::ReadBack:
        finish(WriteOutcome::Result::Unverified,
               tr("written and acknowledged, but not read back: %1").arg(reason));
        break;
    case Phase::Done:
        break;
    }
}

void WriteTransaction::forgetDevice(DeviceId device)
{
    if (m_phase == Phase::Done)
        return;
    if (m_broadcast) {
        const bool current = !m_readBackTargets.isEmpty() && m_readBackTargets.first().device == device;
        m_readBackTargets.removeIf([device](const Target &t) { return t.device == device; });
        if (m_phase == Phase::ReadBack && m_readBackTargets.isEmpty()) {
            if (m_confirmedBy > 0)
                finish(WriteOutcome::Result::Confirmed, tr("broadcast confirmed by read-back from every remaining device"));
            else
                finish(WriteOutcome::Result::Accepted, tr("broadcast sent; no device is left to read it back from"));
        }
        if (current)
            m_attempts = 0;
        return;
    }
    if (m_target.device == device)
        abort(tr("the device was removed from the line"));
}

void WriteTransaction::finish(WriteOutcome::Result result, const QString &message, int exceptionCode)
{
    m_phase = Phase::Done;
    setFinished();
    WriteOutcome outcome;
    outcome.result = result;
    outcome.message = message;
    outcome.exceptionCode = exceptionCode;
    outcome.readBack = m_readBack;
    if (m_finished)
        m_finished(outcome);
}

} // namespace jumo
