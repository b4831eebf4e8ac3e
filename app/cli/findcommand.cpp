#include "findcommand.h"

#include "bus/bus.h"
#include "bus/lineaddress.h"
#include "commandparser.h"
#include "exitcodes.h"
#include "modbuslogging.h"
#include "protocol/familyregistry.h"
#include "quitonsignal.h"

#include <QDir>

#include <algorithm>

namespace jumo {

namespace {

QList<int> listOfInts(const QStringList &values, bool *ok)
{
    QList<int> out;
    *ok = true;
    for (const QString &value : values) {
        for (const QString &part : value.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            bool partOk = false;
            out << part.trimmed().toInt(&partOk);
            *ok = *ok && partOk;
        }
    }
    return out;
}

QStringList listOfWords(const QStringList &values)
{
    QStringList out;
    for (const QString &value : values) {
        for (const QString &part : value.split(QLatin1Char(','), Qt::SkipEmptyParts))
            out << part.trimmed().toUpper();
    }
    return out;
}

} // namespace

FindCommand::FindCommand(const FamilyRegistry &registry, QTextStream &out, QTextStream &err, QObject *parent)
    : QObject(parent), m_registry(registry), m_out(out), m_err(err)
{
}

FindCommand::~FindCommand() = default;

QString FindCommand::settingName(const LineFormat &format) const
{
    return QStringLiteral("%1 %2").arg(format.baudRate).arg(format.formatName());
}

std::optional<int> FindCommand::run(const QStringList &arguments)
{
    CommandParser parser(QStringLiteral("find"),
                         tr("Finds devices on a serial line whose settings nobody knows: tries every baud rate and "
                            "data format the families support, first address 255 (where every IPC 300 and TYA 200 "
                            "answers whatever its own address), then a quick scan of the address range, and says "
                            "what answers where."));
    parser.addOption({QStringLiteral("port"),
                      tr("The serial port (its /dev/serial/by-id name, which 'jumoctl ports' lists, or "
                         "/dev/ttyUSB0, say)."),
                      tr("path")});
    parser.addOption({QStringLiteral("baud"),
                      tr("Try only these baud rates (a list: 9600,19200; default every rate a family supports)."),
                      tr("rates")});
    parser.addOption({QStringLiteral("format"),
                      tr("Try only these data formats (a list: 8N1,8E1; default every format a family supports)."),
                      tr("formats")});
    parser.addOption({QStringLiteral("from"), tr("First address of the range (default 1)."), tr("address"),
                      QStringLiteral("1")});
    parser.addOption({QStringLiteral("to"), tr("Last address of the range (default 31, the most an RS-485 "
                                               "line carries)."),
                      tr("address"), QStringLiteral("31")});
    parser.addOption({QStringLiteral("min-response"),
                      tr("Minimum response time the devices may be set to, in ms (default 0)."), tr("ms"),
                      QStringLiteral("0")});
    parser.addOption({QStringLiteral("verbose"),
                      tr("Show Qt's Modbus messages (CRC errors, timeouts, frames) on stderr.")});
    if (const auto stop = parser.parseArguments(arguments, m_out, m_err, 0, 0))
        return stop;

    const QString port = parser.value(QStringLiteral("port"));
    if (port.isEmpty()) {
        m_err << tr("give the serial port: --port PATH ('jumoctl ports' lists them)") << Qt::endl;
        return exitcode::Usage;
    }
    QString error;
    const std::optional<LineAddress> address = LineAddress::parse(port, &error);
    if (!address) {
        m_err << error << Qt::endl;
        return exitcode::Usage;
    }
    if (address->isNetwork()) {
        m_err << tr("find tries the baud rates and formats of a serial port; behind a gateway or a device server "
                    "they are its own settings: set them there, then use 'jumoctl scan --port %1'")
                         .arg(port)
              << Qt::endl;
        return exitcode::Usage;
    }
    bool okFrom = false;
    bool okTo = false;
    m_first = parser.value(QStringLiteral("from")).toInt(&okFrom);
    m_last = parser.value(QStringLiteral("to")).toInt(&okTo);
    if (!okFrom || !okTo || m_first < 1 || m_last > 255 || m_first > m_last) {
        m_err << tr("--from and --to must be addresses 1..255, from <= to") << Qt::endl;
        return exitcode::Usage;
    }
    bool okBauds = true;
    const QList<int> bauds = listOfInts(parser.values(QStringLiteral("baud")), &okBauds);
    const QStringList formats = listOfWords(parser.values(QStringLiteral("format")));
    for (int baud : bauds) {
        if (!LineFormat::parse(baud, QStringLiteral("8N1")))
            okBauds = false;
    }
    if (!okBauds) {
        m_err << tr("--baud takes rates the families know: 4800, 9600, 19200, 38400") << Qt::endl;
        return exitcode::Usage;
    }
    for (const QString &format : formats) {
        if (!LineFormat::parse(9600, format)) {
            m_err << tr("--format takes 8N1, 8E1, 8O1 and 8N2, not %1").arg(format) << Qt::endl;
            return exitcode::Usage;
        }
    }
    bool okMin = false;
    BusSettings settings;
    settings.portName = LineAddress::absolutePort(port, QDir::currentPath());
    settings.minimumResponseTimeMs = parser.value(QStringLiteral("min-response")).toInt(&okMin);
    if (!okMin || settings.minimumResponseTimeMs < 0 || settings.minimumResponseTimeMs > 500) {
        m_err << tr("--min-response must be 0..500 ms") << Qt::endl;
        return exitcode::Usage;
    }
    // Only reads go out (probes of identity registers); read-only mode has nothing to refuse.
    settings.readOnly = true;
    settings.retries = 0;

    showModbusLogging(parser.isSet(QStringLiteral("verbose")));
    m_bus = std::make_unique<Bus>();
    m_bus->setSettings(settings);
    m_finder = std::make_unique<LineFinder>(*m_bus, m_registry.families());
    m_finder->restrict(bauds, formats);
    const QList<LineFinder::Setting> candidates = m_finder->settings();
    if (candidates.isEmpty()) {
        m_err << tr("no family supports these settings: %1 %2")
                         .arg(parser.values(QStringLiteral("baud")).join(QLatin1Char(',')),
                              parser.values(QStringLiteral("format")).join(QLatin1Char(',')))
              << Qt::endl;
        return exitcode::Usage;
    }
    connect(m_finder.get(), &LineFinder::trying, this, [this](const LineFormat &format, int step, int count, bool hint) {
        m_trying = hint ? tr("address 255 at %1 (%2 of %3)").arg(settingName(format)).arg(step + 1).arg(count)
                        : tr("%1 (%2 of %3)").arg(settingName(format)).arg(step + 1).arg(count);
        showProgress(m_trying);
    });
    connect(m_finder.get(), &LineFinder::probing, this, [this](int address, int, int) {
        const int left = int((m_finder->remainingMs() + 999) / 1000);
        showProgress(tr("%1: address %2, about %n s left", nullptr, left).arg(m_trying).arg(address));
    });
    connect(m_finder.get(), &LineFinder::found, this, &FindCommand::onFound);
    connect(m_finder.get(), &Job::finished, this, &FindCommand::onFinished);

    QStringList rates;
    QStringList names;
    for (const LineFinder::Setting &s : candidates) {
        if (!rates.contains(QString::number(s.format.baudRate)))
            rates << QString::number(s.format.baudRate);
        if (!names.contains(s.format.formatName()))
            names << s.format.formatName();
    }
    const int plannedS = int((m_finder->plannedMs(m_first, m_last) + 999) / 1000);
    m_err << tr("searching %n setting(s) (%1 baud; %2) for addresses %3..%4 and 255: about %5 s where nothing "
                "answers late",
                nullptr, int(candidates.size()))
                     .arg(rates.join(QStringLiteral(", ")), names.join(QLatin1Char(' ')))
                     .arg(m_first)
                     .arg(m_last)
                     .arg(plannedS);
    if (m_finder->plannedListeners() > 0)
        m_err << "; "
              << tr("the range is short, so up to %n address(es) next to it are probed once first at each setting, "
                    "to hear late answers, and not reported",
                    nullptr, int(m_finder->plannedListeners()));
    m_err << Qt::endl;
    m_finder->start(m_first, m_last);
    return std::nullopt;
}

void FindCommand::showProgress(const QString &text)
{
    const QString line = tr("trying %1").arg(text);
    m_err << '\r' << line.leftJustified(m_progressWidth) << Qt::flush;
    m_progressWidth = int(line.size());
}

void FindCommand::clearProgress()
{
    if (m_progressWidth == 0)
        return;
    m_err << '\r' << QString(m_progressWidth, QLatin1Char(' ')) << '\r' << Qt::flush;
    m_progressWidth = 0;
}

void FindCommand::onFound(const LineFinder::Finding &finding)
{
    if (finding.alwaysAnswered)
        return;   // said at the end, where its own address was not found
    clearProgress();
    if (!finding.family)
        m_out << tr("at %1: address %2 answers, but matches no known family").arg(settingName(finding.format)).arg(finding.address);
    else
        m_out << tr("at %1: %2 at address %3 (%4)")
                         .arg(settingName(finding.format), finding.family->family)
                         .arg(finding.address)
                         .arg(finding.family->name);
    m_out << Qt::endl;
}

void FindCommand::interrupt(int signal)
{
    if (m_finished || m_interruptCode)
        return;
    m_interruptCode = 128 + signal;
    if (m_finder && m_finder->isRunning())
        m_finder->cancel();
    else
        onFinished();
}

void FindCommand::onFinished()
{
    if (m_finished)
        return;
    m_finished = true;
    clearProgress();
    const QList<LineFinder::Finding> findings = m_finder ? m_finder->findings() : QList<LineFinder::Finding>();
    const bool complete = m_finder && m_finder->result() == Job::Result::Succeeded;
    // A family answering at 255 whose own address the range did not hold (known only when
    // the whole range was scanned at that setting).
    const QList<LineFinder::Finding> onlyAlways = complete ? m_finder->ownAddressNotFound() : QList<LineFinder::Finding>();
    for (const LineFinder::Finding &f : onlyAlways) {
        if (m_finder->scannedEveryAddressOf(*f.family))
            m_out << tr("at %1: address %3 answers as %2, and no other address did: its own address is %3, or its "
                        "answer there was lost (search again)")
                             .arg(settingName(f.format), f.family->family)
                             .arg(f.address)
                  << Qt::endl;
        else
            m_out << tr("at %1: address %3 answers as %2, as every %2 does whatever its own address; its own is "
                        "outside %4..%5 (--from and --to look further)")
                             .arg(settingName(f.format), f.family->family)
                             .arg(f.address)
                             .arg(m_first)
                             .arg(m_last)
                  << Qt::endl;
    }
    const int onlyAt255 = int(onlyAlways.size());
    // One device at several settings of one baud rate: the adapter or the device took one
    // format for another.
    if (m_finder) {
        for (const LineFinder::SeveralFormats &several : m_finder->answeredAtSeveralFormats()) {
            m_err << tr("%1 at address %2 answers at %3 baud in %4: the device or the adapter takes one for the "
                        "other (a pseudo-terminal does not carry even parity; many UARTs take 8N2 for 8N1); its "
                        "own is in its interface settings")
                             .arg(several.family->family)
                             .arg(several.address)
                             .arg(several.baudRate)
                             .arg(several.formats.join(QStringLiteral(", ")))
                  << Qt::endl;
        }
    }
    // Devices, each once however many settings it answered at.
    QStringList devicesSeen;
    for (const LineFinder::Finding &f : findings) {
        const QString key = QStringLiteral("%1@%2").arg(f.family ? f.family->family : QString()).arg(f.address);
        if (!f.alwaysAnswered && !devicesSeen.contains(key))
            devicesSeen << key;
    }
    const int devices = int(devicesSeen.size()) + onlyAt255;
    const double took = m_finder ? double(m_finder->elapsedMs()) / 1000.0 : 0.0;
    int code = devices > 0 || std::any_of(findings.cbegin(), findings.cend(),
                                          [](const LineFinder::Finding &f) { return f.alwaysAnswered; })
            ? exitcode::Ok
            : exitcode::Failed;
    if (m_finder && m_finder->result() == Job::Result::Failed) {
        // Not a search that found nothing: one that could not go on.
        m_err << tr("find: %1").arg(m_finder->errorText()) << Qt::endl
              << tr("the search stopped: %n device(s) found before, the settings after it not tried", nullptr, devices)
              << Qt::endl;
        emit finished(exitcode::Failed);
        return;
    }
    if (m_interruptCode) {
        m_err << signalSummary(m_interruptCode - 128, tr("%n device(s) found before the search stopped", nullptr, devices))
              << Qt::endl;
        emit finished(m_interruptCode);
        return;
    }
    m_err << tr("%n device(s) found in %1 s", nullptr, devices).arg(took, 0, 'f', 1) << Qt::endl;
    QList<int> bauds;
    for (const LineFinder::Finding &f : findings) {
        if (!bauds.contains(f.format.baudRate))
            bauds << f.format.baudRate;
    }
    if (bauds.size() > 1)
        m_err << tr("the devices answer at different baud rates: a line needs one, so set them alike") << Qt::endl;
    if (const std::optional<LineFormat> best = m_finder ? m_finder->bestSetting() : std::nullopt)
        m_err << tr("the line's settings where the most answered: --baud %1 --format %2")
                         .arg(best->baudRate)
                         .arg(best->formatName())
              << Qt::endl;
    else if (code == exitcode::Failed)
        m_err << tr("nothing answered: check the wiring (A/B swapped?), the termination and the adapter, or a "
                    "minimum response time set in the devices (--min-response)")
              << Qt::endl;
    emit finished(code);
}

} // namespace jumo
