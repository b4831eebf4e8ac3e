// Fuzz target: a parameter-set file (a backup) given to restore or diff. It is either
// refused with a reason or read; then it is compared, as a restore does, against a
// device of its family (the simulator's registers), and what a restore would write must
// be values the file holds for parameters of the family, each one the codec can encode.
// Written back out and read again, the set must be the same.
#include "commissioning/parameterset.h"
#include "protocol/familyregistry.h"
#include "protocol/valuecodec.h"
#include "sim/simulateddevice.h"

#include <cstdint>

using namespace jumo;

namespace {

const FamilyRegistry &registry()
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return r;
}

// The parameters of a simulated device of the family, as a backup of it would hold them.
const ParameterSet &deviceSet(const std::shared_ptr<const RegisterMap> &map)
{
    static QHash<QString, ParameterSet> sets;
    auto it = sets.find(map->family);
    if (it == sets.end()) {
        SimulatedDevice device(map, 1);
        ParameterSet set;
        set.family = map->family;
        set.address = 1;
        for (const QString &id : ParameterSet::parameterIds(*map)) {
            const RegisterEntry *e = map->entry(id);
            QList<quint16> words;
            for (int i = 0; i < e->wordCount(); ++i)
                words << device.word(quint16(e->address + i));
            set.values.insert(id, ValueCodec::exactText(*e, *map, words));
        }
        it = sets.insert(map->family, set);
    }
    return *it;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray json(reinterpret_cast<const char *>(data), qsizetype(size));
    QString error;
    const std::optional<ParameterSet> set = ParameterSet::fromJson(json, &error);
    if (!set) {
        if (error.isEmpty())
            __builtin_trap();   // a refusal always says why
        return 0;
    }
    QString again;
    const std::optional<ParameterSet> reread = ParameterSet::fromJson(set->toJson(), &again);
    if (!reread || reread->family != set->family || reread->values != set->values)
        __builtin_trap();   // what is saved reads back the same

    const std::shared_ptr<const RegisterMap> map = registry().family(set->family);
    if (!map)
        return 0;
    (void)set->incompatibility(*map, QStringLiteral("1.02.03"));
    const ParameterSet &device = deviceSet(map);
    const QList<ParameterDifference> shown = device.differences(*set, *map);
    for (const ParameterDifference &d : ParameterSet::toRestore(shown)) {
        const RegisterEntry *e = map->entry(d.id);
        if (!e || !ParameterSet::isParameter(*e) || !set->values.contains(d.id) || d.newValue != set->values.value(d.id))
            __builtin_trap();   // a restore writes only parameters, only values the file holds
        (void)ValueCodec::encode(*e, *map, d.newValue);
    }
    // Compared with itself, a set differs in nothing.
    if (!set->differences(*set, *map).isEmpty())
        __builtin_trap();
    return 0;
}
