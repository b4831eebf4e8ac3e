// The search for a line's settings in simulated line time: devices set to different baud
// rates and formats on one fake line, each answering only requests sent at its own; the
// settings heard at address 255 are scanned first; a narrowed search tries only what it
// is given; a cancel stops it and leaves the bus closed at its own settings. The pty tests
// of jumoctl find against jumo-sim and of the HMI's dialog remain the proof on a line.
#include "bus/linefinder.h"
#include "fakeline.h"

#include <QSignalSpy>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

namespace {

// A line whose devices each keep their own setting: a request sent at another is lost.
// ("8N1|8N2": a device whose UART takes either.)
struct MixedLine
{
    explicit MixedLine(const QList<std::tuple<QString, int, int, QString>> &devices)
        : line({})
    {
        for (const auto &[family, address, baud, format] : devices) {
            line.add(families().family(family), quint8(address));
            for (const QString &one : format.split(QLatin1Char('|')))
                formats.insert(quint8(address), *LineFormat::parse(baud, one));
        }
        bus = std::make_unique<Bus>(&line.clock, [this](const BusSettings &s) {
            auto t = std::make_unique<FakeTransport>(&line.clock, line.simulated(), s.format);
            t->drop = [this, format = s.format](const ModbusRequest &r) {
                // At 255 the device of a family that answers there, whatever its own address.
                for (const auto &d : line.sims) {
                    const bool addressed = d->address() == r.slave
                            || (!formats.contains(r.slave) && d->map().protocol.alwaysAnswersAddress == int(r.slave));
                    if (addressed)
                        return !formats.values(d->address()).contains(format);
                }
                return true;
            };
            transport = t.get();
            return t;
        });
        BusSettings settings;
        settings.portName = QStringLiteral("fake");
        settings.format = *LineFormat::parse(38400, QStringLiteral("8O1"));
        bus->setSettings(settings);
    }

