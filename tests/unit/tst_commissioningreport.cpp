// The commissioning report as a document: the title block as entered (escaped), values
// with their units in the locale's way, the manual's defaults and the mark where a value
// differs from one, values that are not current said as such, the manual's order of
// sections, the writes, the signature lines; the PDF's pages keep headings with their
// tables.
#include "commissioning/commissioningreport.h"
#include "protocol/familyregistry.h"
#include "protocol/translations.h"
#include "protocol/valuecodec.h"
#include "reportwriter.h"

#include <QAbstractTextDocumentLayout>
#include <QGuiApplication>
#include <QJsonObject>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QTest>
#include <QTextBlock>
#include <QTextDocument>
#include <QTextFrame>
#include <QTextLayout>
#include <QTextTable>

using namespace jumo;

namespace {

const RegisterMap &map(const QString &family)
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return *r.family(family);
}

// Entry states as the bus keeps them, made from the words a device would send.
class States
{
public:
    explicit States(const RegisterMap &map) : m_map(map) { }

    void set(const QString &id, const QList<quint16> &words, Validity validity = Validity::Current,
             ReadError error = ReadError::None)
    {
        EntryState s;
        s.words = words;
        s.value = ValueCodec::decode(*m_map.entry(id), m_map, words);
        s.validity = validity;
        s.error = error;
        s.goodMs = 1;
        s.updatedMs = 1;
        m_states.insert(id, s);
    }
    void setFloat(const QString &id, float value, Validity validity = Validity::Current, ReadError error = ReadError::None)
    {
        set(id, ValueCodec::encodeFloat(value, m_map.protocol.floatWordOrder), validity, error);
    }
    CommissioningReport::StateLookup lookup() const
    {
        return [this](const QString &id) { return m_states.contains(id) ? &m_states.find(id).value() : nullptr; };
    }

private:
    const RegisterMap &m_map;
    QHash<QString, EntryState> m_states;
};

// The table row (<tr ...>...</tr>) whose first cell is the label.
QString rowOf(const QString &html, const QString &label)
{
    const QRegularExpression row(QStringLiteral("<tr[^>]*><td[^>]*>%1</td>.*?</tr>").arg(QRegularExpression::escape(label)));
    return row.match(html).captured(0);
}

QDateTime reportTime()
{
    return QDateTime(QDate(2025, 3, 14), QTime(9, 26, 53));
}

} // namespace

class tst_CommissioningReport : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void titleBlockAsEnteredAndEscaped();
    void defaultsAreTheManuals();
    void differingValuesAreMarked_data();
    void differingValuesAreMarked();
    void familyWithoutDefaultsSaysSo();
    void valuesWithUnitsInTheLocalesWay();
    void valuesNotCurrentAreSaidAsSuch();
    void sectionsInTheManualsOrder();
    void writesWithLabelsAndUnits();
    void bitWritesByTheirLabels();
    void modelAsTheDeviceTellsIt_data();
    void modelAsTheDeviceTellsIt();
    void currentSaidOnce();
    void signatureLines();
    void pdfHasPagesAndHeadingsStayWithTheirTables();

private:
    QString ipcReport(States &states, const ReportTitle &title = {}) const;
};

void tst_CommissioningReport::initTestCase()
{
    useLanguage(*qApp, QLocale(QLocale::English, QLocale::UnitedStates));
}

QString tst_CommissioningReport::ipcReport(States &states, const ReportTitle &title) const
{
    CommissioningReport report(map("ipc300"), 1, states.lookup());
    report.setTitle(title);
    report.setTime(reportTime());
    BusSettings line;
    line.portName = QStringLiteral("/dev/ttyUSB0");
    line.format = *LineFormat::parse(19200, QStringLiteral("8E1"));
    report.setLine(line);
    report.setSoftware(QStringLiteral("jumoctl 0.1.0"));
    return report.html();
}

