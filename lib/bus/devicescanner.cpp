#include "bus/devicescanner.h"

#include "bus/bus.h"
#include "bus/linetiming.h"

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

DeviceScanner::Mode DeviceScanner::effectiveMode(qsizetype addresses) const
{
    if (m_mode == Mode::Thorough || m_bus.lineKind() == LineAddress::Kind::ModbusTcp)
        return Mode::Thorough;
    // A short range borrows listeners from 1..247 outside it: a few, unless a long timeout
    // would make them a scan of their own.
    if (addresses >= quickPassMinimum())
        return Mode::Quick;
    const qsizetype free = 247 - addresses - m_bus.devices().size();
    return quickPassMinimum() <= std::min<qsizetype>(maxListeners, free) ? Mode::Quick : Mode::Thorough;
}

qsizetype DeviceScanner::quickPassMinimum() const
{
    // The listener after the quick pass must be an address that went quiet longer ago than
    // a late answer may take, with a fifth to spare: the probes after its own must span
    // that, each silent (an address that answers takes less).
    const qint64 quick = std::max(1, quickTimeoutMs());
    return 1 + qsizetype((qint64(heardWindowMs()) * 6 + quick * 5 - 1) / (quick * 5));
}

QList<int> DeviceScanner::listenersFor(int firstAddress, int lastAddress) const
{
    QList<int> addresses;
    for (int a = std::clamp(firstAddress, 1, 255); a <= std::clamp(lastAddress, 1, 255); ++a)
        addresses << a;
    return listenersFor(addresses);
}

QList<int> DeviceScanner::listenersFor(const QList<int> &addresses) const
{
    QList<int> listeners;
    // A range long enough has none; a short one borrows enough to listen on their own,
    // since the range's addresses may answer at once.
    const qsizetype needed = quickPassMinimum();
    if (addresses.isEmpty() || addresses.size() >= needed || effectiveMode(addresses.size()) != Mode::Quick)
        return listeners;
    QSet<int> taken(addresses.cbegin(), addresses.cend());
    for (DeviceId id : m_bus.devices())
        taken.insert(m_bus.deviceAddress(id));
    // Next to the range: above it, then below. Never 248..255, where 255 is every IPC 300's
    // and TYA 200's own address and would have them all answer at once.
    int low = 248;
    int high = 0;
    for (int a : addresses) {
        if (a <= 247) {
            low = std::min(low, a);
            high = std::max(high, a);
        }
    }
    if (high == 0)
        high = 247;   // a range of 248..255 alone borrows from 247 down
    for (int a = high + 1; a <= 247 && listeners.size() < needed; ++a) {
        if (!taken.contains(a))
            listeners << a;
    }
    for (int a = low - 1; a >= 1 && listeners.size() < needed; --a) {
        if (!taken.contains(a))
            listeners.prepend(a);
    }
    return listeners;
}

int DeviceScanner::probeWords() const
{
    int words = 1;
    for (const auto &f : std::as_const(m_families)) {
        for (const IdentifyProbe &probe : f->identify)
            words = std::max(words, probe.words);
    }
    return words;
}

int DeviceScanner::fullTimeoutMs() const
{
    return m_bus.requestTimeoutMs(m_slowest, LineTiming::readRequestBytes, LineTiming::readReplyBytes(probeWords()));
}

int DeviceScanner::quickTimeoutMs() const
{
    return m_bus.quickProbeTimeoutMs(m_slowest, LineTiming::readRequestBytes, LineTiming::readReplyBytes(probeWords()));
}

qint64 DeviceScanner::thoroughWorstMs(qsizetype addresses) const
{
    return qint64(addresses) * 4 * fullTimeoutMs();
}

qint64 DeviceScanner::remainingMs() const
{
    if (!m_running)
        return 0;
    const qint64 quickEach = m_quickDone > 0 ? m_quickCostMs / m_quickDone : quickTimeoutMs();
    const qint64 thoroughEach = m_thoroughDone > 0 ? m_thoroughCostMs / m_thoroughDone : thoroughWorstMs(1);
    const qint64 quickLeft = m_quickPass ? m_addresses.size() - m_next : 0;
    return quickLeft * quickEach + qint64(m_thorough.size()) * thoroughEach;
}

void DeviceScanner::start(int firstAddress, int lastAddress)
{
    const int first = std::clamp(firstAddress, 1, 255);
    const int last = std::clamp(lastAddress, first, 255);
    QList<int> addresses;
    for (int a = first; a <= last; ++a)
        addresses << a;
    start(addresses);
}

void DeviceScanner::start(const QList<int> &addresses)
{
    m_addresses.clear();
    for (int a : addresses) {
        if (a >= 1 && a <= 255 && !m_addresses.contains(a))
            m_addresses << a;
    }
    m_total = int(m_addresses.size());
    m_next = 0;
    m_address = 0;
    m_quickPass = effectiveMode(m_addresses.size()) == Mode::Quick;
    m_thorough.clear();
    m_queued.clear();
    if (!m_quickPass)
        m_thorough = m_addresses;
    const QList<int> listeners = listenersFor(m_addresses);
    m_listeners = QSet<int>(listeners.cbegin(), listeners.cend());
    m_addresses = listeners + m_addresses;
    m_silentAt.clear();
    m_strays = m_bus.strayReplies();
    m_straysSeenMs = m_bus.clockMs();
    m_done = 0;
    m_reprobed = 0;
    m_quickCostMs = m_thoroughCostMs = 0;
    m_quickDone = m_thoroughDone = 0;
    m_addressStartedMs = -1;
    m_running = true;
    begin();
    nextAddress();
}

