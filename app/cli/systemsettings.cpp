#include "systemsettings.h"

#include <QSettings>

namespace jumo::SystemSettings {

namespace {

QSettings systemSettings()
{
    return QSettings(QSettings::SystemScope, QStringLiteral("jumo"), QStringLiteral("jumo-hmi"));
}

} // namespace

bool readOnly()
{
    return systemSettings().value(QStringLiteral("readOnly"), false).toBool();
}

QString fileName()
{
    return systemSettings().fileName();
}

} // namespace jumo::SystemSettings
