// A line of simulated devices behind a fake transport on a manual clock, with a bus on
// it: unit tests of the bus and its jobs run minutes of line time in milliseconds.
#pragma once

#include "bus/bus.h"
#include "faketransport.h"
#include "protocol/familyregistry.h"
#include "sim/simulateddevice.h"

#include <QCoreApplication>

#include <functional>
#include <memory>
#include <vector>

namespace jumo::test {

inline const FamilyRegistry &families()
{
    static const FamilyRegistry registry = FamilyRegistry::load({}, true);
    return registry;
}

// A line of simulated devices behind a fake transport, on a manual clock.
struct Line
{
    explicit Line(const QList<QPair<QString, int>> &devices, int baud = 19200)
    {
        for (const auto &[family, address] : devices)
            add(families().family(family), quint8(address));
        bus = std::make_unique<Bus>(&clock, [this](const BusSettings &s) {
            auto t = std::make_unique<FakeTransport>(&clock, simulated(), s.format);
            transport = t.get();
            return t;
        });
        BusSettings settings;
        settings.portName = QStringLiteral("fake");
        settings.format = *LineFormat::parse(baud, QStringLiteral("8N1"));
        bus->setSettings(settings);
    }

    void add(std::shared_ptr<const RegisterMap> map, quint8 address)
    {
        sims.push_back(std::make_unique<SimulatedDevice>(std::move(map), address));
    }

    QHash<quint8, SimulatedDevice *> simulated() const
    {
        QHash<quint8, SimulatedDevice *> out;
        for (const auto &d : sims)
            out.insert(d->address(), d.get());
        return out;
    }

    SimulatedDevice *sim(quint8 address) const { return simulated().value(address); }

    // Runs the line until done() holds or maxMs of line time have passed; Qt's own events
    // (job results) are processed on the way.
    bool runUntil(const std::function<bool()> &done, qint64 maxMs)
    {
        const qint64 end = clock.nowMs() + maxMs;
        while (!done()) {
            QCoreApplication::processEvents();
            if (done())
                return true;
            const qint64 next = clock.nextCallMs();
            if (next < 0 || next > end)
                return false;
            clock.runNext();
        }
        return true;
    }
    void run(qint64 ms)
    {
        runUntil([] { return false; }, ms);
        clock.advanceTo(clock.nowMs());
    }

    ManualClock clock;
    std::vector<std::unique_ptr<SimulatedDevice>> sims;
    FakeTransport *transport = nullptr;
    std::unique_ptr<Bus> bus;
};

} // namespace jumo::test
