// Finds devices on a serial line whose settings nobody knows: every baud rate and data
// format the families support, one after the other, on the one port.
//
// First a hint pass: at each setting one quick probe of address 255, where every IPC 300
// and TYA 200 answers whatever its own address. Then, the settings where anything was
// heard first, a quick scan (DeviceScanner) of address 255 and the range at each setting. A device answers at its own setting only (the
// manuals: no response on a baud rate or format mismatch); a lenient UART may accept a
// neighbouring format (8N1 and 8N2 often look alike), so a device can be found at more
// than one, and each is reported.
#pragma once

#include "bus/bussettings.h"
#include "bus/job.h"
#include "protocol/registermap.h"

#include <QList>

#include <memory>

namespace jumo {

class Bus;
class DeviceScanner;

class LineFinder : public Job
{
    Q_OBJECT

public:
    struct Setting
    {
        LineFormat format;
        QList<std::shared_ptr<const RegisterMap>> families;   // those that support it
        bool alwaysAnswered() const;                          // some answer at 255
    };

    struct Finding
    {
        LineFormat format;
        int address = 0;
        std::shared_ptr<const RegisterMap> family;   // null: answers, but matches no family
        // The family's always-answered address (255): a device of it is on the line at this
        // setting, its own address unknown unless found in the range as well.
        bool alwaysAnswered = false;
    };

    // The bus must be closed; it is opened at each setting in turn and left closed with
    // its own settings when the search ends.
    LineFinder(Bus &bus, QList<std::shared_ptr<const RegisterMap>> families, QObject *parent = nullptr);
    ~LineFinder() override;

    // Every baud rate and format some family supports, the factory default (9600 8N1)
    // first; narrowed to these baud rates and formats where given (before start()).
    void restrict(const QList<int> &baudRates, const QStringList &formats);
    QList<Setting> settings() const { return m_settings; }
    // The line time the search takes at most where nothing answers (every setting's quick
    // scan with its listener and the wait after it); late answers make it longer.
    // (Asks the closed bus for each setting's timeouts.)
    qint64 plannedMs(int firstAddress, int lastAddress);
    // The most listeners a setting's scan borrows next to the range (see DeviceScanner),
    // as the last plannedMs() found.
    qsizetype plannedListeners() const { return m_plannedListeners; }
    qint64 remainingMs() const;
    // Line time from start() to the end (so far, while running).
    qint64 elapsedMs() const;

    // Ends Succeeded (whatever was found), Cancelled, or Failed when the port cannot be
    // opened (its reason in errorText()).
    void start(int firstAddress, int lastAddress);

    QList<Finding> findings() const { return m_findings; }
    // Where the settings that answered tell one line setting: the one where the most was
    // found (a device's own address counting more than an answer at 255 alone), the first
    // of settings() where several tie. Null when nothing answered.
    std::optional<LineFormat> bestSetting() const;

    // Devices heard at their family's always-answered address (255) at a setting whose own
    // address the scan of that setting did not find. Complete once the search Succeeded.
    QList<Finding> ownAddressNotFound() const;
    // Whether the scan (the same range at every setting) probed every address a device of
    // this family can have, so that one heard at 255 only has 255 for its own, or lost its
    // answer at its own.
    bool scannedEveryAddressOf(const RegisterMap &family) const;
    // One device (family and address) that answered at more than one data format of a baud
    // rate: the device or the adapter takes one format for the other.
    struct SeveralFormats
    {
        std::shared_ptr<const RegisterMap> family;
        int address = 0;
        int baudRate = 0;
        QStringList formats;
    };
    QList<SeveralFormats> answeredAtSeveralFormats() const;

signals:
    // A setting is being tried: the step of its pass (0 .. count - 1; the hint pass tries
    // the settings of families with an always-answered address, the scan pass every
    // setting, those where a hint was heard first), and whether this is the hint pass.
    void trying(const jumo::LineFormat &format, int step, int count, bool hint);
    // An address of the current setting's scan is probed.
    void probing(int address, int done, int total);
    void found(const jumo::LineFinder::Finding &finding);

protected:
    void onCancel() override;

private:
    // What a setting's scan probes: the always-answered addresses of its families, then the range.
    static QList<int> addressesOf(const Setting &setting, int firstAddress, int lastAddress);
    void nextHint();
    void onHintFinished(int ticket, const QList<quint16> &words, bool timedOut, int exceptionCode);
    void nextScan();
    void scanFinished();
    bool openAt(const LineFormat &format);
    void end(Result result, const QString &error = QString());

    Bus &m_bus;
    BusSettings m_own;
    QList<std::shared_ptr<const RegisterMap>> m_families;
    QList<Setting> m_settings;
    int m_first = 1;          // the range scanned at each setting
    int m_last = 31;
    QList<int> m_order;       // indices into m_settings, the settings that answered hints first
    QList<bool> m_heard;      // per setting: the hint pass heard something
    QList<Finding> m_findings;
    int m_index = -1;         // into m_settings (hint pass) or m_order (scan pass)
    bool m_hintPass = false;
    int m_hintTicket = -1;
    qint64 m_hintQuietUntilMs = 0;   // a lost hint's answer could come until then
    quint64 m_strays = 0;
    std::unique_ptr<DeviceScanner> m_scanner;
    qint64 m_startedMs = 0;
    qint64 m_endedMs = -1;
    qint64 m_plannedMs = 0;
    qsizetype m_plannedListeners = 0;
};

} // namespace jumo