void tst_CommissioningReport::titleBlockAsEnteredAndEscaped()
{
    States states(map("ipc300"));
    const ReportTitle title{QStringLiteral("Plant <North> & \"Süd\""), QStringLiteral("=A1+B2"),
                            QStringLiteral("TIC-101"), QStringLiteral("<script>alert('x')</script>")};
    const QString html = ipcReport(states, title);
    QVERIFY(html.contains("Plant &lt;North&gt; &amp; &quot;Süd&quot;"));
    QVERIFY(html.contains("&lt;script&gt;alert('x')&lt;/script&gt;"));
    QVERIFY(!html.contains("<script>"));
    QVERIFY(!html.contains("<North>"));
    QVERIFY(rowOf(html, "Site").contains("Plant &lt;North&gt;"));
    QVERIFY2(rowOf(html, "Site").contains("<td width=\"33%\">3/14/2025 9:26:53 AM</td>"), qPrintable(rowOf(html, "Site")));   // the date beside it
    QVERIFY(rowOf(html, "Cabinet").contains("=A1+B2"));
    QVERIFY(rowOf(html, "Device tag").contains("TIC-101"));
    QVERIFY(rowOf(html, "Device tag").contains("<td width=\"33%\">1</td>"));   // the address
    QVERIFY(rowOf(html, "Device").contains("JUMO IPC 300 electronic transformer"));
    QVERIFY(rowOf(html, "Device").contains("19200 baud, 8E1, port /dev/ttyUSB0"));
    QVERIFY(rowOf(html, "Model").contains("jumoctl 0.1.0"));
    QVERIFY(html.contains("<title>Commissioning report TIC-101</title>"));
    // Fields left empty show as such, not as a blank that could be filled in later.
    const QString empty = ipcReport(states);
    QVERIFY(rowOf(empty, "Site").contains(QStringLiteral("<td width=\"33%\">\u2014</td>")));
}

void tst_CommissioningReport::defaultsAreTheManuals()
{
    // IPC 300 interface description, 5.1.2 table, 0x00AB: "default value is set to 10 %".
    QCOMPARE(map("ipc300").entry("load_monitoring_limit")->defaultValue, std::optional<double>(10));
    // IPC 300, 6.1: "Following power on, 0 % is used as the setpoint value".
    QCOMPARE(map("ipc300").entry("input_setpoint")->defaultValue, std::optional<double>(0));
    // TYA 200 (B70.9061.2), 6.2: "After power ON, the default α value of 180° is used".
    QCOMPARE(map("tya200").entry("alpha_default")->defaultValue, std::optional<double>(180));
    // TYA 200, 6.1: "After power ON the set point value 0 % is started with".
    QCOMPARE(map("tya200").entry("setpoint")->defaultValue, std::optional<double>(0));
    // The manuals give none for what they do not mention: the IPC 300's current limit, say.
    QVERIFY(!map("ipc300").entry("current_limit")->defaultValue);
    // The dTRON 300 manual (2.8.1) marks factory settings only for its interface settings,
    // which are no registers; the Quantrol manual gives none.
    for (const QString family : {"dtron300", "quantrol"}) {
        for (const RegisterEntry &e : map(family).entries())
            QVERIFY2(!e.defaultValue, qPrintable(family + ": " + e.id));
    }
}

void tst_CommissioningReport::differingValuesAreMarked_data()
{
    QTest::addColumn<float>("value");
    QTest::addColumn<int>("validity");
    QTest::addColumn<bool>("marked");
    QTest::newRow("the default") << 10.0f << int(Validity::Current) << false;
    QTest::newRow("another value") << 25.0f << int(Validity::Current) << true;
    QTest::newRow("close to the default, not equal") << 10.01f << int(Validity::Current) << true;
    QTest::newRow("another value, stale") << 25.0f << int(Validity::Stale) << true;
    QTest::newRow("another value, unknown now") << 25.0f << int(Validity::Unknown) << false;
}

