// The built-in register maps hold every register and bit row of the manuals' address
// tables. The expected counts and rows in tests/data/*-rows.tsv were transcribed from
// the manuals separately from the map files, so a slip in either shows up here.
#include "protocol/familyregistry.h"
#include "protocol/valuecodec.h"

#include <QFile>
#include <QTest>

using namespace jumo;

namespace {

const FamilyRegistry &registry()
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return r;
}

struct ExpectedRow
{
    QStringList fields;   // kind, address, bit, type, access, label_word, section
};

QList<QStringList> readRows(const QString &family)
{
    QFile file(QStringLiteral(JUMO_TEST_DATA_DIR "/%1-rows.tsv").arg(family));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot open %s", qPrintable(file.fileName()));
    QList<QStringList> rows;
    const QList<QByteArray> lines = file.readAll().split('\n');
    for (qsizetype i = 1; i < lines.size(); ++i) {
        if (lines[i].trimmed().isEmpty())
            continue;
        rows << QString::fromUtf8(lines[i]).split('\t');
    }
    return rows;
}

QString sectionOf(const RegisterEntry &e)
{
    return e.group.section(' ', 0, 0);
}

const QStringList families{"ipc300", "tya200", "quantrol", "dtron300"};

} // namespace

class tst_RegisterMaps : public QObject
{
    Q_OBJECT

private slots:
    void sectionCounts_data();
    void sectionCounts();
    void namedRows_data();
    void namedRows();
    void familyFacts_data();
    void familyFacts();
    void errataAreCorrectedAndRecorded_data();
    void errataAreCorrectedAndRecorded();
    void everyEntryIsWellFormed_data();
    void everyEntryIsWellFormed();
    void pollClasses_data();
    void pollClasses();
};

void tst_RegisterMaps::sectionCounts_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QString>("section");
    QTest::addColumn<int>("registers");
    QTest::addColumn<int>("bits");
    for (const QString &family : families) {
        for (const QStringList &row : readRows(family)) {
            if (row.value(0) != "count")
                continue;
            QTest::addRow("%s %s", qPrintable(family), qPrintable(row.value(6)))
                    << family << row.value(6) << row.value(1).toInt() << row.value(2).toInt();
        }
    }
}

void tst_RegisterMaps::sectionCounts()
{
    QFETCH(QString, family);
    QFETCH(QString, section);
    QFETCH(int, registers);
    QFETCH(int, bits);
    const auto map = registry().family(family);
    QVERIFY(map);
    int foundRegisters = 0;
    int foundBits = 0;
    for (const RegisterEntry &e : map->entries()) {
        if (sectionOf(e) != section)
            continue;
        ++foundRegisters;
        foundBits += int(e.bits.size());
    }
    QCOMPARE(foundRegisters, registers);
    QCOMPARE(foundBits, bits);
}

void tst_RegisterMaps::namedRows_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QStringList>("row");
    for (const QString &family : families) {
        int totalExpected = 0;
        for (const QStringList &row : readRows(family)) {
            if (row.value(0) == "count")
                totalExpected += row.value(1).toInt();
            if (row.value(0) != "row")
                continue;
            const QString bit = row.value(2) == "-" ? QString() : " bit " + row.value(2);
            QTest::addRow("%s %s%s %s", qPrintable(family), qPrintable(row.value(1)), qPrintable(bit),
                          qPrintable(row.value(5)))
                    << family << row;
        }
        // The sections listed in the check list cover the whole map: no entry outside them.
        QTest::addRow("%s total", qPrintable(family)) << family << QStringList{"total", QString::number(totalExpected)};
    }
}

void tst_RegisterMaps::namedRows()
{
    QFETCH(QString, family);
    QFETCH(QStringList, row);
    const auto map = registry().family(family);
    QVERIFY(map);
    if (row.value(0) == "total") {
        QCOMPARE(map->entries().size(), row.value(1).toInt());
        return;
    }
    const quint16 address = quint16(row.value(1).mid(2).toUInt(nullptr, 16));
    const RegisterEntry *entry = nullptr;
    for (const RegisterEntry &e : map->entries()) {
        if (e.address == address && e.alias.isEmpty())
            entry = &e;
    }
    QVERIFY2(entry, qPrintable("no entry starts at " + row.value(1)));
    QCOMPARE(sectionOf(*entry), row.value(6));
    QString label = entry->label;
    if (row.value(2) != "-") {
        const int bitNumber = row.value(2).toInt();
        const BitDefinition *bit = nullptr;
        for (const BitDefinition &b : entry->bits) {
            if (b.bit == bitNumber)
                bit = &b;
        }
        QVERIFY2(bit, qPrintable(QString("no bit %1 at %2").arg(bitNumber).arg(row.value(1))));
        label = bit->label;
    } else {
        QCOMPARE(valueTypeName(entry->type), row.value(3));
        QCOMPARE(accessName(entry->access), row.value(4));
    }
    QVERIFY2(label.contains(row.value(5), Qt::CaseInsensitive),
             qPrintable(QString("label '%1' lacks '%2'").arg(label, row.value(5))));
}

