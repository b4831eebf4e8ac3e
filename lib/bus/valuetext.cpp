#include "bus/valuetext.h"

#include "protocol/valuecodec.h"
#include "protocol/valueformat.h"

namespace jumo {

QString ValueText::noValue()
{
    return QString(QChar(0x2014));   // an em dash: no number, never a zero
}

QString ValueText::value(const EntryState *state, const RegisterEntry &entry)
{
    if (!state || state->validity == Validity::Unknown || !state->hasValue())
        return noValue();
    return ValueFormat::withUnit(state->value, entry);
}

QString ValueText::number(const EntryState *state, const RegisterEntry &entry)
{
    if (!state || state->validity == Validity::Unknown || !state->hasValue())
        return noValue();
    return ValueFormat::value(state->value, entry);
}

QString ValueText::unit(const RegisterEntry &entry)
{
    return entry.configuredUnit.isEmpty() ? entry.unit : tr("(configured)");
}

QString ValueText::unitNote(const RegisterEntry &entry, const RegisterMap &map)
{
    if (entry.configuredUnit.isEmpty())
        return {};
    return tr("Unit as configured on the device: %1")
            .arg(QCoreApplication::translate("jumo::maps", map.configuredUnits.value(entry.configuredUnit).toUtf8().constData()));
}

QString ValueText::reason(ReadError error, int exceptionCode, const RegisterMap &map)
{
    switch (error) {
    case ReadError::None:
        return {};
    case ReadError::NotRead:
        return tr("Not read yet");
    case ReadError::Timeout:
        return tr("No answer");
    case ReadError::Exception:
        return tr("Exception %1: %2").arg(exceptionCode).arg(map.exceptionMeaning(exceptionCode));
    case ReadError::Mismatch:
        return tr("Reply did not fit the request");
    case ReadError::DeviceOffline:
        return tr("Device not answering");
    case ReadError::LineLost:
        return tr("Line lost");
    case ReadError::LineClosed:
        return tr("Line disconnected");
    case ReadError::NotAvailable:
        return tr("Not available on this device");
    case ReadError::Unconfirmed:
        return tr("Identity not confirmed yet");
    case ReadError::WrongDevice:
        return tr("Another device answers at this address");
    }
    return {};
}

QString ValueText::status(const EntryState *state, const RegisterMap &map, qint64 nowMs)
{
    if (!state)
        return reason(ReadError::NotRead, 0, map);
    switch (state->validity) {
    case Validity::Current:
        return state->value.isOk() ? tr("OK") : ValueCodec::statusDescription(state->value.status, map);
    case Validity::Stale:
        return tr("Stale (%1 s old)").arg(QString::number((nowMs - state->goodMs) / 1000.0, 'f', 0));
    case Validity::Unknown:
        break;
    }
    return reason(state->error, state->exceptionCode, map);
}

} // namespace jumo
