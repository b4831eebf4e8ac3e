// One write from start to outcome: for a bit change, the words that report the other
// bits are read first and the write follows at once; then the write, repeated after a
// lost answer only when it is safe to repeat (values, never actions); then the read-back
// that confirms it. A broadcast goes out once and is read back from each known device of
// the family. The outcome is confirmed, accepted, mismatch, refused, unknown, unverified
// or not sent, never a guess.
#pragma once

#include "bus/transaction.h"
#include "bus/writeoutcome.h"
#include "protocol/bitwrite.h"

#include <QCoreApplication>
#include <QHash>

#include <functional>
#include <memory>

namespace jumo {

class WriteTransaction final : public Transaction
{
    Q_DECLARE_TR_FUNCTIONS(jumo::WriteTransaction)

public:
    struct Target
    {
        DeviceId device = -1;
        quint8 slave = 0;
    };
    using Finished = std::function<void(const WriteOutcome &)>;

    // A value already encoded for the entry, to one device.
    static std::unique_ptr<WriteTransaction> value(int ticket, Lane lane, Target target,
                                                   std::shared_ptr<const RegisterMap> map, const RegisterEntry &entry,
                                                   QList<quint16> words, bool verify, Finished finished);
    // Some bits of a bit field, the others kept as the device reports them.
    static std::unique_ptr<WriteTransaction> bits(int ticket, Lane lane, Target target,
                                                  std::shared_ptr<const RegisterMap> map, const BitWrite &change,
                                                  Finished finished);
    // A value to address 0, read back from these devices of the family.
    static std::unique_ptr<WriteTransaction> broadcast(int ticket, std::shared_ptr<const RegisterMap> map,
                                                       const RegisterEntry &entry, QList<quint16> words,
                                                       QList<Target> readBack, Finished finished);

    std::optional<ModbusRequest> nextRequest() const override;
    ProtocolInfo timing() const override { return m_map->protocol; }
    // The write follows its pre-read at once; a repeat after a lost answer comes after a
    // quiet gap anyway, and lets a keepalive go first.
    bool holdsLine() const override { return m_phase == Phase::Write && m_bitWrite.has_value() && m_attempts == 0; }
    Next onResult(const ModbusResult &result, int maxRetries) override;
    void abort(const QString &reason) override;
    void forgetDevice(DeviceId device) override;

private:
    enum class Phase { PreRead, Write, ReadBack, Done };

    WriteTransaction(int ticket, Lane lane, Target target, std::shared_ptr<const RegisterMap> map,
                     const RegisterEntry &entry, Finished finished);
    void startWrite();
    void afterWrite();
    void checkReadBack(const ModbusResult &result);
    void finish(WriteOutcome::Result result, const QString &message, int exceptionCode = 0);
    bool isBusy(const ModbusResult &result) const;
    QString refusal(int exceptionCode) const;

    Target m_target;
    std::shared_ptr<const RegisterMap> m_map;
    const RegisterEntry *m_entry;
    Finished m_finished;
    Phase m_phase = Phase::Write;
    QList<quint16> m_words;                              // to write
    bool m_verify = true;
    bool m_broadcast = false;
    std::optional<BitWrite> m_bitWrite;
    QList<const RegisterEntry *> m_reads;                // pre-reads or bit reporters, in turn
    int m_readIndex = 0;
    QHash<QString, QList<quint16>> m_readWords;          // entry id -> words
    QList<Target> m_readBackTargets;                     // broadcast read-backs still to do
    int m_confirmedBy = 0;                               // devices that read the broadcast back
    int m_attempts = 0;                                  // of the current request
    DecodedValue m_readBack;
};

} // namespace jumo
