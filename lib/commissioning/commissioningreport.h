// The commissioning report of one device as an HTML document an engineer signs: a title
// block (site, cabinet, tag, engineer, date, device, line), the identity, the parameters
// by the manual's sections with the manual's defaults, the live values and active alarms
// at the time, the writes, and signature lines. The HMI and jumoctl print it as HTML or,
// through ReportWriter, as paginated PDF.
#pragma once

#include "bus/bussettings.h"
#include "bus/entrystate.h"
#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonObject>

#include <functional>
#include <optional>

namespace jumo {

// What the person making the report enters: where the device is and who commissions it.
struct ReportTitle
{
    QString site;
    QString cabinet;
    QString tag;        // the device's tag in the plant (TIC-101, say)
    QString engineer;
};

class CommissioningReport
{
    Q_DECLARE_TR_FUNCTIONS(jumo::CommissioningReport)

public:
    using StateLookup = std::function<const EntryState *(const QString &entryId)>;

    CommissioningReport(const RegisterMap &map, quint8 address, StateLookup states);

    void setTitle(const ReportTitle &title) { m_title = title; }
    void setLine(const BusSettings &settings) { m_line = settings; }
    // The program that made the report and its version ("jumoctl 0.1.0").
    void setSoftware(const QString &software) { m_software = software; }
    // Audit records (see WriteAudit) of this device made since the given time.
    void setWrites(const QList<QJsonObject> &writes, const QDateTime &since)
    {
        m_writes = writes;
        m_writesSince = since;
    }
    void setTime(const QDateTime &time) { m_time = time; }

    // The document, numbers and dates in the default locale's way.
    QString html() const;
    // A line for the head of every printed page: the report, the tag and the site.
    QString pageHeader() const;
    // A line for the foot of every printed page: the device and when it was reported.
    QString pageFooter() const;

    // The entry's default (see the map's "default") as the device would report it;
    // nullopt where the manual gives none.
    static std::optional<DecodedValue> defaultValue(const RegisterEntry &entry, const RegisterMap &map);
    // Whether a value differs from the entry's default, compared as the device stores
    // it (word by word); nullopt without a default or without a value to compare.
    static std::optional<bool> differsFromDefault(const RegisterEntry &entry, const RegisterMap &map,
                                                  const EntryState *state);
    // The text of the identity words that name the device's model, where they do (the
    // TYA's basic type "709061 (TYA 201 - single-phase unit)"); empty where they do not
    // or are not known.
    static QString identifiedModel(const RegisterMap &map, const StateLookup &states);
    // The mark of a parameter that differs from its default.
    static QString differsMark() { return QStringLiteral("\u2260"); }

private:
    QString titleBlock() const;
    QString model() const;
    QString identity() const;
    QString parameters() const;
    QString liveValues() const;
    QString alarms() const;
    QString writes() const;
    QString signatures() const;
    QString valueText(const RegisterEntry &entry) const;
    QString stateText(const RegisterEntry &entry) const;
    QString auditValue(const RegisterEntry *entry, const QString &text) const;
    QString configuredUnitsNote(const QList<const RegisterEntry *> &entries) const;

    const RegisterMap &m_map;
    quint8 m_address;
    StateLookup m_states;
    ReportTitle m_title;
    std::optional<BusSettings> m_line;
    QString m_software;
    QList<QJsonObject> m_writes;
    QDateTime m_writesSince;
    QDateTime m_time = QDateTime::currentDateTime();
};

} // namespace jumo
