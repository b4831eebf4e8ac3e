// How a device is named for people, in one place: "IPC 300 @ 1" in lists and on
// faceplates, where the page around it says the rest, and with its line where it must be
// unmistakable (the question before a write). A device's tag joins its titles here.
#pragma once

#include "protocol/registermap.h"

#include <QCoreApplication>

namespace jumo {

class DeviceTitle
{
    Q_DECLARE_TR_FUNCTIONS(jumo::DeviceTitle)

public:
    // "IPC 300 @ 1"
    static QString brief(const RegisterMap &map, quint8 address);
    // "IPC 300 at address 1 on line cabinet-a"; without the line when none is given.
    static QString full(const RegisterMap &map, quint8 address, const QString &line);
};

} // namespace jumo