void DeviceScanner::nextAddress()
{
    const qint64 now = m_bus.clockMs();
    if (m_addressStartedMs >= 0) {
        // What the address cost, with whatever the line did meanwhile: the estimate's base.
        (m_addressWasQuick ? m_quickCostMs : m_thoroughCostMs) += now - m_addressStartedMs;
        ++(m_addressWasQuick ? m_quickDone : m_thoroughDone);
    }
    if (isCancelled()) {
        m_running = false;
        finish(Result::Cancelled);
        return;
    }
    if (m_quickPass && m_next >= m_addresses.size()) {
        m_quickPass = false;
        beginThoroughPass(now);
    }
    if (!m_quickPass && m_thorough.isEmpty()) {
        m_running = false;
        finish(Result::Succeeded);
        return;
    }
    m_address = m_quickPass ? m_addresses.at(m_next++) : m_thorough.takeFirst();
    m_addressWasQuick = m_quickPass;
    m_addressStartedMs = now;
    m_cache.clear();
    if (!m_listeners.contains(m_address)) {
        emit progress(m_address, m_done, m_total);
        ++m_done;
    }
    const auto silent = m_silentAt.constFind(m_address);
    if (!m_quickPass && silent != m_silentAt.cend() && now < *silent + fullTimeoutMs()) {
        // Its answer to the quick probe may still come, and would be taken for this
        // address's next probe of another register: wait it out.
        m_bus.clock()->callAt(*silent + fullTimeoutMs(), this, [this] { evaluate(); });
        return;
    }
    evaluate();
}

void DeviceScanner::suspectRecentSilence(qint64 heardSince)
{
    // What was heard came after heardSince; an answer comes within the full timeout of its
    // request, so its request went out after heardSince - fullTimeoutMs(), and its quick
    // probe ended later still.
    QList<int> recent;
    for (auto it = m_silentAt.cbegin(); it != m_silentAt.cend(); ++it) {
        if (*it >= heardSince - heardWindowMs() && !m_queued.contains(it.key()) && !m_listeners.contains(it.key()))
            recent << it.key();
    }
    std::sort(recent.begin(), recent.end());
    for (int address : std::as_const(recent)) {
        m_queued.insert(address);
        m_thorough << address;
        ++m_reprobed;
        ++m_total;
    }
}

void DeviceScanner::beginThoroughPass(qint64 now)
{
    // A borrowed listener's own late answer needs no hearing: nothing of it is reported.
    const auto stillListening = [&] {
        for (auto it = m_silentAt.cbegin(); it != m_silentAt.cend(); ++it) {
            if (now - *it <= heardWindowMs() && !m_listeners.contains(it.key()))
                return true;
        }
        return false;
    };
    if (!stillListening())
        return;
    // Late answers to the last quick probes may still be on their way, and nothing hears
    // them while no request is out: an address that went quiet long before is probed
    // thoroughly first, and listens meanwhile.
    // A borrowed listener first, so that no address of the range is probed for it.
    int listener = -1;
    for (auto it = m_silentAt.cbegin(); it != m_silentAt.cend(); ++it) {
        const bool better = listener < 0 || m_listeners.contains(it.key()) > m_listeners.contains(listener)
                || (m_listeners.contains(it.key()) == m_listeners.contains(listener) && it.key() < listener);
        if (now - *it > heardWindowMs() && better)
            listener = it.key();
    }
    if (listener < 0) {
        suspectRecentSilence(now);
        return;
    }
    if (m_queued.contains(listener)) {
        m_thorough.removeOne(listener);
    } else {
        m_queued.insert(listener);
        if (!m_listeners.contains(listener)) {
            ++m_reprobed;
            ++m_total;
        }
    }
    m_thorough.prepend(listener);
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
    if (m_listeners.contains(m_address) && !m_cache.isEmpty()) {
        // A listener's one probe is all it is for; whatever answered there is not reported.
        if (m_cache.cbegin()->timedOut && m_bus.state() != LineState::Connected) {
            m_running = false;
            finish(Result::Failed, m_bus.lastError());
            return;
        }
        nextAddress();
        return;
    }
    for (const auto &family : std::as_const(m_families)) {
        bool matches = true;
        for (const IdentifyProbe &probe : family->identify) {
            const auto it = m_cache.constFind(cacheKey(probe));
            if (it == m_cache.cend()) {
                m_pendingKey = cacheKey(probe);
                m_pendingQuick = m_quickPass && m_cache.isEmpty() && quickFirstProbe();
                m_pendingTicket = m_pendingQuick
                        ? m_bus.quickProbe(quint8(m_address), probe.address, quint16(probe.words), m_slowest)
                        : m_bus.probe(quint8(m_address), probe.address, quint16(probe.words), m_slowest);
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
    const qint64 now = m_bus.clockMs();
    m_cache.insert(m_pendingKey, ProbeResult{timedOut, exceptionCode, words});
    if (m_pendingQuick && timedOut)
        m_silentAt.insert(m_address, now);
    const quint64 strays = m_bus.strayReplies();
    if (strays != m_strays) {
        // Somebody answered what was not asked of them (or garbled an answer) since the
        // last look: a late answer, perhaps, to a quick probe that counted as silence.
        m_strays = strays;
        suspectRecentSilence(m_straysSeenMs);
    }
    m_straysSeenMs = now;
    evaluate();
}

bool DeviceScanner::quickFirstProbe() const
{
    // A device on the bus is polled: a poll of it right after a lost quick probe could
    // take the probe's late answer for its own.
    for (DeviceId id : m_bus.devices()) {
        if (m_bus.deviceAddress(id) == m_address)
            return false;
    }
    return true;
}

} // namespace jumo
