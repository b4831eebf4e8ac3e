// Fuzz target: a parameter-set file (a backup) given to restore or diff. It is either
// refused with a reason or read, and then compared against a device's values.
#include "commissioning/parameterset.h"
#include "protocol/familyregistry.h"

#include <cstdint>

using namespace jumo;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const FamilyRegistry registry = FamilyRegistry::load({}, true);
    const QByteArray json(reinterpret_cast<const char *>(data), qsizetype(size));
    QString error;
    const std::optional<ParameterSet> set = ParameterSet::fromJson(json, &error);
    if (!set) {
        if (error.isEmpty())
            __builtin_trap();   // a refusal always says why
        return 0;
    }
    (void)set->toJson();
    return 0;
}
