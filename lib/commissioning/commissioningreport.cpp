#include "commissioning/commissioningreport.h"

#include "commissioning/parameterset.h"
#include "protocol/valueformat.h"

#include <algorithm>

namespace jumo {

namespace {

QString translated(const QString &text)
{
    return QCoreApplication::translate("jumo::maps", text.toUtf8().constData());
}

QString cell(const QString &text)
{
    return QStringLiteral("<td>%1</td>").arg(text.toHtmlEscaped());
}

} // namespace

CommissioningReport::CommissioningReport(const RegisterMap &map, quint8 address, StateLookup states)
    : m_map(map), m_address(address), m_states(std::move(states))
{
}

QString CommissioningReport::valueText(const RegisterEntry &entry) const
{
    // Validity as the HMI shows it: a current value as it is, a stale one marked, an
    // unknown one as no value with the reason and the last value known.
    const EntryState *s = m_states(entry.id);
    if (!s || !s->hasValue())
        return tr("not read");
    // As the HMI shows it: the entry's precision, the locale's decimal sign, the unit.
    QString text = ValueFormat::withUnit(s->value, entry);
    switch (s->validity) {
    case Validity::Current:
        return text;
    case Validity::Stale:
        return text + QLatin1Char(' ') + tr("(stale)");
    case Validity::Unknown:
        break;
    }
    return tr("unknown (%1); last known: %2").arg(s->statusName(), text);
}

QString CommissioningReport::html() const
{
    QString h;
    h += QStringLiteral("<html><head><meta charset=\"utf-8\"><title>%1</title>"
                        "<style>body{font-family:sans-serif;font-size:10pt} table{border-collapse:collapse;width:100%}"
                        "td,th{padding:2px 4px;text-align:left} th{background:#ddd}"
                        "h1{font-size:16pt} h2{font-size:12pt;margin-top:14pt}</style></head><body>")
                 .arg(tr("Commissioning report").toHtmlEscaped());
    h += QStringLiteral("<h1>%1</h1>").arg(tr("Commissioning report").toHtmlEscaped());
    h += QStringLiteral("<p><b>%1</b>, %2<br>%3</p>")
                 .arg(m_map.name.toHtmlEscaped(), tr("address %1").arg(m_address).toHtmlEscaped(),
                      tr("Made %1").arg(m_time.toString(Qt::ISODate)).toHtmlEscaped());

    h += QStringLiteral("<h2>%1</h2><table border=\"1\" cellspacing=\"0\">").arg(tr("Identity").toHtmlEscaped());
    for (const QString &id : m_map.identity) {
        const RegisterEntry *e = m_map.entry(id);
        h += QStringLiteral("<tr>") + cell(translated(e->label)) + cell(valueText(*e).trimmed()) + QStringLiteral("</tr>");
    }
    if (m_map.identity.isEmpty())
        h += QStringLiteral("<tr><td>%1</td></tr>").arg(tr("The family has no identity registers.").toHtmlEscaped());
    h += QStringLiteral("</table>");

    h += QStringLiteral("<h2>%1</h2><table border=\"1\" cellspacing=\"0\">").arg(tr("Active alarms and warnings").toHtmlEscaped());
    int active = 0;
    QStringList unknownWords;
    for (const RegisterEntry &e : m_map.entries()) {
        if (e.type != ValueType::Bitfield || !e.isReadable() || e.isCommand()
            || std::none_of(e.bits.cbegin(), e.bits.cend(), [](const BitDefinition &b) {
                   return !b.reserved && (b.kind == BitKind::Alarm || b.kind == BitKind::Warning);
               }))
            continue;
        const EntryState *s = m_states(e.id);
        if (!s || !s->hasValue() || s->validity == Validity::Unknown) {
            unknownWords << formatAddress(e.address);
            continue;
        }
        for (const BitDefinition &b : e.bits) {
            if (b.reserved || b.width != 1 || (b.kind != BitKind::Alarm && b.kind != BitKind::Warning))
                continue;
            if (s->value.raw & b.mask()) {
                ++active;
                h += QStringLiteral("<tr>") + cell(formatAddress(e.address)) + cell(tr("bit %1").arg(b.bit))
                        + cell(translated(b.label)) + cell(bitKindName(b.kind)) + QStringLiteral("</tr>");
            }
        }
    }
    if (!unknownWords.isEmpty())
        h += QStringLiteral("<tr><td colspan=\"4\"><b>%1</b></td></tr>")
                     .arg(tr("Unknown: %1 could not be read").arg(unknownWords.join(QStringLiteral(", "))).toHtmlEscaped());
    else if (active == 0)
        h += QStringLiteral("<tr><td>%1</td></tr>").arg(tr("none").toHtmlEscaped());
    h += QStringLiteral("</table>");

    const auto table = [&](const QString &title, const std::function<bool(const RegisterEntry &)> &wanted) {
        h += QStringLiteral("<h2>%1</h2><table border=\"1\" cellspacing=\"0\"><tr><th>%2</th><th>%3</th><th>%4</th><th>%5</th><th>%6</th></tr>")
                     .arg(title.toHtmlEscaped(), tr("Register").toHtmlEscaped(), tr("Id").toHtmlEscaped(),
                          tr("Signal").toHtmlEscaped(), tr("Value").toHtmlEscaped(), tr("Storage").toHtmlEscaped());
        for (const RegisterEntry &e : m_map.entries()) {
            if (!wanted(e))
                continue;
            h += QStringLiteral("<tr>") + cell(formatAddress(e.address)) + cell(e.id) + cell(translated(e.label))
                    + cell(valueText(e).trimmed()) + cell(storageName(e.storage)) + QStringLiteral("</tr>");
        }
        h += QStringLiteral("</table>");
    };
    table(tr("Parameters"), [](const RegisterEntry &e) { return ParameterSet::isParameter(e); });
    table(tr("Live values"), [](const RegisterEntry &e) {
        return e.isReadable() && !e.reserved && e.alias.isEmpty() && !ParameterSet::isParameter(e);
    });

    h += QStringLiteral("<h2>%1</h2><table border=\"1\" cellspacing=\"0\"><tr><th>%2</th><th>%3</th><th>%4</th><th>%5</th><th>%6</th></tr>")
                 .arg(tr("Writes of the session").toHtmlEscaped(), tr("Time").toHtmlEscaped(), tr("Entry").toHtmlEscaped(),
                      tr("Old value").toHtmlEscaped(), tr("New value").toHtmlEscaped(), tr("Result").toHtmlEscaped());
    for (const QJsonObject &w : m_writes) {
        h += QStringLiteral("<tr>") + cell(w.value("time").toString()) + cell(w.value("entry").toString())
                + cell(w.value("old").toString()) + cell(w.value("new").toString())
                + cell(w.value("result").toString() + QStringLiteral(": ") + w.value("message").toString())
                + QStringLiteral("</tr>");
    }
    if (m_writes.isEmpty())
        h += QStringLiteral("<tr><td colspan=\"5\">%1</td></tr>").arg(tr("none").toHtmlEscaped());
    h += QStringLiteral("</table></body></html>");
    return h;
}

} // namespace jumo
