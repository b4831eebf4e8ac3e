// The station's lines as the HMI keeps them in its settings: an array "lines" of name,
// address, baud, format, timing and devices ("family@address"). Settings of the one-line
// versions (line/port, line/baud, line/format, devices) are read as one line "line1".
#pragma once

#include "bus/bussettings.h"

#include <QStringList>

class QSettings;

namespace jumo {

class StationSettings
{
public:
    struct Line
    {
        QString name;
        BusSettings settings;
        QStringList devices;   // "ipc300@1"
    };

    static QList<Line> load(const QSettings &settings);
    // Replaces what was kept (the one-line keys too).
    static void save(QSettings &settings, const QList<Line> &lines);
};

} // namespace jumo