void tst_CommissioningReport::differingValuesAreMarked()
{
    QFETCH(float, value);
    QFETCH(int, validity);
    QFETCH(bool, marked);
    States states(map("ipc300"));
    states.setFloat("load_monitoring_limit", value, Validity(validity),
                    Validity(validity) == Validity::Unknown ? ReadError::DeviceOffline : ReadError::None);
    states.setFloat("current_limit", 42);   // no default: never marked
    const QString html = ipcReport(states);
    const QString row = rowOf(html, "Limit value for load monitoring");
    QVERIFY2(!row.isEmpty(), qPrintable(html));
    QCOMPARE(row.startsWith("<tr class=\"differs\">"), marked);
    QCOMPARE(row.contains(CommissioningReport::differsMark()), marked);
    QVERIFY2(row.endsWith("<td>10.0 %</td></tr>"), qPrintable(row));   // the default beside it
    const QString unmarked = rowOf(html, "Current limit value");
    QVERIFY(unmarked.startsWith("<tr><td>"));
    QVERIFY(!unmarked.contains(CommissioningReport::differsMark()));
    QVERIFY2(unmarked.endsWith("<td>&nbsp;</td><td>&nbsp;</td></tr>"), qPrintable(unmarked));   // the manual gives none
    // Compared: the one value with a default that is known (the input setpoint is not read).
    QCOMPARE(html.contains(QStringLiteral("Differing: %1 of 1 compared.").arg(marked ? 1 : 0)),
             Validity(validity) != Validity::Unknown);
}

void tst_CommissioningReport::familyWithoutDefaultsSaysSo()
{
    States states(map("dtron300"));
    CommissioningReport report(map("dtron300"), 4, states.lookup());
    const QString html = report.html();
    QVERIFY(html.contains("The manual gives no default values for these parameters"));
    QVERIFY(!html.contains(CommissioningReport::differsMark()));
    QVERIFY(!html.contains("<th width=\"24%\" align=\"left\">Default</th>"));
}

void tst_CommissioningReport::valuesWithUnitsInTheLocalesWay()
{
    States states(map("ipc300"));
    states.setFloat("load_monitoring_limit", 12.5f);
    states.setFloat("load_current", 19.994f);
    states.setFloat("load_voltage", 229.96f);
    states.set("language", {1});
    QString html = ipcReport(states);
    QVERIFY2(rowOf(html, "Limit value for load monitoring").contains("<td class=\"differs\">12.5 %</td>"), qPrintable(html));
    QVERIFY(rowOf(html, "Load current").contains("<td>19.99 A</td>"));
    QVERIFY(rowOf(html, "Load voltage").contains("<td>230.0 V</td>"));

    QVERIFY(useLanguage(*qApp, QLocale(QLocale::German, QLocale::Germany)));
    const auto english = qScopeGuard([] { useLanguage(*qApp, QLocale(QLocale::English, QLocale::UnitedStates)); });
    html = ipcReport(states);
    QVERIFY2(rowOf(html, "Grenzwert für Lastüberwachung").contains("<td class=\"differs\">12,5 %</td>"), qPrintable(html));
    QVERIFY(rowOf(html, "Laststrom").contains("<td>19,99 A</td>"));
    QVERIFY(rowOf(html, "Standort").contains("14.03.2025 09:26:53"));
    QVERIFY(html.contains("<h2>Parameter</h2>"));
    QVERIFY(html.contains("Unterschrift"));
}

void tst_CommissioningReport::valuesNotCurrentAreSaidAsSuch()
{
    States states(map("ipc300"));
    states.setFloat("load_voltage", 230.0f, Validity::Unknown, ReadError::DeviceOffline);
    states.setFloat("load_current", 4.2f, Validity::Stale);
    states.setFloat("current_limit", 42.0f, Validity::Unknown, ReadError::Timeout);
    const QString html = ipcReport(states);
    // An unknown value shows no number as its value, only as what was last known.
    const QString voltage = rowOf(html, "Load voltage");
    QVERIFY2(voltage.contains(QStringLiteral("<td>\u2014</td><td>Device not answering; last known: 230.0 V</td>")),
             qPrintable(voltage));
    QVERIFY(!html.contains("<td>230.0 V</td>"));
    QVERIFY(rowOf(html, "Load current").contains("<td>4.200 A (stale)</td>"));
    QVERIFY(rowOf(html, "Current limit value").contains(QStringLiteral("\u2014 (No answer; last known: 42.00 A)")));
    // Never read: no value, and why.
    QVERIFY(rowOf(html, "Power").contains(QStringLiteral("<td>\u2014</td><td>Not read yet</td>")));
    // Alarm words that could not be read leave the alarms unknown, not "none".
    QVERIFY(html.contains("could not be read; their alarms are not known"));
    QVERIFY(!html.contains("None active."));
}

