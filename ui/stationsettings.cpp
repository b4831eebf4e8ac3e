#include "stationsettings.h"

#include <QSettings>

namespace jumo {

namespace {

BusSettings busSettings(const QSettings &s, const QString &prefix)
{
    BusSettings b;
    b.portName = s.value(prefix + QStringLiteral("port")).toString();
    b.format = LineFormat::parse(s.value(prefix + QStringLiteral("baud"), 9600).toInt(),
                                 s.value(prefix + QStringLiteral("format"), QStringLiteral("8N1")).toString())
                       .value_or(*LineFormat::parse(9600, QStringLiteral("8N1")));
    b.timeoutMs = s.value(prefix + QStringLiteral("timeout_ms"), 0).toInt();
    b.minimumResponseTimeMs = s.value(prefix + QStringLiteral("min_response_ms"), 0).toInt();
    b.retries = s.value(prefix + QStringLiteral("retries"), 2).toInt();
    return b;
}

} // namespace

QList<StationSettings::Line> StationSettings::load(const QSettings &settings)
{
    // QSettings' array functions are not const; the keys are read one by one.
    QList<Line> lines;
    const int count = settings.value(QStringLiteral("lines/size"), -1).toInt();
    if (count < 0) {
        // Kept by a one-line version: its line, named as a first line is.
        if (!settings.contains(QStringLiteral("line/port")) && !settings.contains(QStringLiteral("devices")))
            return lines;
        lines << Line{QStringLiteral("line1"), busSettings(settings, QStringLiteral("line/")),
                      settings.value(QStringLiteral("devices")).toStringList()};
        return lines;
    }
    for (int i = 1; i <= count; ++i) {
        const QString prefix = QStringLiteral("lines/%1/").arg(i);
        lines << Line{settings.value(prefix + QStringLiteral("name")).toString(), busSettings(settings, prefix),
                      settings.value(prefix + QStringLiteral("devices")).toStringList()};
    }
    return lines;
}

void StationSettings::save(QSettings &settings, const QList<Line> &lines)
{
    settings.remove(QStringLiteral("line"));
    settings.remove(QStringLiteral("devices"));
    settings.remove(QStringLiteral("lines"));
    settings.beginWriteArray(QStringLiteral("lines"), int(lines.size()));
    for (int i = 0; i < lines.size(); ++i) {
        settings.setArrayIndex(i);
        const Line &l = lines[i];
        settings.setValue(QStringLiteral("name"), l.name);
        settings.setValue(QStringLiteral("port"), l.settings.portName);
        settings.setValue(QStringLiteral("baud"), l.settings.format.baudRate);
        settings.setValue(QStringLiteral("format"), l.settings.format.formatName());
        settings.setValue(QStringLiteral("timeout_ms"), l.settings.timeoutMs);
        settings.setValue(QStringLiteral("min_response_ms"), l.settings.minimumResponseTimeMs);
        settings.setValue(QStringLiteral("retries"), l.settings.retries);
        settings.setValue(QStringLiteral("devices"), l.devices);
    }
    settings.endArray();
}

} // namespace jumo
