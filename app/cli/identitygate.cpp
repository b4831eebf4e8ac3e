#include "identitygate.h"

#include "exitcodes.h"
#include "logs/eventlog.h"
#include "protocol/familyregistry.h"

#include <QCommandLineParser>
#include <QJsonObject>

namespace jumo {

IdentityGate::IdentityGate(Bus &bus, const FamilyRegistry &registry, QTextStream &err, QObject *parent)
    : QObject(parent), m_bus(bus), m_registry(registry), m_err(err)
{
}

IdentityGate::~IdentityGate() = default;

void IdentityGate::addOption(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("no-identify"),
                      tr("Trust the named family without checking the device's identity registers (for devices "
                         "whose identity cannot be read; the audit log records it).")});
}

void IdentityGate::configure(const QCommandLineParser &parser)
{
    // optionNames(): what was given; a command without the option (scan) has none of it.
    m_skipped = parser.optionNames().contains(QStringLiteral("no-identify"));
}

void IdentityGate::pass(const QList<IdentityCheck::Claim> &claims, const std::function<void()> &next,
                        const std::function<void(int)> &refused, const std::function<void()> &whenSilent)
{
    if (m_skipped) {
        for (const IdentityCheck::Claim &c : claims) {
            if (m_audit)
                m_audit->append(QJsonObject{{"device", QStringLiteral("%1@%2").arg(c.family->family).arg(c.address)},
                                            {"entry", QString()},
                                            {"result", QStringLiteral("identity_not_checked")},
                                            {"message", tr("the family was not checked against the device "
                                                           "(--no-identify)")}});
        }
        next();
        return;
    }
    m_check = std::make_unique<IdentityCheck>(m_bus, m_registry.families());
    connect(m_check.get(), &Job::finished, this, [this, next, refused, whenSilent] {
        if (m_check->result() == Job::Result::Succeeded) {
            next();
            return;
        }
        if (m_check->result() == Job::Result::Cancelled)
            return;   // whoever cancelled ends the command
        if (!m_check->foundOtherDevice() && !m_check->findings().isEmpty() && whenSilent) {
            whenSilent();
            return;
        }
        m_err << m_check->errorText() << Qt::endl;
        if (m_check->foundOtherDevice())
            m_err << tr("nothing was read or written; --no-identify skips the check for a device whose identity "
                        "registers cannot be read")
                  << Qt::endl;
        refused(m_check->foundOtherDevice() ? exitcode::WrongDevice : exitcode::Failed);
    });
    m_check->start(claims);
}

void IdentityGate::cancel()
{
    if (m_check)
        m_check->cancel();
}

} // namespace jumo
