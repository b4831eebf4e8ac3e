#include "bus/writeoutcome.h"

namespace jumo {

QString WriteOutcome::resultName() const
{
    switch (result) {
    case Result::Confirmed: return QStringLiteral("confirmed");
    case Result::Accepted: return QStringLiteral("accepted");
    case Result::Mismatch: return QStringLiteral("mismatch");
    case Result::Refused: return QStringLiteral("refused");
    case Result::Unknown: return QStringLiteral("unknown");
    case Result::Unverified: return QStringLiteral("unverified");
    case Result::NotSent: return QStringLiteral("not_sent");
    case Result::ReadOnlyMode: return QStringLiteral("read_only");
    case Result::Invalid: return QStringLiteral("invalid");
    }
    return {};
}

} // namespace jumo
