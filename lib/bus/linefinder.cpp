#include "bus/linefinder.h"

#include "bus/bus.h"
#include "bus/devicescanner.h"
#include "bus/linetiming.h"

#include <algorithm>

namespace jumo {

namespace {

// The factory default of every family first, then the other rates in the manuals' order.
int baudRank(int baud)
{
    const QList<int> order{9600, 19200, 38400, 4800};
    const qsizetype i = order.indexOf(baud);
    return i < 0 ? int(order.size()) + baud : int(i);
}

int formatRank(const QString &format)
{
    const QStringList order{QStringLiteral("8N1"), QStringLiteral("8E1"), QStringLiteral("8O1"), QStringLiteral("8N2")};
    const qsizetype i = order.indexOf(format);
    return i < 0 ? int(order.size()) : int(i);
}

} // namespace

bool LineFinder::Setting::alwaysAnswered() const
{
    return std::any_of(families.cbegin(), families.cend(),
                       [](const auto &f) { return f->protocol.alwaysAnswersAddress.has_value(); });
}

LineFinder::LineFinder(Bus &bus, QList<std::shared_ptr<const RegisterMap>> families, QObject *parent)
    : Job(parent), m_bus(bus), m_own(bus.settings()), m_families(std::move(families))
{
    restrict({}, {});
}

LineFinder::~LineFinder() = default;

void LineFinder::restrict(const QList<int> &baudRates, const QStringList &formats)
{
    QList<int> bauds;
    QStringList names;
    for (const auto &family : std::as_const(m_families)) {
        for (int baud : family->protocol.baudRates) {
            if (!bauds.contains(baud) && (baudRates.isEmpty() || baudRates.contains(baud)))
                bauds << baud;
        }
        for (const QString &name : family->protocol.dataFormats) {
            if (!names.contains(name) && (formats.isEmpty() || formats.contains(name)))
                names << name;
        }
    }
    std::sort(bauds.begin(), bauds.end(), [](int a, int b) { return baudRank(a) < baudRank(b); });
    std::sort(names.begin(), names.end(), [](const QString &a, const QString &b) { return formatRank(a) < formatRank(b); });
    m_settings.clear();
    for (int baud : std::as_const(bauds)) {
        for (const QString &name : std::as_const(names)) {
            const std::optional<LineFormat> format = LineFormat::parse(baud, name);
            if (!format)
                continue;
            Setting setting{*format, {}};
            for (const auto &family : std::as_const(m_families)) {
                if (family->protocol.supports(baud, name))
                    setting.families << family;
            }
            if (!setting.families.isEmpty())
                m_settings << setting;
        }
    }
}

QList<int> LineFinder::addressesOf(const Setting &setting, int firstAddress, int lastAddress)
{
    QList<int> addresses;
    // Where a device answers whatever its own address: a device of such a family is on the
    // line at this setting even when its own address is outside the range.
    for (const auto &family : setting.families) {
        const std::optional<int> always = family->protocol.alwaysAnswersAddress;
        if (always && !addresses.contains(*always))
            addresses << *always;
    }
    for (int a = std::clamp(firstAddress, 1, 255); a <= std::clamp(lastAddress, 1, 255); ++a) {
        if (!addresses.contains(a))
            addresses << a;
    }
    return addresses;
}

qint64 LineFinder::plannedMs(int firstAddress, int lastAddress)
{
    if (isRunning())
        return m_plannedMs;
    qint64 total = 0;
    m_plannedListeners = 0;
    for (const Setting &setting : std::as_const(m_settings)) {
        BusSettings at = m_own;
        at.format = setting.format;
        m_bus.setSettings(at);
        DeviceScanner scanner(m_bus, m_families);
        scanner.setMode(DeviceScanner::Mode::Quick);   // as nextScan() has it
        const QList<int> addresses = addressesOf(setting, firstAddress, lastAddress);
        // Hint (waited out to the full timeout), then the quick pass (with the listeners a
        // short range borrows) and the listener after it (a thorough probe of one address).
        total += setting.alwaysAnswered() ? scanner.fullTimeoutMs() : 0;
        const qsizetype listeners = scanner.listenersFor(addresses).size();
        m_plannedListeners = std::max(m_plannedListeners, listeners);
        const qsizetype quickPass = addresses.size() + listeners;
        total += scanner.effectiveMode(addresses.size()) == DeviceScanner::Mode::Quick
                ? qint64(quickPass) * scanner.quickTimeoutMs() + scanner.thoroughWorstMs(1)
                : scanner.thoroughWorstMs(addresses.size());
    }
    m_bus.setSettings(m_own);
    return total;
}

qint64 LineFinder::remainingMs() const
{
    if (!isRunning())
        return 0;
    const qint64 spent = m_bus.clockMs() - m_startedMs;
    return std::max<qint64>(0, m_plannedMs - spent);
}

qint64 LineFinder::elapsedMs() const
{
    return (m_endedMs >= 0 ? m_endedMs : m_bus.clockMs()) - m_startedMs;
}

void LineFinder::start(int firstAddress, int lastAddress)
{
    m_endedMs = -1;
    m_first = firstAddress;
    m_last = lastAddress;
    m_own = m_bus.settings();
    m_plannedMs = plannedMs(firstAddress, lastAddress);
    m_findings.clear();
    m_heard = QList<bool>(m_settings.size(), false);
    m_order.clear();
    m_index = -1;
    m_hintPass = true;
    m_startedMs = m_bus.clockMs();
    connect(&m_bus, &Bus::probeFinished, this, &LineFinder::onHintFinished, Qt::UniqueConnection);
    begin();
    nextHint();
}

bool LineFinder::openAt(const LineFormat &format)
{
    m_bus.close();
    BusSettings at = m_own;
    at.format = format;
    m_bus.setSettings(at);
    if (m_bus.open())
        return true;
    end(Result::Failed, m_bus.lastError());
    return false;
}

void LineFinder::nextHint()
{
    if (isCancelled()) {
        end(Result::Cancelled);
        return;
    }
    while (++m_index < m_settings.size()) {
        const Setting &setting = m_settings.at(m_index);
        if (!setting.alwaysAnswered())
            continue;
        // The family's first identify probe, asked at its always-answered address.
        for (const auto &family : setting.families) {
            if (!family->protocol.alwaysAnswersAddress || family->identify.isEmpty())
                continue;
            const auto hints = std::count_if(m_settings.cbegin(), m_settings.cend(),
                                             [](const Setting &s) { return s.alwaysAnswered(); });
            const auto step = std::count_if(m_settings.cbegin(), m_settings.cbegin() + m_index,
                                            [](const Setting &s) { return s.alwaysAnswered(); });
            emit trying(setting.format, int(step), int(hints), true);
            if (!openAt(setting.format))
                return;
            m_strays = m_bus.strayReplies();
            const IdentifyProbe &probe = family->identify.constFirst();
            // A late answer may come until the full timeout: it is waited for at this
            // setting, where it is heard, never read at the next (whose probe asks the same).
            // (The slowest family's time: a device may be set to answer later than its own.)
            int quietMs = 0;
            for (const auto &f : std::as_const(m_families))
                quietMs = std::max(quietMs, m_bus.requestTimeoutMs(f->protocol, LineTiming::readRequestBytes,
                                                                  LineTiming::readReplyBytes(probe.words)));
            m_hintQuietUntilMs = m_bus.clockMs() + quietMs;
            m_hintTicket = m_bus.quickProbe(quint8(*family->protocol.alwaysAnswersAddress), probe.address,
                                            quint16(probe.words), family->protocol);
            return;
        }
    }
    // The settings where anything was heard first, each group in the order tried.
    m_hintPass = false;
    for (int pass = 0; pass < 2; ++pass) {
        for (int i = 0; i < m_settings.size(); ++i) {
            if (m_heard.at(i) == (pass == 0))
                m_order << i;
        }
    }
    m_index = -1;
    nextScan();
}

void LineFinder::onHintFinished(int ticket, const QList<quint16> &, bool timedOut, int)
{
    if (ticket != m_hintTicket || !m_hintPass)
        return;
    m_hintTicket = -1;
    if (!timedOut || m_bus.strayReplies() != m_strays)
        m_heard[m_index] = true;
    if (m_bus.state() != LineState::Connected) {
        end(Result::Failed, m_bus.lastError());
        return;
    }
    if (!timedOut || m_bus.clockMs() >= m_hintQuietUntilMs) {
        nextHint();
        return;
    }
    m_bus.clock()->callAt(m_hintQuietUntilMs, this, [this] {
        if (m_bus.strayReplies() != m_strays)
            m_heard[m_index] = true;   // it answered late: scanned early
        nextHint();
    });
}

void LineFinder::nextScan()
{
    if (isCancelled()) {
        end(Result::Cancelled);
        return;
    }
    if (++m_index >= m_order.size()) {
        end(Result::Succeeded);
        return;
    }
    const Setting &setting = m_settings.at(m_order.at(m_index));
    emit trying(setting.format, m_index, int(m_order.size()), false);
    if (!openAt(setting.format))
        return;
    // Every family is asked: a device set to this setting is of one that supports it, but
    // one that answers here because its UART or the adapter takes this setting for its own
    // is named all the same, not called unknown.
    m_scanner = std::make_unique<DeviceScanner>(m_bus, m_families);
    m_scanner->setMode(DeviceScanner::Mode::Quick);
    const LineFormat format = setting.format;
    connect(m_scanner.get(), &DeviceScanner::progress, this, &LineFinder::probing);
    connect(m_scanner.get(), &DeviceScanner::found, this, [this, format](int address, std::shared_ptr<const RegisterMap> map) {
        Finding finding{format, address, map, address == map->protocol.alwaysAnswersAddress};
        m_findings << finding;
        emit found(finding);
    });
    connect(m_scanner.get(), &DeviceScanner::unknownDevice, this, [this, format](int address) {
        Finding finding{format, address, nullptr, false};
        m_findings << finding;
        emit found(finding);
    });
    connect(m_scanner.get(), &Job::finished, this, &LineFinder::scanFinished);
    m_scanner->start(addressesOf(setting, m_first, m_last));
}

void LineFinder::scanFinished()
{
    const Result result = m_scanner->result();
    const QString error = m_scanner->errorText();
    m_scanner.release()->deleteLater();   // its finished() is being delivered
    if (result == Result::Failed) {
        end(Result::Failed, error);
        return;
    }
    nextScan();
}

void LineFinder::onCancel()
{
    if (m_scanner)
        m_scanner->cancel();
}

void LineFinder::end(Result result, const QString &error)
{
    m_endedMs = m_bus.clockMs();
    m_bus.close();
    m_bus.setSettings(m_own);
    finish(result, error);
}

std::optional<LineFormat> LineFinder::bestSetting() const
{
    std::optional<LineFormat> best;
    int bestCount = 0;
    for (const Setting &setting : std::as_const(m_settings)) {
        const auto count = std::count_if(m_findings.cbegin(), m_findings.cend(), [&](const Finding &f) {
            return f.format == setting.format && f.family && !f.alwaysAnswered;
        });
        const auto always = std::count_if(m_findings.cbegin(), m_findings.cend(), [&](const Finding &f) {
            return f.format == setting.format;
        });
        // Devices with their own address weigh more than an answer at 255 alone.
        const int score = int(count) * 2 + int(always - count);
        if (score > bestCount) {
            bestCount = score;
            best = setting.format;
        }
    }
    return best;
}

QList<LineFinder::Finding> LineFinder::ownAddressNotFound() const
{
    QList<Finding> out;
    for (const Finding &f : std::as_const(m_findings)) {
        if (!f.alwaysAnswered)
            continue;
        const bool own = std::any_of(m_findings.cbegin(), m_findings.cend(), [&](const Finding &g) {
            return !g.alwaysAnswered && g.family == f.family && g.format == f.format;
        });
        if (!own)
            out << f;
    }
    return out;
}

bool LineFinder::scannedEveryAddressOf(const RegisterMap &family) const
{
    const std::optional<int> always = family.protocol.alwaysAnswersAddress;
    for (int a = family.protocol.addressMin; a <= family.protocol.addressMax; ++a) {
        if (a != always && (a < m_first || a > m_last))
            return false;
    }
    return true;
}

QList<LineFinder::SeveralFormats> LineFinder::answeredAtSeveralFormats() const
{
    QList<SeveralFormats> out;
    for (const Finding &f : std::as_const(m_findings)) {
        if (f.alwaysAnswered || !f.family)
            continue;
        const bool listed = std::any_of(out.cbegin(), out.cend(), [&](const SeveralFormats &s) {
            return s.family == f.family && s.address == f.address && s.baudRate == f.format.baudRate;
        });
        if (listed)
            continue;
        SeveralFormats several{f.family, f.address, f.format.baudRate, {}};
        for (const Finding &g : std::as_const(m_findings)) {
            if (!g.alwaysAnswered && g.family == f.family && g.address == f.address && g.format.baudRate == f.format.baudRate
                && !several.formats.contains(g.format.formatName()))
                several.formats << g.format.formatName();
        }
        if (several.formats.size() > 1)
            out << several;
    }
    return out;
}

} // namespace jumo
