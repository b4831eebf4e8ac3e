#include "bus/entrystate.h"

namespace jumo {

QString EntryState::statusName() const
{
    if (validity == Validity::Current)
        return value.status == ValueStatus::DecodeError ? QStringLiteral("invalid") : valueStatusName(value.status);
    if (validity == Validity::Stale)
        return QStringLiteral("stale");
    switch (error) {
    case ReadError::Exception:
        return QStringLiteral("exception:%1").arg(exceptionCode);
    case ReadError::Timeout:
    case ReadError::Mismatch:
        return QStringLiteral("timeout");
    case ReadError::DeviceOffline:
        return QStringLiteral("offline");
    case ReadError::LineLost:
        return QStringLiteral("line_lost");
    case ReadError::LineClosed:
        return QStringLiteral("disconnected");
    case ReadError::NotAvailable:
        return QStringLiteral("unavailable");
    case ReadError::Unconfirmed:
        return QStringLiteral("unconfirmed");
    case ReadError::WrongDevice:
        return QStringLiteral("wrong_device");
    case ReadError::None:
    case ReadError::NotRead:
        break;
    }
    return QStringLiteral("not_read");
}

QString validityName(Validity validity)
{
    switch (validity) {
    case Validity::Current: return QStringLiteral("current");
    case Validity::Stale: return QStringLiteral("stale");
    case Validity::Unknown: break;
    }
    return QStringLiteral("unknown");
}

} // namespace jumo