void tst_RegisterMaps::familyFacts_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<int>("maxWords");
    QTest::addColumn<QString>("floatOrder");
    QTest::addColumn<QString>("int32Order");
    QTest::addColumn<QList<int>>("exceptionCodes");
    QTest::addColumn<bool>("hasErrorValues");
    QTest::addColumn<bool>("answers255");
    QTest::addColumn<QList<int>>("baudRates");
    QTest::addColumn<double>("processingMs");

    QTest::newRow("ipc300: 127 words, codes 1-8, error floats") << "ipc300" << 127 << "CDAB" << "ABCD"
            << QList<int>{1, 2, 3, 4, 6, 8} << true << true << QList<int>{9600, 19200, 38400} << 6.0;
    QTest::newRow("tya200: 127 words, codes 1-8, error floats") << "tya200" << 127 << "CDAB" << "ABCD"
            << QList<int>{1, 2, 3, 4, 6, 8} << true << true << QList<int>{9600, 19200, 38400} << 6.0;
    QTest::newRow("quantrol: 32 words, codes 1, 2, 8") << "quantrol" << 32 << "CDAB" << "ABCD"
            << QList<int>{1, 2, 8} << false << false << QList<int>{9600, 19200} << 250.0;
    QTest::newRow("dtron300: 32 words, LONG big-endian") << "dtron300" << 32 << "CDAB" << "ABCD"
            << QList<int>{1, 2, 8} << false << false << QList<int>{4800, 9600, 19200, 38400} << 250.0;
}

void tst_RegisterMaps::familyFacts()
{
    QFETCH(QString, family);
    QFETCH(int, maxWords);
    QFETCH(QString, floatOrder);
    QFETCH(QString, int32Order);
    QFETCH(QList<int>, exceptionCodes);
    QFETCH(bool, hasErrorValues);
    QFETCH(bool, answers255);
    QFETCH(QList<int>, baudRates);
    QFETCH(double, processingMs);
    const auto map = registry().family(family);
    QVERIFY(map);
    QCOMPARE(map->protocol.maxReadWords, maxWords);
    QCOMPARE(map->protocol.maxWriteWords, maxWords);
    QCOMPARE(wordOrderName(map->protocol.floatWordOrder), floatOrder);
    QCOMPARE(wordOrderName(map->protocol.int32WordOrder), int32Order);
    QCOMPARE(map->exceptions.keys(), exceptionCodes);
    QCOMPARE(map->errorValues.has_value(), hasErrorValues);
    QCOMPARE(map->protocol.alwaysAnswersAddress == 255, answers255);
    QList<int> bauds = map->protocol.baudRates;
    std::sort(bauds.begin(), bauds.end());
    QCOMPARE(bauds, baudRates);
    QCOMPARE(map->protocol.processingTimeMaxMs, processingMs);
    QVERIFY(!map->identify.isEmpty());
    QCOMPARE(map->protocol.busErrorTimeoutMs.has_value(), hasErrorValues);   // IPC/TYA: 10 s bus error
}

void tst_RegisterMaps::errataAreCorrectedAndRecorded_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QString>("id");
    QTest::addColumn<int>("address");
    QTest::addColumn<QString>("section");   // the erratum names the manual's section

    // IPC 300 5.2.7 lists "Wire break at voltage input" at 0x0000 between 0x00FF and 0x0101.
    QTest::newRow("ipc300 5.2.7 wire break voltage input at 0x0100") << "ipc300" << "" << 0x0100 << "5.2.7";
    // dTRON 5.6 puts Math 1/2 and Logic on top of the controller parameters at 0x3004..0x3008.
    QTest::newRow("dtron300 5.6 math 1 at 0x3204") << "dtron300" << "" << 0x3204 << "5.6";
    QTest::newRow("dtron300 5.6 math 2 at 0x3206") << "dtron300" << "" << 0x3206 << "5.6";
    QTest::newRow("dtron300 5.6 logic at 0x3208") << "dtron300" << "" << 0x3208 << "5.6";
    // TYA 200 5.8 lists a reserve word inside the float at 0x00EE.
    QTest::newRow("tya200 5.8 reserve inside float") << "tya200" << "reserve_00ef" << 0x00EF << "5.8";
    // Quantrol 4.6 lists "Bit 0" twice for the setpoint changeover.
    QTest::newRow("quantrol 4.6 setpoint changeover is an enum") << "quantrol" << "" << 0x004A << "4.6";
}