    Line line;
    QMultiHash<quint8, LineFormat> formats;
    FakeTransport *transport = nullptr;
    std::unique_ptr<Bus> bus;
};

QString name(const LineFormat &f)
{
    return QStringLiteral("%1 %2").arg(f.baudRate).arg(f.formatName());
}

QStringList describe(const QList<LineFinder::Finding> &findings)
{
    QStringList out;
    for (const LineFinder::Finding &f : findings)
        out << QStringLiteral("%1: %2@%3%4")
                        .arg(name(f.format), f.family ? f.family->family : QStringLiteral("?"))
                        .arg(f.address)
                        .arg(f.alwaysAnswered ? QStringLiteral(" (always)") : QString());
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

class tst_LineFinder : public QObject
{
    Q_OBJECT

private slots:
    void settingsAreWhatTheFamiliesSupport();
    void findsEachDeviceAtItsOwnSetting();
    void narrowedSearchTriesOnlyWhatItIsGiven();
    void cancelLeavesTheBusAsItWas();
    void plannedTimeHoldsForShortAndLongRanges_data();
    void plannedTimeHoldsForShortAndLongRanges();
    void stepsFollowTheOrderTried();
    void devicesHeardOnlyAt255AndAtTwoFormats();
};

void tst_LineFinder::settingsAreWhatTheFamiliesSupport()
{
    MixedLine mixed({});
    LineFinder finder(*mixed.bus, families().families());
    const QList<LineFinder::Setting> settings = finder.settings();
    QCOMPARE(settings.size(), 16);
    QCOMPARE(name(settings.first().format), QStringLiteral("9600 8N1"));   // the factory default
    QCOMPARE(name(settings.last().format), QStringLiteral("4800 8N2"));
    for (const LineFinder::Setting &s : settings) {
        QStringList ids;
        for (const auto &f : s.families)
            ids << f->family;
        // The Quantrol knows 9600 and 19200 at 8N1 only; 4800 is the dTRON's alone.
        QCOMPARE(ids.contains("quantrol"), s.format.baudRate <= 19200 && s.format.baudRate >= 9600 && s.format.formatName() == "8N1");
        QCOMPARE(ids.contains("ipc300"), s.format.baudRate != 4800);
        QVERIFY(ids.contains("dtron300"));
        QCOMPARE(s.alwaysAnswered(), s.format.baudRate != 4800);
    }
}

void tst_LineFinder::findsEachDeviceAtItsOwnSetting()
{
    MixedLine mixed({{"tya200", 4, 19200, "8E1"}, {"dtron300", 7, 9600, "8N2"}, {"quantrol", 9, 19200, "8N1"}});
    LineFinder finder(*mixed.bus, families().families());
    QStringList scanned;
    connect(&finder, &LineFinder::trying, &finder, [&](const LineFormat &f, int, int, bool hint) {
        if (!hint)
            scanned << name(f);
    });
    QSignalSpy finished(&finder, &Job::finished);
    finder.start(1, 10);
    QVERIFY(mixed.line.runUntil([&] { return finished.count() == 1; }, 3600 * 1000));
    QCOMPARE(finder.result(), Job::Result::Succeeded);
    QCOMPARE(describe(finder.findings()),
             QStringList({"19200 8E1: tya200@255 (always)", "19200 8E1: tya200@4", "19200 8N1: quantrol@9",
                          "9600 8N2: dtron300@7"}));
    // The setting heard at 255 is scanned first, then the rest in the usual order.
    QCOMPARE(scanned.size(), 16);
    QCOMPARE(scanned.first(), QStringLiteral("19200 8E1"));
    QCOMPARE(scanned.at(1), QStringLiteral("9600 8N1"));
    // The TYA's own address and its answer at 255 outweigh one device elsewhere.
    QCOMPARE(name(*finder.bestSetting()), QStringLiteral("19200 8E1"));
    // Line time: every setting quick-scanned, seconds each.
    QVERIFY2(finder.elapsedMs() < 120 * 1000, qPrintable(QString::number(finder.elapsedMs())));
    qInfo("16 settings, addresses 1..10 and 255: %.1f s of line time", double(finder.elapsedMs()) / 1000.0);
    // Left closed, at its own settings.
    QCOMPARE(mixed.bus->state(), LineState::Disconnected);
    QCOMPARE(name(mixed.bus->settings().format), QStringLiteral("38400 8O1"));
}

void tst_LineFinder::narrowedSearchTriesOnlyWhatItIsGiven()
{
    MixedLine mixed({{"tya200", 4, 19200, "8E1"}, {"dtron300", 7, 9600, "8N2"}});
    LineFinder finder(*mixed.bus, families().families());
    finder.restrict({9600}, {"8N1", "8N2"});
    QCOMPARE(finder.settings().size(), 2);
    QSignalSpy finished(&finder, &Job::finished);
    finder.start(1, 10);
    QVERIFY(mixed.line.runUntil([&] { return finished.count() == 1; }, 3600 * 1000));
    QCOMPARE(describe(finder.findings()), QStringList({"9600 8N2: dtron300@7"}));
}

void tst_LineFinder::cancelLeavesTheBusAsItWas()
{
    MixedLine mixed({{"ipc300", 2, 9600, "8N1"}});
    LineFinder finder(*mixed.bus, families().families());
    connect(&finder, &LineFinder::found, &finder, [&] { finder.cancel(); });
    QSignalSpy finished(&finder, &Job::finished);
    finder.start(1, 31);
    QVERIFY(mixed.line.runUntil([&] { return finished.count() == 1; }, 3600 * 1000));
    QCOMPARE(finder.result(), Job::Result::Cancelled);
    // Stopped at the first setting: 255 answered there, nothing after it was tried.
    QVERIFY(!finder.findings().isEmpty());
    QCOMPARE(mixed.bus->state(), LineState::Disconnected);
    QCOMPARE(name(mixed.bus->settings().format), QStringLiteral("38400 8O1"));
}

void tst_LineFinder::plannedTimeHoldsForShortAndLongRanges_data()
{
    QTest::addColumn<int>("last");
    QTest::newRow("1..1") << 1;   // too short to listen after a quick pass: listeners borrowed
    QTest::newRow("1..3") << 3;
    QTest::newRow("1..6") << 6;
    QTest::newRow("1..31") << 31;
}

void tst_LineFinder::plannedTimeHoldsForShortAndLongRanges()
{
    // Where nothing answers, the search takes the time it announced, not a multiple of it.
    QFETCH(int, last);
    MixedLine mixed({});
    LineFinder finder(*mixed.bus, families().families());
    const qint64 planned = finder.plannedMs(1, last);
    QSignalSpy finished(&finder, &Job::finished);
    finder.start(1, last);
    QVERIFY(mixed.line.runUntil([&] { return finished.count() == 1; }, 3600 * 1000));
    QCOMPARE(finder.result(), Job::Result::Succeeded);
    qInfo("addresses 1..%d and 255: planned %.1f s, took %.1f s", last, double(planned) / 1000.0,
          double(finder.elapsedMs()) / 1000.0);
    QVERIFY2(finder.elapsedMs() <= planned + planned / 10,
             qPrintable(QStringLiteral("%1 of %2 ms").arg(finder.elapsedMs()).arg(planned)));
    QVERIFY2(finder.elapsedMs() >= planned / 2, qPrintable(QStringLiteral("%1 of %2 ms").arg(finder.elapsedMs()).arg(planned)));
    // A shorter range is no slower than the default one (it was, probed thoroughly: 1..3
    // planned 100 s against 89 s for 1..31).
    const qint64 default31 = finder.plannedMs(1, 31);
    QVERIFY2(planned <= default31, qPrintable(QStringLiteral("%1 against %2 ms for 1..31").arg(planned).arg(default31)));
}

void tst_LineFinder::stepsFollowTheOrderTried()
{
    // The progress of each pass counts up in the order the settings are tried, the
    // settings heard at 255 first.
    MixedLine mixed({{"tya200", 4, 19200, "8E1"}});
    LineFinder finder(*mixed.bus, families().families());
    QList<int> hintSteps;
    QList<int> scanSteps;
    int hintCount = 0;
    int scanCount = 0;
    connect(&finder, &LineFinder::trying, &finder, [&](const LineFormat &, int step, int count, bool hint) {
        (hint ? hintSteps : scanSteps) << step;
        (hint ? hintCount : scanCount) = count;
    });
    QSignalSpy finished(&finder, &Job::finished);
    finder.start(1, 6);
    QVERIFY(mixed.line.runUntil([&] { return finished.count() == 1; }, 3600 * 1000));
    QList<int> upTo12;
    QList<int> upTo16;
    for (int i = 0; i < 16; ++i)
        (i < 12 ? upTo12 : upTo16) << i;
    upTo16 = upTo12 + upTo16;
    QCOMPARE(hintCount, 12);   // 4800 baud is the dTRON's alone, which has no address 255
    QCOMPARE(hintSteps, upTo12);
    QCOMPARE(scanCount, 16);
    QCOMPARE(scanSteps, upTo16);
}

void tst_LineFinder::devicesHeardOnlyAt255AndAtTwoFormats()
{
    MixedLine mixed({{"tya200", 40, 19200, "8E1"}, {"dtron300", 7, 9600, "8N1|8N2"}});
    LineFinder finder(*mixed.bus, families().families());
    QSignalSpy finished(&finder, &Job::finished);
    finder.start(1, 10);
    QVERIFY(mixed.line.runUntil([&] { return finished.count() == 1; }, 3600 * 1000));
    // The TYA's own address is outside the range: heard at 255 only, and said so.
    const QList<LineFinder::Finding> only = finder.ownAddressNotFound();
    QCOMPARE(describe(only), QStringList({"19200 8E1: tya200@255 (always)"}));
    QVERIFY(!finder.scannedEveryAddressOf(*only.first().family));
    // The dTRON answers at both formats of 9600 baud: one device, named once.
    const QList<LineFinder::SeveralFormats> several = finder.answeredAtSeveralFormats();
    QCOMPARE(several.size(), 1);
    QCOMPARE(several.first().family->family, QStringLiteral("dtron300"));
    QCOMPARE(several.first().address, 7);
    QCOMPARE(several.first().baudRate, 9600);
    QCOMPARE(several.first().formats, QStringList({"8N1", "8N2"}));
    // Devices with their own address outweigh one heard at 255 only.
    QCOMPARE(name(*finder.bestSetting()), QStringLiteral("9600 8N1"));

    // With every address a TYA can have in the range, 255 is its own (or an answer was lost).
    LineFinder whole(*mixed.bus, families().families());
    whole.restrict({19200}, {"8E1"});
    QSignalSpy wholeFinished(&whole, &Job::finished);
    whole.start(1, 254);
    QVERIFY(mixed.line.runUntil([&] { return wholeFinished.count() == 1; }, 3600 * 1000));
    QVERIFY(whole.ownAddressNotFound().isEmpty());   // 40 is in the range now
    QVERIFY(whole.scannedEveryAddressOf(*families().family("tya200")));
}

QTEST_GUILESS_MAIN(tst_LineFinder)
#include "tst_linefinder.moc"
