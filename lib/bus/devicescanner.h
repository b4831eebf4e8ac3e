// Finds devices on a line and names their family, with each family's identify probes
// from its map. Probe answers are shared between families, so an address costs one
// request per distinct probe.
//
// A thorough scan gives a silent address the full timeout (the slowest family's worst
// case) twice, each followed by as long a quiet time: about 1.5 s at 38400 baud. A quick
// scan probes every address once at a short timeout (a device given quickAnswerMs) with
// no quiet time, and listens meanwhile: a late answer carries its own address, so it is
// never taken for the next probe's (which goes elsewhere) but heard as a stray reply. Where
// anything was heard (a stray reply, a bad CRC, a reply that fits nothing) the addresses
// probed within the time a late answer could take are probed again thoroughly, after one
// thorough probe of an address probed long before, which listens for the last ones.
//
// A range too short to have such an address gets listeners: neighbouring addresses
// (1..247, none of a device on the bus) probed once each before it, whose only job is to
// have a request out while late answers may come. What answers there is not reported.
#pragma once

#include "bus/job.h"
#include "protocol/registermap.h"

#include <QHash>
#include <QSet>

#include <memory>

namespace jumo {

class Bus;

class DeviceScanner : public Job
{
    Q_OBJECT

public:
    enum class Mode { Thorough, Quick };

    DeviceScanner(Bus &bus, QList<std::shared_ptr<const RegisterMap>> families, QObject *parent = nullptr);

    // Thorough unless set (identity checks and broadcast clearances stay so); before start().
    void setMode(Mode mode) { m_mode = mode; }
    Mode mode() const { return m_mode; }
    // What a scan of these addresses on this line does: Quick is thorough over a Modbus TCP
    // gateway (which answers every request itself, at its own timeout), and on a range too
    // short to listen after its quick pass where a long timeout would need more than a few
    // listeners.
    Mode effectiveMode(int firstAddress, int lastAddress) const { return effectiveMode(lastAddress - firstAddress + 1); }
    Mode effectiveMode(qsizetype addresses) const;
    // The listeners a quick scan of these addresses probes first (none for a range long
    // enough, or a thorough scan), in the order probed.
    QList<int> listenersFor(int firstAddress, int lastAddress) const;
    QList<int> listenersFor(const QList<int> &addresses) const;
    // A silent address's probe: at the full timeout, and at a quick scan's.
    int fullTimeoutMs() const;
    int quickTimeoutMs() const;
    // What a thorough scan of these addresses costs at most: each silent address two
    // probes at the full timeout, each followed by as long a quiet time.
    qint64 thoroughWorstMs(int firstAddress, int lastAddress) const { return thoroughWorstMs(lastAddress - firstAddress + 1); }
    qint64 thoroughWorstMs(qsizetype addresses) const;
    // About how long the rest of the scan takes, from what it cost so far.
    qint64 remainingMs() const;
    // Addresses a quick scan probed again thoroughly because something was heard.
    int reprobed() const { return m_reprobed; }

    // Probes the addresses in the job lane of the bus: devices being monitored keep their
    // polls and keepalives meanwhile. Ends Succeeded, Cancelled, or Failed when the line
    // went away.
    void start(int firstAddress, int lastAddress);
    // The same for these addresses (1..255), in this order.
    void start(const QList<int> &addresses);

signals:
    void progress(int address, int done, int total);
    void found(int address, std::shared_ptr<const jumo::RegisterMap> family);
    // An address answered but matched no family.
    void unknownDevice(int address);
    // Just before unknownDevice: the address answered some probes, then no more, so
    // whether another family would have matched is not known.
    void answeredPartly(int address);

private:
    struct ProbeResult
    {
        bool timedOut = false;
        int exceptionCode = 0;
        QList<quint16> words;
    };

    void nextAddress();
    void evaluate();
    void onProbeFinished(int ticket, const QList<quint16> &words, bool timedOut, int exceptionCode);
    static bool passes(const IdentifyProbe &probe, const ProbeResult &result);
    // The addresses that stayed silent in the quick pass recently enough that what was
    // heard after heardSince may have been their late answer: probed again thoroughly.
    void suspectRecentSilence(qint64 heardSince);
    // After the quick pass: the thorough probes, the listener first.
    void beginThoroughPass(qint64 now);
    // More would be a scan of their own: a short range is then probed thoroughly.
    static constexpr qsizetype maxListeners = 16;
    // A device answers within the full timeout of its request, or not at all.
    int heardWindowMs() const { return fullTimeoutMs(); }
    // How many silent addresses a quick pass needs for its first one to have gone quiet
    // long enough to listen after it; also how many listeners a shorter range borrows.
    qsizetype quickPassMinimum() const;
    bool quickFirstProbe() const;
    int probeWords() const;

    Bus &m_bus;
    QList<std::shared_ptr<const RegisterMap>> m_families;   // in scan order
    ProtocolInfo m_slowest;                                   // timing that fits every family
    QHash<quint64, ProbeResult> m_cache;                      // (register, words) -> answer
    QList<int> m_addresses;   // of the quick pass, in order, the listeners first
    QSet<int> m_listeners;    // probed once, to hear late answers; never reported
    int m_next = 0;           // quick pass: index of the next address
    int m_address = 0;        // probed now
    int m_pendingTicket = -1;
    quint64 m_pendingKey = 0;
    bool m_pendingQuick = false;
    bool m_running = false;

    Mode m_mode = Mode::Thorough;
    bool m_quickPass = false;                 // in the quick pass of a quick scan
    QList<int> m_thorough;                    // addresses left to probe thoroughly
    QSet<int> m_queued;                       // quick pass: addresses put into m_thorough
    QHash<int, qint64> m_silentAt;            // quick pass: silent address -> when it ended
    quint64 m_strays = 0;                     // the bus's stray replies when last looked
    qint64 m_straysSeenMs = 0;                // and when
    int m_done = 0;
    int m_total = 0;
    int m_reprobed = 0;
    qint64 m_quickCostMs = 0;                 // line time the addresses of each pass took
    qint64 m_thoroughCostMs = 0;
    int m_quickDone = 0;
    int m_thoroughDone = 0;
    qint64 m_addressStartedMs = -1;
    bool m_addressWasQuick = false;
};

} // namespace jumo
