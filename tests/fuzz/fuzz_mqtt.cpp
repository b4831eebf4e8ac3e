// Fuzz target: what a viewer takes from a broker. The input is a sequence of messages,
// each a flags byte (bit 0: retained, bit 1: on the LivenessLink's connection), a topic
// and a payload, each preceded by its length in two bytes (big-endian). They go through
// RemoteStation as from the broker (TopicScheme's topic and payload parsing, DeviceSpec,
// the waiting messages, the words decoded through the family's map) and RemoteLines on
// top (MirroredLines, the station's order). Nothing may crash, and what the mirror holds
// stays within its limits: known families only, addresses within the family's range,
// entries of the family's map, at most maxDevicesPerStation devices a station, the
// station's order parsed only as LINE/FAMILY@ADDRESS names and shown as a permutation of
// each line's devices.
#include "mqtt/remotelines.h"
#include "mqtt/remotestation.h"
#include "protocol/familyregistry.h"

#include <QCoreApplication>

#include <cstdint>

using namespace jumo;

namespace {

const FamilyRegistry &registry()
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return r;
}

int bigEndian16(const uint8_t *at)
{
    return (int(at[0]) << 8) | int(at[1]);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!QCoreApplication::instance()) {
        // libFuzzer's own main: deleteLater needs an application to deliver it.
        static int argc = 1;
        static char name[] = "jumo-fuzz-mqtt";
        static char *argv[] = {name, nullptr};
        static QCoreApplication app(argc, argv);
    }
    {
        RemoteStation mirror(registry());
        RemoteLines lines(&mirror);
        size_t at = 0;
        while (at + 5 <= size) {
            const uint8_t flags = data[at];
            const int topicLength = bigEndian16(data + at + 1);
            at += 3;
            if (at + size_t(topicLength) + 2 > size)
                break;
            const QString topic = QString::fromUtf8(reinterpret_cast<const char *>(data + at), topicLength);
            at += size_t(topicLength);
            const int payloadLength = std::min<int>(bigEndian16(data + at), int(size - at - 2));
            at += 2;
            const QByteArray payload(reinterpret_cast<const char *>(data + at), payloadLength);
            at += size_t(payloadLength);
            mirror.takeMessage(topic, payload, flags & 1, flags & 2);
        }
        if (mirror.stations().size() > RemoteStation::maxStations)
            __builtin_trap();
        QHash<QString, int> perStation;
        for (DeviceId id : mirror.devices()) {
            const RemoteDevice *d = mirror.device(id);
            if (!d || !d->map || d->address < d->map->protocol.addressMin || d->address > d->map->protocol.addressMax
                || d->name != QStringLiteral("%1@%2").arg(d->family).arg(d->address)
                || ++perStation[d->station] > RemoteStation::maxDevicesPerStation)
                __builtin_trap();
            for (const QString &entry : mirror.entryIds(id)) {
                const RegisterEntry *e = d->map->entry(entry);
                const EntryState *s = mirror.entryState(id, entry);
                if (!e || !e->isReadable() || !s || !mirror.published(id, entry) || s->value.display.size() > (1 << 20))
                    __builtin_trap();
            }
        }
        for (const QString &name : mirror.stations()) {
            const QStringList order = mirror.station(name)->order;
            if (order.size() > RemoteStation::maxDevicesPerStation)
                __builtin_trap();
            for (const QString &device : order) {
                if (device.count(QLatin1Char('/')) != 1 || !TopicScheme::isTopicLevel(device.section(QLatin1Char('/'), 0, 0)))
                    __builtin_trap();
            }
        }
        for (MirroredLine *line : lines.orderedLines()) {
            QList<DeviceId> ordered = lines.orderedDevices(line);
            QList<DeviceId> all = line->devices();
            std::sort(ordered.begin(), ordered.end());
            std::sort(all.begin(), all.end());
            if (ordered != all)
                __builtin_trap();
        }
    }
    // The lines RemoteLines handed to deleteLater, and the mirror's timers.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    return 0;
}
