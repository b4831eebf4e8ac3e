// What the HMI tells the benchmarks (tests/bench/bench_hmi.cpp) on stderr, in words a
// program reads: every second, the faceplates on screen and how old their values are.
// Header only: nothing here is for a user, and it needs no build entry of its own.
#pragma once

#include "devicetile.h"
#include "mainwindow.h"
#include "stationline.h"

#include <QTextStream>
#include <QTimer>

namespace jumo::BenchReport {

// Every second one line: "faceplate-ages ON_SCREEN TILES ONLINE NEVER_READ OLDEST UNREAD
// AGE_MS...": the faceplates with a part of them on screen, the faceplates, the devices
// online, the faceplate values never read, the oldest value ("ipc300@1/load_current", "-"
// for none), the values of devices online never read (comma-separated, "-" for none),
// and for every other faceplate value of every device (not the settings its bars are scaled
// by, which are read as settings) the time since its value was read
// (the value the faceplate shows, repainted at most DeviceTile's 100 ms later), in the
// bus's own clock.
inline void faceplateAgesEverySecond(MainWindow &window)
{
    auto *timer = new QTimer(&window);
    QObject::connect(timer, &QTimer::timeout, &window, [&window] {
        int tiles = 0;
        int onScreen = 0;
        for (const DeviceTile *tile : window.findChildren<DeviceTile *>()) {
            ++tiles;
            onScreen += tile->isVisible() && !tile->visibleRegion().isEmpty() ? 1 : 0;
        }
        int online = 0;
        int neverRead = 0;
        QString ages;
        QString oldest = QStringLiteral("-");
        QStringList unread;
        qint64 oldestMs = -1;
        for (const StationLine *line : window.lines()) {
            const DeviceSource *source = line->bus();
            const qint64 now = source->clockMs();
            for (DeviceId id : source->devices()) {
                online += source->condition(id).isOnline() ? 1 : 0;
                const std::shared_ptr<const RegisterMap> map = source->deviceMap(id);
                if (!map)
                    continue;
                for (const QString &entry : map->faceplateEntries(false)) {
                    const EntryState *state = source->entryState(id, entry);
                    if (!state || !state->hasValue()) {
                        ++neverRead;
                        if (source->condition(id).isOnline())
                            unread << source->deviceName(id) + QLatin1Char('/') + entry;
                        continue;
                    }
                    const qint64 age = now - state->goodMs;
                    ages += QLatin1Char(' ') + QString::number(age);
                    if (age > oldestMs) {
                        oldestMs = age;
                        oldest = source->deviceName(id) + QLatin1Char('/') + entry;
                    }
                }
            }
        }
        QTextStream(stderr) << "faceplate-ages " << onScreen << ' ' << tiles << ' ' << online << ' ' << neverRead << ' '
                            << oldest << ' ' << (unread.isEmpty() ? QStringLiteral("-") : unread.join(QLatin1Char(',')))
                            << ages << Qt::endl;
    });
    timer->start(1000);
}

} // namespace jumo::BenchReport
