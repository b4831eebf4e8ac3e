#include "broadcastgate.h"

#include "bus/broadcastclearance.h"
#include "bus/bus.h"
#include "exitcodes.h"
#include "identitygate.h"
#include "logs/eventlog.h"
#include "protocol/familyregistry.h"

#include <QCommandLineParser>
#include <QJsonObject>

namespace jumo {

BroadcastGate::BroadcastGate(Bus &bus, const FamilyRegistry &registry, QTextStream &err, QObject *parent)
    : QObject(parent), m_bus(bus), m_registry(registry), m_err(err)
{
}

BroadcastGate::~BroadcastGate() = default;

void BroadcastGate::addOptions(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("scan-first"),
                      tr("For a broadcast: scan addresses %1..%2 first and send only if every device found is of "
                         "the family; it is read back from them unless --verify names some.")
                              .arg(BroadcastClearance::firstAddress)
                              .arg(BroadcastClearance::lastAddress)});
    parser.addOption({QStringLiteral("line-has-only"),
                      tr("For a broadcast: state that every device on the line is of this family (recorded in the "
                         "audit log)."),
                      tr("family")});
}

std::optional<int> BroadcastGate::configure(const QCommandLineParser &parser, std::shared_ptr<const RegisterMap> family,
                                            const QList<quint8> &readBack)
{
    m_family = std::move(family);
    m_readBack = readBack;
    m_scanFirst = parser.isSet(QStringLiteral("scan-first"));
    const bool acknowledged = parser.isSet(QStringLiteral("line-has-only"));
    if (acknowledged && parser.value(QStringLiteral("line-has-only")) != m_family->family) {
        m_err << tr("--line-has-only names %1, the broadcast is for %2")
                         .arg(parser.value(QStringLiteral("line-has-only")), m_family->family)
              << Qt::endl;
        return exitcode::Usage;
    }
    if (m_scanFirst == acknowledged) {
        m_err << tr("a broadcast reaches every device on the line, and the words of %1 mean something else to "
                    "other families: give --scan-first to scan the line for other devices first, or "
                    "--line-has-only %1 if you know there are none")
                         .arg(m_family->family)
              << Qt::endl;
        return exitcode::Usage;
    }
    if (!m_scanFirst && m_readBack.isEmpty()) {
        m_err << tr("a broadcast is not answered: name the devices to read it back from with --verify") << Qt::endl;
        return exitcode::Usage;
    }
    return std::nullopt;
}

void BroadcastGate::pass(IdentityGate &identity, EventLog *audit,
                         const std::function<void(const QList<quint8> &)> &next,
                         const std::function<void(int)> &refused)
{
    if (m_bus.lineKind() == LineAddress::Kind::ModbusTcp) {
        // Before any scan: the bus would refuse it anyway (gateways differ in what they
        // make of unit id 0).
        m_err << tr("no broadcast through a Modbus TCP gateway: what a gateway makes of address 0 differs from "
                    "gateway to gateway; write to each device instead")
              << Qt::endl;
        // As every other refusal of the gate: from the event loop, never inside pass().
        QMetaObject::invokeMethod(this, [refused] { refused(exitcode::Failed); }, Qt::QueuedConnection);
        return;
    }
    if (m_scanFirst) {
        scan(next, refused);
        return;
    }
    const QString device = m_family->family + QStringLiteral("@0");
    audit->append(QJsonObject{{"device", device},
                              {"entry", QString()},
                              {"result", QStringLiteral("broadcast_acknowledged")},
                              {"message", tr("the user stated that every device on the line is a %1 "
                                             "(--line-has-only %1)")
                                                  .arg(m_family->family)}});
    QList<IdentityCheck::Claim> claims;
    for (quint8 address : std::as_const(m_readBack))
        claims << IdentityCheck::Claim{address, m_family};
    const QList<quint8> readBack = m_readBack;
    identity.pass(claims, [next, readBack] { next(readBack); }, refused);
}

void BroadcastGate::scan(const std::function<void(const QList<quint8> &)> &next,
                         const std::function<void(int)> &refused)
{
    m_clearance = std::make_unique<BroadcastClearance>(m_bus, m_registry.families());
    connect(m_clearance.get(), &BroadcastClearance::progress, this, [this](int address) {
        m_err << '\r'
              << tr("scanning address %1 of %2 before the broadcast").arg(address).arg(BroadcastClearance::lastAddress)
              << Qt::flush;
    });
    connect(m_clearance.get(), &Job::finished, this, [this, next, refused] {
        m_err << '\r' << QString(60, QLatin1Char(' ')) << '\r' << Qt::flush;
        if (m_clearance->result() != Job::Result::Succeeded) {
            if (m_clearance->result() != Job::Result::Cancelled) {
                m_err << m_clearance->errorText() << Qt::endl;
                refused(exitcode::Failed);
            }
            return;
        }
        const QList<quint8> found = m_clearance->familyAddresses();
        for (quint8 address : std::as_const(m_readBack)) {
            if (!found.contains(address)) {
                m_err << tr("not broadcast: the scan found no %1 at address %2 to read it back from")
                                 .arg(m_family->family)
                                 .arg(address)
                      << Qt::endl;
                refused(exitcode::WrongDevice);
                return;
            }
        }
        if (found.isEmpty()) {
            m_err << tr("not broadcast: the scan found no %1 on the line").arg(m_family->family) << Qt::endl;
            refused(exitcode::Failed);
            return;
        }
        next(m_readBack.isEmpty() ? found : m_readBack);
    });
    m_clearance->start(m_family);
}

void BroadcastGate::cancel()
{
    if (m_clearance)
        m_clearance->cancel();
}

} // namespace jumo