void tst_RegisterMaps::errataAreCorrectedAndRecorded()
{
    QFETCH(QString, family);
    QFETCH(QString, id);
    QFETCH(int, address);
    QFETCH(QString, section);
    const auto map = registry().family(family);
    QVERIFY(map);
    const RegisterEntry *entry = id.isEmpty() ? map->entryAt(quint16(address)) : map->entry(id);
    QVERIFY(entry);
    QCOMPARE(int(entry->address), address);
    QVERIFY2(!entry->erratum.isEmpty(), qPrintable(entry->id));
    QVERIFY2(entry->erratum.contains(section), qPrintable(entry->erratum));
}

void tst_RegisterMaps::everyEntryIsWellFormed_data()
{
    QTest::addColumn<QString>("family");
    for (const QString &f : families)
        QTest::newRow(qPrintable(f)) << f;
}

void tst_RegisterMaps::everyEntryIsWellFormed()
{
    QFETCH(QString, family);
    const auto map = registry().family(family);
    QVERIFY(map);
    for (const RegisterEntry &e : map->entries()) {
        // Command words carry their activation bit as a bit row of their own.
        if (e.activationMask) {
            bool listed = false;
            for (const BitDefinition &b : e.bits)
                listed |= b.mask() == *e.activationMask;
            QVERIFY2(listed, qPrintable(e.id));
        }
        // Every control must be something the codec can encode.
        if (!e.control.isEmpty())
            QVERIFY2(e.isWritable(), qPrintable(e.id));
        if (e.type == ValueType::Float)
            QCOMPARE(e.wordCount(), 2);
    }
}

void tst_RegisterMaps::pollClasses_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QString>("entry");
    QTest::addColumn<QString>("expected");
    QTest::newRow("ipc300 malfunction bits: alarm") << "ipc300" << "malfunction_signal_1" << "alarm";
    QTest::newRow("ipc300 faceplate mode word: alarm") << "ipc300" << "binary_signal_2" << "alarm";
    // The same state as a word of its own, which the faceplate takes from the bits.
    QTest::newRow("ipc300 manual mode word: live") << "ipc300" << "manual_mode_active" << "live";
    QTest::newRow("ipc300 load voltage: live") << "ipc300" << "load_voltage" << "live";
    QTest::newRow("ipc300 setpoint (RAM): setting") << "ipc300" << "input_setpoint" << "setting";
    QTest::newRow("ipc300 software version (text): setting") << "ipc300" << "software_version" << "setting";
    QTest::newRow("ipc300 nominal current (identity): setting") << "ipc300" << "nominal_current" << "setting";
    QTest::newRow("tya200 malfunction bits: alarm") << "tya200" << "malfunction_signals_3" << "alarm";
    QTest::newRow("tya200 faceplate mode bits: alarm") << "tya200" << "binary_signals_1" << "alarm";
    QTest::newRow("tya200 inputs: live") << "tya200" << "digital_input_1" << "live";
    QTest::newRow("dtron300 program state (warning bit): alarm") << "dtron300" << "program_status" << "alarm";
    QTest::newRow("dtron300 controller state (faceplate mode): alarm") << "dtron300" << "controller_status" << "alarm";
    QTest::newRow("dtron300 process value: live") << "dtron300" << "filtered_process_value" << "live";
    QTest::newRow("dtron300 EEPROM parameter: setting") << "dtron300" << "ps1_pb1" << "setting";
    QTest::newRow("dtron300 device format (identity): setting") << "dtron300" << "device_format" << "setting";
    QTest::newRow("dtron300 sampling time (map says setting)") << "dtron300" << "sampling_cycle_time" << "setting";
    QTest::newRow("quantrol limit monitoring: alarm") << "quantrol" << "limit_value_monitoring" << "alarm";
    QTest::newRow("quantrol sampling time (map says setting)") << "quantrol" << "sampling_time" << "setting";
}

void tst_RegisterMaps::pollClasses()
{
    QFETCH(QString, family);
    QFETCH(QString, entry);
    QFETCH(QString, expected);
    const RegisterEntry *e = registry().family(family)->entry(entry);
    QVERIFY(e);
    QCOMPARE(pollClassName(e->pollClass), expected);
}

QTEST_GUILESS_MAIN(tst_RegisterMaps)
#include "tst_registermaps.moc"
