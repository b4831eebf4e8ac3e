#include "bus/devicescanner.h"

#include "bus/bus.h"

#include <algorithm>

namespace jumo {

namespace {

quint64 cacheKey(const IdentifyProbe &probe)
{
    return quint64(probe.address) << 16 | quint64(probe.words);
}

QString normalised(QString text)
{
    return text.remove(QLatin1Char(' ')).toUpper();
}

} // namespace

DeviceScanner::DeviceScanner(Bus &bus, QList<std::shared_ptr<const RegisterMap>> families, QObject *parent)
    : Job(parent), m_bus(bus), m_families(std::move(families))
{
    std::stable_sort(m_families.begin(), m_families.end(),
                     [](const auto &a, const auto &b) { return a->scanPriority < b->scanPriority; });
    // A silent address must not be declared while a slow family could still answer.
    for (const auto &f : std::as_const(m_families)) {
        m_slowest.processingTimeMaxMs = std::max(m_slowest.processingTimeMaxMs, f->protocol.processingTimeMaxMs);
        m_slowest.turnaroundMs = std::max(m_slowest.turnaroundMs, f->protocol.turnaroundMs);
    }
    connect(&m_bus, &Bus::probeFinished, this, &DeviceScanner::onProbeFinished);
}

void DeviceScanner::start(int firstAddress, int lastAddress)
{
    m_first = std::clamp(firstAddress, 1, 255);
    m_last = std::clamp(lastAddress, m_first, 255);
    m_address = m_first - 1;
    m_running = true;
    begin();
    nextAddress();
}

void DeviceScanner::nextAddress()
{
    if (isCancelled() || m_address >= m_last) {
        m_running = false;
        finish(isCancelled() ? Result::Cancelled : Result::Succeeded);
        return;
    }
    ++m_address;
    m_cache.clear();
    emit progress(m_address, m_address - m_first, m_last - m_first + 1);
    evaluate();
}

bool DeviceScanner::passes(const IdentifyProbe &probe, const ProbeResult &result)
{
    switch (probe.test) {
    case ProbeTest::Answers:
        return !result.timedOut && result.exceptionCode == 0;
    case ProbeTest::Exception:
        return result.exceptionCode == probe.exceptionCode;
    case ProbeTest::MaskNonZero:
        return result.exceptionCode == 0 && !result.words.isEmpty() && (result.words.first() & probe.mask);
    case ProbeTest::TextContains: {
        if (result.exceptionCode != 0 || result.words.isEmpty())
            return false;
        QByteArray bytes;
        for (quint16 w : result.words)
            bytes.append(char(w >> 8)).append(char(w & 0xFF));
        return normalised(QString::fromLatin1(bytes.left(bytes.indexOf('\0') < 0 ? bytes.size() : bytes.indexOf('\0'))))
                .contains(normalised(probe.text));
    }
    }
    return false;
}

// Walks the families in order with what is known; asks the bus for the first probe
// that is not known yet, or decides the address.
void DeviceScanner::evaluate()
{
    if (isCancelled()) {
        nextAddress();
        return;
    }
    for (const auto &family : std::as_const(m_families)) {
        bool matches = true;
        for (const IdentifyProbe &probe : family->identify) {
            const auto it = m_cache.constFind(cacheKey(probe));
            if (it == m_cache.cend()) {
                m_pendingKey = cacheKey(probe);
                m_pendingTicket = m_bus.probe(quint8(m_address), probe.address, quint16(probe.words), m_slowest);
                return;
            }
            if (it->timedOut) {
                if (m_bus.state() != LineState::Connected) {
                    // The line is gone: this is no answer about the address.
                    m_running = false;
                    finish(Result::Failed, m_bus.lastError());
                    return;
                }
                // Nothing answers at this address, or it stopped answering part way.
                if (std::any_of(m_cache.cbegin(), m_cache.cend(), [](const ProbeResult &r) { return !r.timedOut; })) {
                    emit answeredPartly(m_address);
                    emit unknownDevice(m_address);
                }
                nextAddress();
                return;
            }
            if (!passes(probe, *it)) {
                matches = false;
                break;
            }
        }
        if (matches) {
            emit found(m_address, family);
            nextAddress();
            return;
        }
    }
    emit unknownDevice(m_address);
    nextAddress();
}

void DeviceScanner::onProbeFinished(int ticket, const QList<quint16> &words, bool timedOut, int exceptionCode)
{
    if (ticket != m_pendingTicket || !m_running)
        return;
    m_pendingTicket = -1;
    m_cache.insert(m_pendingKey, ProbeResult{timedOut, exceptionCode, words});
    evaluate();
}

} // namespace jumo
