// Numbers as an engineer writes them: the entry's precision (decimals or significant
// digits), the locale's decimal sign without thousands separators, the unit; and what a
// person types read back in the locale's way or with a dot, never a thousand times off.
#include "protocol/valueformat.h"

#include <QTest>

#include <cmath>

using namespace jumo;

namespace {

RegisterEntry floatEntry(const QString &unit, DisplayPrecision precision)
{
    RegisterEntry e;
    e.id = QStringLiteral("value");
    e.type = ValueType::Float;
    e.unit = unit;
    e.precision = precision;
    return e;
}

DecodedValue reading(const QVariant &value)
{
    DecodedValue v;
    v.status = ValueStatus::Ok;
    v.value = value;
    v.display = value.toString();
    return v;
}

const QLocale english(QLocale::English, QLocale::UnitedStates);
const QLocale german(QLocale::German, QLocale::Germany);

} // namespace

class tst_ValueFormat : public QObject
{
    Q_OBJECT

private slots:
    void number_data();
    void number();
    void rounded();
    void bitsByTheirLabels();
    void withUnit();
    void defaultsPerUnit();
    void limit();
    void parseNumber_data();
    void parseNumber();
};

void tst_ValueFormat::number_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<int>("kind");   // 0 decimals, 1 significant
    QTest::addColumn<int>("digits");
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("expected");
    QTest::newRow("a voltage to a tenth") << 91.94382 << 0 << 1 << "en" << "91.9";
    QTest::newRow("German decimal comma") << 91.94382 << 0 << 1 << "de" << "91,9";
    QTest::newRow("rounding up to a tenth") << 91.98382 << 0 << 1 << "en" << "92.0";
    QTest::newRow("current to four digits") << 19.99113 << 1 << 4 << "en" << "19.99";
    QTest::newRow("small current to four digits, as many decimals as zero") << 0.5123456 << 1 << 4 << "de" << "0,512";
    QTest::newRow("power to four digits") << 1838.42 << 1 << 4 << "en" << "1838";
    QTest::newRow("more whole digits than significant ones") << 12345.6 << 1 << 4 << "en" << "12346";
    QTest::newRow("rounding adds a digit in front") << 9.99962 << 1 << 4 << "en" << "10.00";
    QTest::newRow("zero to four digits") << 0.0 << 1 << 4 << "en" << "0.000";
    QTest::newRow("negative to four digits") << -0.0123456 << 1 << 4 << "en" << "-0.012";
    // 26.8: the precision first, then the sign: noise around zero is no four-digit reading.
    QTest::newRow("noise around zero is zero") << -0.00007528 << 1 << 4 << "en" << "0.000";
    QTest::newRow("noise around zero in German") << 0.00004 << 1 << 4 << "de" << "0,000";
    QTest::newRow("below zero's decimals, rounded to them") << -0.0007528 << 1 << 4 << "en" << "-0.001";
    QTest::newRow("no thousands separator in English") << 12345.6 << 0 << 1 << "en" << "12345.6";
    QTest::newRow("no thousands separator in German") << 12345.6 << 0 << 1 << "de" << "12345,6";
    QTest::newRow("a value rounding to zero has no sign") << -0.04 << 0 << 1 << "de" << "0,0";
    QTest::newRow("whole numbers") << 350.4 << 0 << 0 << "en" << "350";
    QTest::newRow("a negative value keeps its sign") << -12.34 << 0 << 1 << "de" << "-12,3";
}

void tst_ValueFormat::number()
{
    QFETCH(double, value);
    QFETCH(int, kind);
    QFETCH(int, digits);
    QFETCH(QString, language);
    QFETCH(QString, expected);
    const DisplayPrecision precision = kind == 0 ? DisplayPrecision::decimals(digits) : DisplayPrecision::significant(digits);
    QCOMPARE(ValueFormat::number(value, precision, language == "de" ? german : english), expected);
}

void tst_ValueFormat::rounded()
{
    // As the text reads: a bar or an arrow drawn from it says the same.
    QCOMPARE(ValueFormat::rounded(-0.00007528, DisplayPrecision::significant(4)), 0.0);
    QVERIFY(!std::signbit(ValueFormat::rounded(-0.00007528, DisplayPrecision::significant(4))));
    QCOMPARE(ValueFormat::rounded(19.99113, DisplayPrecision::significant(4)), 19.99);
    QCOMPARE(ValueFormat::rounded(1838.42, DisplayPrecision::significant(4)), 1838.0);
    QCOMPARE(ValueFormat::rounded(-0.04, DisplayPrecision::decimals(1)), 0.0);
    QCOMPARE(ValueFormat::rounded(91.94382, DisplayPrecision::decimals(1)), 91.9);
}

void tst_ValueFormat::bitsByTheirLabels()
{
    // 26.10: people read the manual's words, never the map's ids ("0x0004 (program_stop)").
    RegisterEntry status;
    status.id = QStringLiteral("program_status");
    status.type = ValueType::Bitfield;
    auto bit = [](int at, int width, const QString &id, const QString &label, bool reserved = false) {
        BitDefinition b;
        b.bit = at;
        b.width = width;
        b.id = id;
        b.label = label;
        b.reserved = reserved;
        return b;
    };
    status.bits = {bit(1, 1, "program_pause", "Program pause"), bit(2, 1, "program_stop", "Basic status/Program stop"),
                   bit(3, 1, "spare", "Spare", true), bit(8, 8, "slot_1", "Slot 1")};
    QCOMPARE(ValueFormat::bits(0x0004, status), QString("0x0004 (Basic status/Program stop, Slot 1: 0)"));
    QCOMPARE(ValueFormat::bits(0x0A06, status), QString("0x0A06 (Program pause, Basic status/Program stop, Slot 1: 10)"));
    status.bits.removeLast();
    QCOMPARE(ValueFormat::bits(0x0008, status), QString("0x0008 (none set)"));   // a reserved bit is no state
    DecodedValue word = reading(qint64(4));
    word.raw = 4;
    word.display = QStringLiteral("0x0004 (program_stop)");
    QCOMPARE(ValueFormat::withUnit(word, status, english), QString("0x0004 (Basic status/Program stop)"));
}

