#include "commissioning/commissioningreport.h"

#include "commissioning/parameterset.h"
#include "protocol/bitwrite.h"
#include "bus/valuetext.h"
#include "protocol/valuecodec.h"
#include "protocol/valueformat.h"

#include <QLocale>
#include <QRegularExpression>

#include <QHash>

#include <algorithm>
#include <array>

namespace jumo {

namespace {

QString translated(const QString &text)
{
    return QCoreApplication::translate("jumo::maps", text.toUtf8().constData());
}

QString escaped(const QString &text)
{
    return text.toHtmlEscaped();
}

// An empty cell holds a space: Qt's rich text measures a row by its last cell when that
// is empty, and what follows the table then overlaps the row's other lines.
QString emptyCell()
{
    return QStringLiteral("<td>&nbsp;</td>");
}

QString cell(const QString &text, const QString &attributes = QString())
{
    return QStringLiteral("<td%1>%2</td>").arg(attributes.isEmpty() ? QString() : QString(QLatin1Char(' ') + attributes),
                                              text.isEmpty() ? QStringLiteral("&nbsp;") : escaped(text));
}

// A table over the page's width; the header row is repeated on every page it spans.
// Attributes for Qt's rich text, the style for browsers.
QString tableStart(const QList<QPair<QString, int>> &columns)
{
    QString h = QStringLiteral("<table class=\"grid\" width=\"100%\" border=\"1\" cellspacing=\"0\" cellpadding=\"3\" "
                               "style=\"border-collapse:collapse;border-color:#999999\">");
    if (!columns.isEmpty()) {
        h += QStringLiteral("<thead><tr>");
        for (const auto &[title, percent] : columns)
            h += QStringLiteral("<th width=\"%1%\" align=\"left\">%2</th>").arg(percent).arg(escaped(title));
        h += QStringLiteral("</tr></thead>");
    }
    return h;
}

QString heading(int level, const QString &text)
{
    return QStringLiteral("<h%1>%2</h%1>").arg(level).arg(escaped(text));
}

QString paragraph(const QString &text, const QString &cssClass = QStringLiteral("note"))
{
    return QStringLiteral("<p class=\"%1\">%2</p>").arg(cssClass, escaped(text));
}

// The entries in groups, in the manual's order of sections and the map's order within.
QList<QPair<QString, QList<const RegisterEntry *>>> byGroup(const QList<const RegisterEntry *> &entries)
{
    QList<QPair<QString, QList<const RegisterEntry *>>> groups;
    for (const RegisterEntry *e : entries) {
        auto it = std::find_if(groups.begin(), groups.end(), [e](const auto &g) { return g.first == e->group; });
        if (it == groups.end())
            groups.append({e->group, {e}});
        else
            it->second << e;
    }
    std::stable_sort(groups.begin(), groups.end(),
                     [](const auto &a, const auto &b) { return sectionBefore(a.first, b.first); });
    return groups;
}

// Dates with the year in full and times to the second, in the locale's order.
QString dateText(const QDate &date, const QLocale &locale)
{
    QString format = locale.dateFormat(QLocale::ShortFormat);
    if (!format.contains(QLatin1String("yyyy")))
        format.replace(QLatin1String("yy"), QLatin1String("yyyy"));
    return locale.toString(date, format);
}

QString timeText(const QTime &time, const QLocale &locale)
{
    QString format = locale.timeFormat(QLocale::ShortFormat);
    if (!format.contains(QLatin1String("ss")))
        format.replace(QLatin1String("mm"), QLatin1String("mm:ss"));
    return locale.toString(time, format);
}

QString dateTimeText(const QDateTime &time, const QLocale &locale)
{
    return dateText(time.date(), locale) + QLatin1Char(' ') + timeText(time.time(), locale);
}

} // namespace

CommissioningReport::CommissioningReport(const RegisterMap &map, quint8 address, StateLookup states)
    : m_map(map), m_address(address), m_states(std::move(states))
{
}

std::optional<DecodedValue> CommissioningReport::defaultValue(const RegisterEntry &entry, const RegisterMap &map)
{
    if (!entry.defaultValue)
        return std::nullopt;
    const EncodeResult encoded = ValueCodec::encode(entry, map, QString::number(*entry.defaultValue, 'g', 17));
    if (!encoded.ok())
        return std::nullopt;
    return ValueCodec::decode(entry, map, encoded.words);
}

std::optional<bool> CommissioningReport::differsFromDefault(const RegisterEntry &entry, const RegisterMap &map,
                                                            const EntryState *state)
{
    if (!entry.defaultValue || !state || !state->hasValue() || state->validity == Validity::Unknown)
        return std::nullopt;
    const EncodeResult encoded = ValueCodec::encode(entry, map, QString::number(*entry.defaultValue, 'g', 17));
    if (!encoded.ok())
        return std::nullopt;
    return encoded.words != state->words;
}

QString CommissioningReport::valueText(const RegisterEntry &entry) const
{
    // As the HMI shows it: a current value with its unit, a stale one marked as such, an
    // unknown one as no value (the state column says why).
    const EntryState *s = m_states(entry.id);
    if (!s || !s->hasValue() || s->validity == Validity::Unknown)
        return ValueText::noValue();
    QString text = ValueFormat::withUnit(s->value, entry).trimmed();
    if (text.isEmpty())
        text = tr("(empty)");   // a text the device holds none of, not a missing value
    return s->validity == Validity::Stale ? tr("%1 (stale)").arg(text) : text;
}

QString CommissioningReport::stateText(const RegisterEntry &entry) const
{
    const EntryState *s = m_states(entry.id);
    if (!s)
        return ValueText::reason(ReadError::NotRead, 0, m_map);
    switch (s->validity) {
    case Validity::Current:
        // Said once above the table, not on every row: a current value has no remark.
        return s->value.isOk() ? QString() : ValueCodec::statusDescription(s->value.status, m_map);
    case Validity::Stale:
        return tr("stale: not read in the last cycle");
    case Validity::Unknown:
        break;
    }
    const QString reason = ValueText::reason(s->error, s->exceptionCode, m_map);
    if (!s->hasValue())
        return reason;
    return tr("%1; last known: %2").arg(reason, ValueFormat::withUnit(s->value, entry).trimmed());
}

QString CommissioningReport::configuredUnitsNote(const QList<const RegisterEntry *> &entries) const
{
    QStringList used;
    for (const RegisterEntry *e : entries) {
        if (!e->configuredUnit.isEmpty() && !used.contains(e->configuredUnit))
            used << e->configuredUnit;
    }
    QStringList notes;
    for (const QString &id : std::as_const(used))
        notes << translated(m_map.configuredUnits.value(id));
    if (notes.isEmpty())
        return {};
    return paragraph(tr("Values without a unit are in a unit set on the device: %1.").arg(notes.join(QStringLiteral("; "))));
}

QString CommissioningReport::pageHeader() const
{
    QStringList parts{tr("Commissioning report")};
    if (!m_title.tag.trimmed().isEmpty())
        parts << m_title.tag.trimmed();
    if (!m_title.site.trimmed().isEmpty())
        parts << m_title.site.trimmed();
    return parts.join(QStringLiteral(" \u00b7 "));
}

QString CommissioningReport::pageFooter() const
{
    return tr("%1, address %2, %3").arg(m_map.shortName).arg(m_address).arg(dateTimeText(m_time, QLocale()));
}

QString CommissioningReport::identifiedModel(const RegisterMap &map, const StateLookup &states)
{
    // The family's type numbers ("709061" of "TYA 201 (type 709061)"), and the models
    // that have none by their names.
    static const QRegularExpression typeNumber(QStringLiteral("\\d{5,}"));
    QStringList marks;
    for (const QString &model : map.models) {
        QRegularExpressionMatchIterator it = typeNumber.globalMatch(model);
        if (!it.hasNext())
            marks << QString(model).remove(QLatin1Char(' '));
        while (it.hasNext())
            marks << it.next().captured(0);
    }
    // An identity word names the model when its text (an enum's, or a set bit's label)
    // carries one of them: the TYA's basic type "709061 (TYA 201 - single-phase unit)",
    // the dTRON's device format "Type 703041/45 (48 mm x 48 mm)".
    QStringList named;
    for (const QString &id : map.identity) {
        const RegisterEntry *e = map.entry(id);
        const EntryState *s = states(id);
        if (!e || !s || !s->hasValue() || s->validity == Validity::Unknown || !s->value.isOk())
            continue;
        QStringList texts;
        if (e->type == ValueType::Enum) {
            texts << translated(e->enumValues.value(int(s->value.raw)));
        } else if (e->type == ValueType::Bitfield) {
            for (const BitDefinition &b : e->bits) {
                if (!b.reserved && b.width == 1 && (s->value.raw & b.mask()))
                    texts << translated(b.label);
            }
        }
        for (const QString &text : std::as_const(texts)) {
            const QString plain = QString(text).remove(QLatin1Char(' '));
            if (std::any_of(marks.cbegin(), marks.cend(), [&plain](const QString &m) { return plain.contains(m); }))
                named << text;
        }
    }
    return named.join(QStringLiteral(", "));
}

QString CommissioningReport::model() const
{
    const QString identified = identifiedModel(m_map, m_states);
    if (!identified.isEmpty())
        return identified;
    return m_map.models.isEmpty() ? ValueText::noValue()
                                  : tr("one of %1 (the device does not say which)").arg(m_map.models.join(QStringLiteral(", ")));
}

QString CommissioningReport::titleBlock() const
{
    const QLocale locale;
    const auto given = [](const QString &text) { return text.trimmed().isEmpty() ? ValueText::noValue() : text.trimmed(); };
    QString line = ValueText::noValue();
    if (m_line) {
        line = tr("%1 baud, %2").arg(m_line->format.baudRate).arg(m_line->format.formatName());
        if (!m_line->portName.isEmpty())
            line += tr(", port %1").arg(m_line->portName);
    }
    const QList<std::array<QString, 4>> rows{
            {tr("Site"), given(m_title.site), tr("Date"), dateTimeText(m_time, locale)},
            {tr("Cabinet"), given(m_title.cabinet), tr("Engineer"), given(m_title.engineer)},
            {tr("Device tag"), given(m_title.tag), tr("Address"), QString::number(m_address)},
            {tr("Device"), m_map.displayName(), tr("Line"), line},
            {tr("Model"), model(), tr("Software"), given(m_software)},
    };
    QString h = QStringLiteral("<table class=\"title\" width=\"100%\" border=\"1\" cellspacing=\"0\" cellpadding=\"4\" "
                               "style=\"border-collapse:collapse;border-color:#999999\">");
    // Labels wide enough for a long German word ("Inbetriebnehmer") in one line.
    for (const auto &r : rows) {
        h += QStringLiteral("<tr>") + cell(r[0], QStringLiteral("width=\"17%\" class=\"label\""))
                + cell(r[1], QStringLiteral("width=\"33%\"")) + cell(r[2], QStringLiteral("width=\"17%\" class=\"label\""))
                + cell(r[3], QStringLiteral("width=\"33%\"")) + QStringLiteral("</tr>");
    }
    h += QStringLiteral("</table>");
    return h;
}

QString CommissioningReport::identity() const
{
    QString h = heading(2, tr("Identity"));
    if (m_map.identity.isEmpty())
        return h + paragraph(tr("The family has no identity registers."));
    h += tableStart({});
    for (const QString &id : m_map.identity) {
        const RegisterEntry *e = m_map.entry(id);
        const EntryState *s = m_states(id);
        QString value = valueText(*e);
        if (!s || !s->hasValue() || s->validity == Validity::Unknown)
            value += QStringLiteral(" (") + stateText(*e) + QLatin1Char(')');
        h += QStringLiteral("<tr>") + cell(translated(e->label), QStringLiteral("width=\"45%\""))
                + cell(value, QStringLiteral("width=\"55%\"")) + QStringLiteral("</tr>");
    }
    return h + QStringLiteral("</table>");
}

QString CommissioningReport::parameters() const
{
    QList<const RegisterEntry *> entries;
    for (const RegisterEntry &e : m_map.entries()) {
        if (ParameterSet::isParameter(e))
            entries << &e;
    }
    if (entries.isEmpty())
        return heading(2, tr("Parameters")) + paragraph(tr("The family has no parameters."));
    const bool withDefaults = std::any_of(entries.cbegin(), entries.cend(), [](const RegisterEntry *e) { return e->defaultValue; });
    int differing = 0;
    int compared = 0;
    QString tables;
    for (const auto &[group, members] : byGroup(entries)) {
        tables += heading(3, translated(group));
        if (withDefaults)
            tables += tableStart({{tr("Parameter"), 48}, {tr("Value"), 24}, {differsMark(), 4}, {tr("Default"), 24}});
        else
            tables += tableStart({{tr("Parameter"), 55}, {tr("Value"), 45}});
        for (const RegisterEntry *e : members) {
            const std::optional<bool> differs = differsFromDefault(*e, m_map, m_states(e->id));
            compared += differs.has_value();
            differing += differs.value_or(false);
            QString value = valueText(*e);
            if (const EntryState *s = m_states(e->id); !s || !s->hasValue() || s->validity == Validity::Unknown)
                value += QStringLiteral(" (") + stateText(*e) + QLatin1Char(')');
            tables += differs.value_or(false) ? QStringLiteral("<tr class=\"differs\">") : QStringLiteral("<tr>");
            tables += cell(translated(e->label)) + cell(value, differs.value_or(false) ? QStringLiteral("class=\"differs\"") : QString());
            if (withDefaults) {
                const std::optional<DecodedValue> d = defaultValue(*e, m_map);
                tables += differs.value_or(false) ? QStringLiteral("<td align=\"center\"><b>%1</b></td>").arg(differsMark())
                                                  : emptyCell();
                tables += cell(d ? ValueFormat::withUnit(*d, *e).trimmed() : QString());
            }
            tables += QStringLiteral("</tr>");
        }
        tables += QStringLiteral("</table>");
    }
    QString h = heading(2, tr("Parameters"));
    if (withDefaults) {
        h += paragraph(tr("Default: the factory setting, or the value after power on, where the manual gives one; %1 marks "
                          "a value that differs from it. Differing: %2 of %3 compared.")
                               .arg(differsMark()).arg(differing).arg(compared));
    } else {
        h += paragraph(tr("The manual gives no default values for these parameters: none are compared."));
    }
    h += configuredUnitsNote(entries);
    return h + tables;
}

QString CommissioningReport::liveValues() const
{
    QList<const RegisterEntry *> entries;
    for (const RegisterEntry &e : m_map.entries()) {
        if (e.isReadable() && !e.reserved && e.alias.isEmpty() && !e.isCommand() && !ParameterSet::isParameter(e)
            && !m_map.identity.contains(e.id))
            entries << &e;
    }
    QString h = heading(2, tr("Live values"));
    if (entries.isEmpty())
        return h + paragraph(tr("The family has no live values."));
    h += paragraph(tr("As read at %1; a value with nothing under State is current. A value that could not be read "
                      "shows %2 and why.")
                           .arg(dateTimeText(m_time, QLocale()), ValueText::noValue()));
    h += configuredUnitsNote(entries);
    for (const auto &[group, members] : byGroup(entries)) {
        h += heading(3, translated(group));
        h += tableStart({{tr("Signal"), 48}, {tr("Value"), 26}, {tr("State"), 26}});
        for (const RegisterEntry *e : members)
            h += QStringLiteral("<tr>") + cell(translated(e->label)) + cell(valueText(*e)) + cell(stateText(*e)) + QStringLiteral("</tr>");
        h += QStringLiteral("</table>");
    }
    return h;
}

QString CommissioningReport::alarms() const
{
    QString rows;
    int active = 0;
    QStringList unknownWords;
    for (const RegisterEntry &e : m_map.entries()) {
        if (e.type != ValueType::Bitfield || !e.isReadable() || e.isCommand() || !e.hasAlarmBits())
            continue;
        const EntryState *s = m_states(e.id);
        if (!s || !s->hasValue() || s->validity == Validity::Unknown) {
            unknownWords << translated(e.label);
            continue;
        }
        for (const BitDefinition &b : e.bits) {
            if (b.reserved || b.width != 1 || (b.kind != BitKind::Alarm && b.kind != BitKind::Warning))
                continue;
            if (s->value.raw & b.mask()) {
                ++active;
                QString where = tr("%1, bit %2").arg(translated(e.label)).arg(b.bit);
                if (s->validity == Validity::Stale)
                    where += QLatin1Char(' ') + tr("(stale)");
                rows += QStringLiteral("<tr>") + cell(translated(b.label))
                        + cell(b.kind == BitKind::Alarm ? tr("alarm") : tr("warning")) + cell(where) + QStringLiteral("</tr>");
            }
        }
    }
    QString h = heading(2, tr("Active alarms and warnings"));
    if (!unknownWords.isEmpty())
        h += QStringLiteral("<p class=\"warning\"><b>%1</b></p>")
                     .arg(escaped(tr("Unknown: %1 could not be read; their alarms are not known.")
                                          .arg(unknownWords.join(QStringLiteral(", ")))));
    if (active == 0)
        return h + paragraph(unknownWords.isEmpty() ? tr("None active.") : tr("None of the others active."));
    return h + tableStart({{tr("Alarm"), 45}, {tr("Kind"), 15}, {tr("Where"), 40}}) + rows + QStringLiteral("</table>");
}

QString CommissioningReport::auditValue(const RegisterEntry *entry, const QString &text) const
{
    // The log keeps values as the codec writes them ("12.5"): shown here as elsewhere.
    if (text.isEmpty())
        return ValueText::noValue();
    if (!entry)
        return text;
    bool ok = false;
    const double number = text.toDouble(&ok);
    if (ok && isNumeric(entry->type)) {
        const QString shown = entry->type == ValueType::Float ? ValueFormat::number(number, entry->precision)
                                                               : QString::number(qint64(number));
        return ValueFormat::joinUnit(shown, entry->unit);
    }
    if (ok && entry->type == ValueType::Enum && entry->enumValues.contains(int(number)))
        return translated(entry->enumValues.value(int(number)));
    if (entry->type == ValueType::Bitfield) {
        // Bit changes as the log keeps them ("binary_output_control.output_k1=1") and
        // words as the codec wrote them ("0x8002 (output_2)"): by the bits' labels.
        QStringList changes;
        for (const QString &part : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
            const BitDefinition *bit = entry->bitById(part.section(QLatin1Char('='), 0, 0).section(QLatin1Char('.'), -1));
            const std::optional<bool> on = BitWrite::parseState(part.section(QLatin1Char('='), 1));
            if (!bit || !on || !part.contains(QLatin1Char('='))) {
                changes.clear();
                break;
            }
            changes << (*on ? tr("%1 on") : tr("%1 off")).arg(translated(bit->label));
        }
        if (!changes.isEmpty())
            return changes.join(QStringLiteral(", "));
        const uint word = text.section(QLatin1Char(' '), 0, 0).toUInt(&ok, 0);
        if (ok)
            return ValueFormat::bits(word, *entry);
    }
    return text;
}

QString CommissioningReport::writes() const
{
    const QLocale locale;
    QString h = heading(2, m_writesSince.isValid() ? tr("Writes since %1").arg(dateTimeText(m_writesSince, locale))
                                                   : tr("Writes"));
    if (m_writes.isEmpty())
        return h + paragraph(tr("None."));
    static const QHash<QString, const char *> outcomes{
            {QStringLiteral("confirmed"), QT_TR_NOOP("confirmed by read-back")},
            {QStringLiteral("accepted"), QT_TR_NOOP("accepted (cannot be read back)")},
            {QStringLiteral("mismatch"), QT_TR_NOOP("read back another value")},
            {QStringLiteral("refused"), QT_TR_NOOP("refused by the device")},
            {QStringLiteral("unknown"), QT_TR_NOOP("unknown: the answer was lost")},
            {QStringLiteral("unverified"), QT_TR_NOOP("not verified")},
            {QStringLiteral("not_sent"), QT_TR_NOOP("not sent")},
            {QStringLiteral("read_only"), QT_TR_NOOP("not sent: read-only mode")},
            {QStringLiteral("invalid"), QT_TR_NOOP("not sent: invalid value")},
            {QStringLiteral("identity_not_checked"), QT_TR_NOOP("identity not checked")},
            {QStringLiteral("broadcast_acknowledged"), QT_TR_NOOP("broadcast acknowledged")},
    };
    h += tableStart({{tr("Time"), 17}, {tr("Parameter"), 31}, {tr("Old value"), 14}, {tr("New value"), 14}, {tr("Outcome"), 24}});
    for (const QJsonObject &w : m_writes) {
        QDateTime time = QDateTime::fromString(w.value("time").toString(), Qt::ISODateWithMs);
        const QString timeShown = time.isValid() ? dateTimeText(time.toLocalTime(), locale) : w.value("time").toString();
        const QString id = w.value("entry").toString();
        const RegisterEntry *e = m_map.entry(id);
        const QString result = w.value("result").toString();
        QString outcome = outcomes.contains(result) ? tr(outcomes.value(result)) : result;
        if (result != QLatin1String("confirmed") && result != QLatin1String("accepted") && !w.value("message").toString().isEmpty())
            outcome += QStringLiteral(": ") + w.value("message").toString();
        h += QStringLiteral("<tr>") + cell(timeShown) + cell(e ? translated(e->label) : id)
                + cell(auditValue(e, w.value("old").toString())) + cell(auditValue(e, w.value("new").toString()))
                + cell(outcome) + QStringLiteral("</tr>");
    }
    return h + QStringLiteral("</table>");
}

QString CommissioningReport::signatures() const
{
    // Two columns, each a role with lines to write on: wide enough for a hand.
    QString h = heading(2, tr("Signatures"));
    h += paragraph(tr("The device was commissioned with the parameters above."));
    h += QStringLiteral("<table class=\"signatures\" width=\"100%\" border=\"0\" cellspacing=\"0\" cellpadding=\"4\" style=\"border-collapse:collapse\">");
    h += QStringLiteral("<tr>") + QStringLiteral("<td width=\"47%\"><b>%1</b></td>").arg(escaped(tr("Commissioning engineer")))
            + QStringLiteral("<td width=\"6%\">&nbsp;</td>")
            + QStringLiteral("<td width=\"47%\"><b>%1</b></td>").arg(escaped(tr("Customer"))) + QStringLiteral("</tr>");
    const QString engineer = m_title.engineer.trimmed();
    // The line is a cell's lower border, the room above it the cell's padding (by class:
    // Qt's rich text drops a class's border when the cell has a style of its own).
    const QList<QPair<QString, QString>> lines{{tr("Name"), QStringLiteral("line")},
                                               {tr("Date"), QStringLiteral("line")},
                                               {tr("Signature"), QStringLiteral("sign")}};
    for (const auto &[line, cssClass] : lines) {
        const QString onTheLine = line == tr("Name") ? escaped(engineer) : QString();
        h += QStringLiteral("<tr><td class=\"%1\">%2</td>%3<td class=\"%1\">&nbsp;</td></tr>")
                     .arg(cssClass, onTheLine.isEmpty() ? QStringLiteral("&nbsp;") : onTheLine, emptyCell());
        h += QStringLiteral("<tr><td class=\"rule\">%1</td>%2<td class=\"rule\">%1</td></tr>").arg(escaped(line), emptyCell());
    }
    return h + QStringLiteral("</table>");
}

QString CommissioningReport::html() const
{
    const QString title = m_title.tag.trimmed().isEmpty() ? tr("Commissioning report")
                                                          : tr("Commissioning report %1").arg(m_title.tag.trimmed());
    QString h = QStringLiteral(
                        "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>%1</title><style>"
                        // Lengths in px: Qt's rich text takes them (as 1/96 inch), not pt.
                        "body{font-family:sans-serif;font-size:9pt}"
                        "h1{font-size:16pt;margin-top:0px;margin-bottom:8px}"
                        "h2{font-size:12pt;margin-top:16px;margin-bottom:4px}"
                        "h3{font-size:10pt;margin-top:10px;margin-bottom:3px}"
                        "table{border-collapse:collapse}"
                        "th{background-color:#e8e8e8;text-align:left}"
                        "td{vertical-align:top}"
                        "td.label{background-color:#f0f0f0;font-weight:bold;font-size:8pt}"
                        "td.differs{font-weight:bold}"
                        "p.note{color:#333333;margin-top:2px;margin-bottom:4px}"
                        "p.warning{margin-top:2px;margin-bottom:4px}"
                        "td.line{border-bottom:1px solid #000000;padding-top:30px}"
                        "td.sign{border-bottom:1px solid #000000;padding-top:48px}"
                        "td.rule{font-size:8pt;color:#333333}"
                        "</style></head><body>")
                        .arg(escaped(title));
    h += heading(1, title);
    h += titleBlock();
    h += identity();
    h += parameters();
    h += liveValues();
    h += alarms();
    h += writes();
    h += signatures();
    return h + QStringLiteral("</body></html>");
}

} // namespace jumo