void tst_CommissioningReport::sectionsInTheManualsOrder()
{
    // The dTRON's addresses put 5.4 and 5.5 before 5.3 and 5.2; the report follows the manual.
    States states(map("dtron300"));
    const QString html = CommissioningReport(map("dtron300"), 4, states.lookup()).html();
    const qsizetype setpoints = html.indexOf("<h3>5.2 Setpoints</h3>");
    const qsizetype controller = html.indexOf("<h3>5.3 Controller parameters</h3>");
    const qsizetype configuration = html.indexOf("<h3>5.4 Configuration</h3>");
    const qsizetype program = html.indexOf("<h3>5.5 Program transmission</h3>");
    QVERIFY(setpoints > 0);
    QVERIFY(setpoints < controller);
    QVERIFY(controller < configuration);
    QVERIFY(configuration < program);
    // Within a section, the map's order: Pb1 of set 1 before Pb2 before set 2.
    QVERIFY(html.indexOf(">Parameter set 1: Pb1<") < html.indexOf(">Parameter set 1: Pb2<"));
    QVERIFY(html.indexOf(">Parameter set 1: Pb2<") < html.indexOf(">Parameter set 2: Pb1<"));
    // No internal ids where a label belongs.
    QVERIFY(!html.contains(">ps1_pb1<"));
}

void tst_CommissioningReport::writesWithLabelsAndUnits()
{
    States states(map("ipc300"));
    CommissioningReport report(map("ipc300"), 1, states.lookup());
    const QDateTime since(QDate(2025, 3, 14), QTime(8, 0));
    report.setWrites({QJsonObject{{"time", "2025-03-14T09:12:05.120"}, {"device", "ipc300@1"},
                                  {"entry", "load_monitoring_limit"}, {"old", "10"}, {"new", "25"},
                                  {"result", "confirmed"}, {"message", "confirmed"}},
                      QJsonObject{{"time", "2025-03-14T09:13:00.000"}, {"device", "ipc300@1"}, {"entry", "language"},
                                  {"old", "English"}, {"new", "1"}, {"result", "refused"},
                                  {"message", "exception 3: illegal data value"}}},
                     since);
    const QString html = report.html();
    QVERIFY2(html.contains("<h2>Writes since 3/14/2025 8:00:00 AM</h2>"), qPrintable(html.mid(html.indexOf("<h2>Writes"), 300)));
    const QString write = rowOf(html, "3/14/2025 9:12:05 AM");
    QVERIFY2(write.contains("<td>Limit value for load monitoring</td><td>10.0 %</td><td>25.0 %</td><td>confirmed by read-back</td>"),
             qPrintable(write));
    const QString refused = rowOf(html, "3/14/2025 9:13:00 AM");
    QVERIFY2(refused.contains("<td>refused by the device: exception 3: illegal data value</td>"), qPrintable(refused));
}

// 26.10: the writes of bits by the bits' labels, the words they replaced too; never the
// ids the audit log keeps ("binary_output_control.output_k1=1", "0x8002 (output_k2)").
void tst_CommissioningReport::bitWritesByTheirLabels()
{
    States states(map("quantrol"));
    CommissioningReport report(map("quantrol"), 3, states.lookup());
    report.setWrites({QJsonObject{{"time", "2025-03-14T09:12:05.120"}, {"device", "quantrol@3"},
                                  {"entry", "binary_output_control"}, {"old", "0x8002 (output_k2+activation)"},
                                  {"new", "binary_output_control.output_k1=1 binary_output_control.output_k3=0"},
                                  {"result", "confirmed"}, {"message", "confirmed by read-back: output_k1=1, output_k3=0"}}},
                     QDateTime(QDate(2025, 3, 14), QTime(8, 0)));
    const QString html = report.html();
    const QString write = rowOf(html, "3/14/2025 9:12:05 AM");
    QVERIFY2(write.contains("<td>Control of the binary outputs</td><td>0x8002 (Output K2, Activation)</td>"
                            "<td>Output K1 on, Output K3 off</td><td>confirmed by read-back</td>"),
             qPrintable(write));
    QVERIFY2(!html.contains("output_k"), qPrintable(html));
}