void tst_ValueFormat::withUnit()
{
    QCOMPARE(ValueFormat::withUnit(reading(91.94382), floatEntry("V", DisplayPrecision::decimals(1)), german),
             QString("91,9 V"));
    QCOMPARE(ValueFormat::withUnit(reading(45.0), floatEntry("%", DisplayPrecision::decimals(1)), english),
             QString("45.0 %"));
    QCOMPARE(ValueFormat::withUnit(reading(37.54), floatEntry("°", DisplayPrecision::decimals(1)), german),
             QString("37,5°"));
    // A unit set on the device has no symbol to show.
    RegisterEntry pv = floatEntry(QString(), DisplayPrecision::decimals(1));
    pv.configuredUnit = "process_value";
    QCOMPARE(ValueFormat::withUnit(reading(93.74566), pv, german), QString("93,7"));
    // Integers whole, in the locale's way, with their unit.
    RegisterEntry seconds;
    seconds.type = ValueType::Int32;
    seconds.unit = "s";
    QCOMPARE(ValueFormat::withUnit(reading(qint64(12345)), seconds, german), QString("12345 s"));
    // An error value is what it is, never a number with a unit.
    DecodedValue over;
    over.status = ValueStatus::Overrange;
    over.display = "Overrange";
    QCOMPARE(ValueFormat::withUnit(over, floatEntry("A", DisplayPrecision::significant(4)), german), QString("Overrange"));
    // Enums and texts as decoded.
    RegisterEntry mode;
    mode.type = ValueType::Enum;
    DecodedValue on = reading(qint64(1));
    on.display = "On";
    QCOMPARE(ValueFormat::withUnit(on, mode, german), QString("On"));
}

void tst_ValueFormat::defaultsPerUnit()
{
    QCOMPARE(DisplayPrecision::defaultForUnit("V"), DisplayPrecision::decimals(1));
    QCOMPARE(DisplayPrecision::defaultForUnit("A"), DisplayPrecision::significant(4));
    QCOMPARE(DisplayPrecision::defaultForUnit("Ω"), DisplayPrecision::significant(4));
    QCOMPARE(DisplayPrecision::defaultForUnit("%"), DisplayPrecision::decimals(1));
    QCOMPARE(DisplayPrecision::defaultForUnit("Hz"), DisplayPrecision::decimals(2));
    QCOMPARE(DisplayPrecision::defaultForUnit(""), DisplayPrecision::decimals(1));
    QCOMPARE(DisplayPrecision::defaultForUnit("bar"), DisplayPrecision::significant(4));
    QCOMPARE(DisplayPrecision::significant(4).name(), QString("significant:4"));
    QCOMPARE(DisplayPrecision::decimals(1).name(), QString("decimals:1"));
}

void tst_ValueFormat::limit()
{
    const RegisterEntry percent = floatEntry("%", DisplayPrecision::decimals(1));
    QCOMPARE(ValueFormat::limit(100, percent, german), QString("100,0"));
    // A limit is exact even where values show fewer digits.
    const RegisterEntry whole = floatEntry("W", DisplayPrecision::decimals(0));
    QCOMPARE(ValueFormat::limit(0.5, whole, german), QString("0,5"));
    RegisterEntry integer;
    integer.type = ValueType::Int16;
    QCOMPARE(ValueFormat::limit(-1999, integer, english), QString("-1999"));
}

void tst_ValueFormat::parseNumber_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("expected");   // empty: refused
    QTest::newRow("German comma") << "de" << "42,5" << "42.5";
    QTest::newRow("German with a dot") << "de" << "42.5" << "42.5";
    QTest::newRow("German 1.500 is 1500 or 1.5: refused") << "de" << "1.500" << "";
    QTest::newRow("German 12.345 is grouped or not: refused") << "de" << "-12.345" << "";
    QTest::newRow("German 1.5 with a dot is no grouping") << "de" << "1.5" << "1.5";
    QTest::newRow("German 1.5000 with a dot is no grouping") << "de" << "1.5000" << "1.5";
    QTest::newRow("German 1,5e3") << "de" << "1,5e3" << "1500";
    QTest::newRow("English 1.500 is one and a half") << "en" << "1.500" << "1.5";
    QTest::newRow("German thousands grouping refused as grouping") << "de" << "1.500,5" << "";
    QTest::newRow("English dot") << "en" << "42.5" << "42.5";
    QTest::newRow("English comma is no decimal sign") << "en" << "42,5" << "";
    QTest::newRow("English thousands grouping refused") << "en" << "1,500" << "";
    QTest::newRow("negative German") << "de" << "-0,25" << "-0.25";
    QTest::newRow("spaces around") << "de" << " 7,5 " << "7.5";
    QTest::newRow("exponent") << "en" << "1e3" << "1000";
    QTest::newRow("a word") << "de" << "viel" << "";
    QTest::newRow("empty") << "en" << "" << "";
}

void tst_ValueFormat::parseNumber()
{
    QFETCH(QString, language);
    QFETCH(QString, typed);
    QFETCH(QString, expected);
    const std::optional<QString> parsed = ValueFormat::parseNumber(typed, language == "de" ? german : english);
    QCOMPARE(parsed.value_or(QString()), expected);
}

QTEST_APPLESS_MAIN(tst_ValueFormat)
#include "tst_valueformat.moc"
