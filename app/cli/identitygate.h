// What a line command passes before it trusts the family it was given: the identity
// check of the devices it names, or, with --no-identify, a record in the audit log that
// the user skipped it.
#pragma once

#include "bus/identitycheck.h"

#include <QObject>
#include <QTextStream>

#include <functional>
#include <memory>

class QCommandLineParser;

namespace jumo {

class Bus;
class EventLog;
class FamilyRegistry;

class IdentityGate : public QObject
{
    Q_OBJECT

public:
    IdentityGate(Bus &bus, const FamilyRegistry &registry, QTextStream &err, QObject *parent = nullptr);
    ~IdentityGate() override;

    static void addOption(QCommandLineParser &parser);
    // Takes --no-identify from the parsed options.
    void configure(const QCommandLineParser &parser);
    // Commands that write: the audit log records the devices written without the check.
    void recordSkipsIn(EventLog *audit) { m_audit = audit; }
    bool isSkipped() const { return m_skipped; }

    // Calls next() once every device is confirmed (or the check is skipped). Otherwise
    // the reasons go to stderr and refused() gets the exit code: WrongDevice when
    // another device answers, Failed when one is silent, unless whenSilent is given:
    // then that is called instead (a read reports the timeouts itself).
    void pass(const QList<IdentityCheck::Claim> &claims, const std::function<void()> &next,
              const std::function<void(int)> &refused, const std::function<void()> &whenSilent = {});

    // Stops a check under way; neither next() nor refused() follows.
    void cancel();

private:
    Bus &m_bus;
    const FamilyRegistry &m_registry;
    QTextStream &m_err;
    EventLog *m_audit = nullptr;
    bool m_skipped = false;
    std::unique_ptr<IdentityCheck> m_check;
};

} // namespace jumo