void tst_CommissioningReport::modelAsTheDeviceTellsIt_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QString>("entry");
    QTest::addColumn<int>("word");
    QTest::addColumn<QString>("model");
    QTest::newRow("TYA 201 by its basic type") << "tya200" << "basic_type" << 0 << "709061 (TYA 201 - single-phase unit)";
    QTest::newRow("TYA 203 by its basic type") << "tya200" << "basic_type" << 2
                                               << "709063 (TYA 203 - three-phase power controller)";
    QTest::newRow("dTRON by its format") << "dtron300" << "device_format" << 2 << "Type 703042/43/46 (48 mm x 96 mm)";
    QTest::newRow("IPC 300 by its basic type") << "ipc300" << "basic_type" << 0 << "IPC300_709051";
    QTest::newRow("dTRON whose format is not read") << "dtron300" << QString() << 0
                                                    << "one of dTRON 304, dTRON 308, dTRON 316, dTRON 304 plast, dTRON 308 plast, "
                                                       "dTRON 316 plast, 703041, 703042, 703043, 703044, 703045, 703046, 703047, "
                                                       "703048 (the device does not say which)";
    QTest::newRow("Quantrol, which does not say") << "quantrol" << "controller_status" << 0
                                                  << "one of Quantrol LC100, Quantrol LC200, Quantrol LC300 (the device does "
                                                     "not say which)";
}

// 26.14: the model the identity words name, not every model of the family.
void tst_CommissioningReport::modelAsTheDeviceTellsIt()
{
    QFETCH(QString, family);
    QFETCH(QString, entry);
    QFETCH(int, word);
    QFETCH(QString, model);
    States states(map(family));
    if (!entry.isEmpty())
        states.set(entry, {quint16(word)});
    const QString html = CommissioningReport(map(family), 1, states.lookup()).html();
    const QString row = rowOf(html, "Model");
    QVERIFY2(row.contains(QStringLiteral("<td width=\"33%\">%1</td>").arg(model.toHtmlEscaped())), qPrintable(row));
}

// 26.14: a current value needs no word of its own on each of sixty rows: the report says
// once what an empty state means, and names only what is not current.
void tst_CommissioningReport::currentSaidOnce()
{
    const RegisterMap &tya = map("tya200");
    States states(tya);
    int current = 0;
    for (const RegisterEntry &e : tya.entries()) {
        if (e.type == ValueType::Float && e.isReadable() && e.alias.isEmpty() && !e.reserved) {
            states.setFloat(e.id, 1.5f);
            ++current;
        }
    }
    states.setFloat("load_voltage", 230.0f, Validity::Stale);
    QVERIFY(current > 30);
    const QString html = CommissioningReport(tya, 4, states.lookup()).html();
    QVERIFY2(!html.contains(">current<"), qPrintable(html));
    QVERIFY(html.contains("a value with nothing under State is current"));
    QVERIFY2(rowOf(html, "Load voltage").contains("<td>230.0 V (stale)</td><td>stale: not read in the last cycle</td>"),
             qPrintable(rowOf(html, "Load voltage")));
    QVERIFY2(rowOf(html, "Load current").contains("<td>1.500 A</td><td>&nbsp;</td>"), qPrintable(rowOf(html, "Load current")));
}

void tst_CommissioningReport::signatureLines()
{
    States states(map("ipc300"));
    const QString html = ipcReport(states, {QString(), QString(), QString(), QStringLiteral("Erika Mustermann")});
    const qsizetype signatures = html.indexOf("<h2>Signatures</h2>");
    QVERIFY(signatures > 0);
    const QString tail = html.mid(signatures);
    for (const char *text : {"Commissioning engineer", "Customer", ">Name<", ">Date<", ">Signature<"})
        QVERIFY2(tail.contains(text), text);
    QVERIFY(tail.contains(">Erika Mustermann<"));   // the engineer's name is printed on the line
    QVERIFY(tail.indexOf("Signatures") < tail.indexOf("</body>"));
}

