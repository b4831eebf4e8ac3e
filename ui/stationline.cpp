#include "stationline.h"

#include "logs/alarmjournal.h"
#include "logs/writeaudit.h"

#include <QLocale>

namespace jumo {

StationLine::StationLine(const QString &name, const BusSettings &settings, QObject *parent)
    : QObject(parent), m_name(name), m_settings(settings)
{
    m_bus.setSettings(settings);
    connect(&m_bus, &Bus::stateChanged, this, [this](LineState state) {
        m_since = QDateTime::currentDateTime();
        if (state == LineState::Connected)
            m_lastError.clear();
        emit stateChanged(state);
    });
    connect(&m_bus, &Bus::lineError, this, [this](const QString &message) {
        // The loss is told before its reason: the state in words again, with it.
        m_lastError = message;
        emit stateChanged(state());
    });
}

StationLine::~StationLine()
{
    m_bus.close();
}

void StationLine::setName(const QString &name)
{
    if (name == m_name)
        return;
    m_name = name;
    setNamedInLogs(m_namedInLogs);
    emit changed();
}

void StationLine::setSettings(const BusSettings &settings)
{
    m_settings = settings;
    emit changed();
}

bool StationLine::open()
{
    BusSettings s = m_settings;
    s.readOnly = m_bus.isReadOnly() || m_settings.readOnly;
    m_bus.setSettings(s);
    if (m_bus.open())
        return true;
    m_lastError = m_bus.lastError();
    m_since = QDateTime::currentDateTime();
    emit stateChanged(m_bus.state());
    return false;
}

void StationLine::close()
{
    m_lastError.clear();
    m_bus.close();
}

QString StationLine::reason() const
{
    return m_lastError;
}

QString StationLine::stateText() const
{
    switch (state()) {
    case LineState::Connected:
        return tr("Connected");
    case LineState::Lost: {
        // The connection's reason says "line lost: ..." itself.
        QString reason = m_lastError;
        const QString said = LineConnection::tr("line lost: %1").arg(QString());
        if (reason.startsWith(said))
            reason = reason.mid(said.size());
        const QString since = QLocale().toString(m_since.time(), QStringLiteral("HH:mm:ss"));
        return reason.isEmpty() ? tr("Line lost since %1").arg(since) : tr("Line lost since %1: %2").arg(since, reason);
    }
    case LineState::Disconnected:
        break;
    }
    return m_lastError.isEmpty() ? tr("Disconnected") : tr("Disconnected: %1").arg(m_lastError);
}

void StationLine::attachLogs(EventLog *journal, EventLog *audit)
{
    m_journal = new AlarmJournal(&m_bus, journal, this);
    m_audit = new WriteAudit(&m_bus, audit, this);
    setNamedInLogs(m_namedInLogs);
}

void StationLine::setNamedInLogs(bool named)
{
    m_namedInLogs = named;
    const QString prefix = named ? m_name + QLatin1Char('/') : QString();
    if (m_journal)
        m_journal->setDevicePrefix(prefix);
    if (m_audit)
        m_audit->setDevicePrefix(prefix);
}

QString StationLine::deviceName(DeviceId id) const
{
    const QString device = m_bus.deviceName(id);
    return m_namedInLogs && !device.isEmpty() ? m_name + QLatin1Char('/') + device : device;
}

} // namespace jumo
