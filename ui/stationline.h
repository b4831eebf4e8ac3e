// One line of the station as the HMI keeps it: its name, what it is opened with, its bus
// (and so its devices), its journal and audit hooks, and its state in words. The window
// holds any number of them; pages and tiles of a device talk to its line's bus.
#pragma once

#include "bus/bus.h"

#include <QDateTime>
#include <QObject>

namespace jumo {

class AlarmJournal;
class EventLog;
class WriteAudit;

class StationLine : public QObject
{
    Q_OBJECT

public:
    StationLine(const QString &name, const BusSettings &settings, QObject *parent = nullptr);
    ~StationLine() override;

    QString name() const { return m_name; }
    void setName(const QString &name);
    // What the line is opened with: address (port or URL), format, timing, read-only.
    const BusSettings &settings() const { return m_settings; }
    void setSettings(const BusSettings &settings);
    Bus *bus() { return &m_bus; }
    const Bus *bus() const { return &m_bus; }

    // Opens the line with its settings; false with the reason in lastError().
    bool open();
    void close();
    LineState state() const { return m_bus.state(); }
    QString lastError() const { return m_lastError; }
    QDateTime since() const { return m_since; }
    // "Connected", "Line lost: the port is gone", "Disconnected": the state in words.
    QString stateText() const;
    // Whether the line's own error (a loss, a failed open) is part of its state.
    QString reason() const;

    // Alarms and writes of this line's devices go to these logs; with a prefix (several
    // lines) a device is named "LINE/family@address" in them.
    void attachLogs(EventLog *journal, EventLog *audit);
    void setNamedInLogs(bool named);
    // "ipc300@1", or "line2/ipc300@1" while lines must be told apart.
    QString deviceName(DeviceId id) const;

signals:
    void stateChanged(jumo::LineState state);
    // The name or the settings changed.
    void changed();

private:
    QString m_name;
    BusSettings m_settings;
    Bus m_bus;
    QString m_lastError;
    QDateTime m_since = QDateTime::currentDateTime();
    bool m_namedInLogs = false;
    AlarmJournal *m_journal = nullptr;
    WriteAudit *m_audit = nullptr;
};

} // namespace jumo