void tst_CommissioningReport::pdfHasPagesAndHeadingsStayWithTheirTables()
{
    // Every value read, as from a device.
    States states(map("ipc300"));
    for (const RegisterEntry &e : map("ipc300").entries()) {
        if (!e.isReadable() || e.reserved)
            continue;
        if (e.type == ValueType::Float)
            states.setFloat(e.id, 12.5f);
        else
            states.set(e.id, QList<quint16>(e.wordCount(), e.type == ValueType::Text ? 0x4142 : 0));
    }
    const QString html = ipcReport(states, {QStringLiteral("Plant North"), QString(), QStringLiteral("TIC-101"), QString()});
    int pages = 0;
    const QByteArray pdf = ReportWriter::pdf(html, {QStringLiteral("Report"), QStringLiteral("Head"), QStringLiteral("Foot")},
                                             &pages);
    QVERIFY(pdf.startsWith("%PDF-"));
    QVERIFY2(pages >= 3, qPrintable(QString::number(pages)));   // 13 parameters, 90 live values

    // On pages of any height, a heading never ends a page without the first rows of its
    // table, and the signatures are never split.
    int moved = 0;
    for (qreal height = 420; height <= 1000; height += 23) {
        QTextDocument document;
        document.setDocumentMargin(0);
        document.setHtml(html);
        document.setPageSize(QSizeF(700, height));
        // (Not laid out in full before: as the writer does it.)
        ReportWriter::keepTogether(document, height);
        for (QTextBlock b = document.begin(); b.isValid(); b = b.next())
            moved += bool(b.blockFormat().pageBreakPolicy() & QTextFormat::PageBreak_AlwaysBefore);
        QAbstractTextDocumentLayout *layout = document.documentLayout();
        // Every text is laid out, to be painted where it was measured.
        for (QTextBlock b = document.begin(); b.isValid(); b = b.next()) {
            QVERIFY2(b.text().isEmpty() || b.layout()->lineCount() > 0,
                     qPrintable(QStringLiteral("page height %1: '%2' not laid out").arg(height).arg(b.text())));
        }
        const auto pageOf = [height](qreal y) { return int(y / height); };
        QTextBlock lastHeading;
        QTextTable *lastTable = nullptr;
        for (QTextFrame::iterator it = document.rootFrame()->begin(); !it.atEnd(); ++it) {
            if (auto *table = qobject_cast<QTextTable *>(it.currentFrame())) {
                lastTable = table;
                const int rows = std::min(table->rows(), table->format().headerRowCount() + 2);
                const QTextBlock kept = table->cellAt(rows - 1, 0).lastCursorPosition().block();
                if (lastHeading.isValid()) {
                    QVERIFY2(pageOf(layout->blockBoundingRect(lastHeading).top()) == pageOf(layout->blockBoundingRect(kept).bottom() - 0.5),
                             qPrintable(QStringLiteral("page height %1: '%2' apart from its table").arg(height).arg(lastHeading.text())));
                }
                lastHeading = QTextBlock();
            } else if (it.currentBlock().blockFormat().headingLevel() > 0) {
                lastHeading = it.currentBlock();
            }
        }
        QVERIFY(lastTable);   // the signatures, whole on one page
        const qreal top = layout->frameBoundingRect(lastTable).top();
        const qreal bottom = layout->blockBoundingRect(lastTable->cellAt(lastTable->rows() - 1, 0).lastCursorPosition().block()).bottom();
        QVERIFY2(pageOf(top) == pageOf(bottom - 0.5), qPrintable(QStringLiteral("page height %1: signatures split").arg(height)));
    }
    QVERIFY(moved > 0);   // the check above had something to check
}

QTEST_MAIN(tst_CommissioningReport)
#include "tst_commissioningreport.moc"
