// What a broadcast passes before it goes out: address 0 reaches every device on the
// line, so the line must be known to carry only the family. Either a scan of the whole
// address range in this run finds no other device (--scan-first), or the user names the
// family in an acknowledgement (--line-has-only FAMILY) that the audit log records; the
// devices it is read back from are then checked like any other.
#pragma once

#include "protocol/registermap.h"

#include <QObject>
#include <QTextStream>

#include <functional>
#include <memory>
#include <optional>

class QCommandLineParser;

namespace jumo {

class BroadcastClearance;
class Bus;
class EventLog;
class FamilyRegistry;
class IdentityGate;

class BroadcastGate : public QObject
{
    Q_OBJECT

public:
    BroadcastGate(Bus &bus, const FamilyRegistry &registry, QTextStream &err, QObject *parent = nullptr);
    ~BroadcastGate() override;

    static void addOptions(QCommandLineParser &parser);
    // Before the line is opened: an exit code when the options do not clear a broadcast
    // of this family with these read-back addresses.
    std::optional<int> configure(const QCommandLineParser &parser, std::shared_ptr<const RegisterMap> family,
                                 const QList<quint8> &readBack);
    // Clears the broadcast, then calls next() with the addresses to read it back from;
    // else the reason goes to stderr and refused() gets the exit code.
    void pass(IdentityGate &identity, EventLog *audit, const std::function<void(const QList<quint8> &)> &next,
              const std::function<void(int)> &refused);

    // Stops a check under way; neither next() nor refused() follows.
    void cancel();

private:
    void scan(const std::function<void(const QList<quint8> &)> &next, const std::function<void(int)> &refused);

    Bus &m_bus;
    const FamilyRegistry &m_registry;
    QTextStream &m_err;
    std::shared_ptr<const RegisterMap> m_family;
    QList<quint8> m_readBack;
    bool m_scanFirst = false;
    std::unique_ptr<BroadcastClearance> m_clearance;
};

} // namespace jumo
