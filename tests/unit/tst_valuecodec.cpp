// Value codecs reproduce the manuals' example values byte-exact, in both directions,
// and classify the devices' float error values.
#include "protocol/familyregistry.h"
#include "protocol/valuecodec.h"

#include <QTest>

#include <cmath>

using namespace jumo;

namespace {

const RegisterMap &family(const QString &id)
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    const auto map = r.family(id);
    if (!map)
        qFatal("family %s missing", qPrintable(id));
    return *map;
}

QList<quint16> words(std::initializer_list<quint16> list) { return QList<quint16>(list); }

} // namespace

class tst_ValueCodec : public QObject
{
    Q_OBJECT

private slots:
    void wordOrders_data();
    void wordOrders();
    void manualExamples_data();
    void manualExamples();
    void floatErrorValues_data();
    void floatErrorValues();
    void encodeRefusesBadInput_data();
    void encodeRefusesBadInput();
    void encodeCommandWordsAddActivation();
    void overrideAcceptsRestoreValue();
    void decodeRefusesWrongWordCount();
    void floatExtremesRoundTrip_data();
    void floatExtremesRoundTrip();
};

void tst_ValueCodec::wordOrders_data()
{
    QTest::addColumn<QString>("order");
    QTest::addColumn<quint16>("first");
    QTest::addColumn<quint16>("second");
    QTest::newRow("ABCD big-endian") << "ABCD" << quint16(0x1122) << quint16(0x3344);
    QTest::newRow("CDAB low word first") << "CDAB" << quint16(0x3344) << quint16(0x1122);
    QTest::newRow("BADC bytes swapped") << "BADC" << quint16(0x2211) << quint16(0x4433);
    QTest::newRow("DCBA little-endian") << "DCBA" << quint16(0x4433) << quint16(0x2211);
}

void tst_ValueCodec::wordOrders()
{
    QFETCH(QString, order);
    QFETCH(quint16, first);
    QFETCH(quint16, second);
    const WordOrder o = *wordOrderFromName(order);
    QCOMPARE(ValueCodec::splitWords(0x11223344u, o), words({first, second}));
    QCOMPARE(ValueCodec::joinWords(first, second, o), 0x11223344u);
}

void tst_ValueCodec::manualExamples_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QString>("id");
    QTest::addColumn<QList<quint16>>("registerWords");
    QTest::addColumn<QString>("text");   // the value as the manual states it

    // Floats are CDAB in all four manuals: register x holds the low word.
    QTest::newRow("ipc300 4.1.2 550.0 = 0x44098000") << "ipc300" << "load_voltage" << words({0x8000, 0x4409}) << "550";
    QTest::newRow("ipc300 3.3 setpoint 12.34") << "ipc300" << "input_setpoint" << words({0x70A3, 0x4145}) << "12.34";
    QTest::newRow("ipc300 3.1 load current bytes 70A3 4145 (stated 12.24: erratum)")
            << "ipc300" << "load_current" << words({0x70A3, 0x4145}) << "12.34";
    QTest::newRow("ipc300 4.1.1 integer 45") << "ipc300" << "internal_software_version" << words({0x002D}) << "45";
    QTest::newRow("ipc300 4.1.3 device name IPC300")
            << "ipc300" << "device_name" << words({0x4950, 0x4333, 0x3030, 0x2020, 0x0000}) << "IPC300  ";
    QTest::newRow("tya200 4.1.3 device name TYA 200")
            << "tya200" << "device_name" << words({0x5459, 0x4120, 0x3230, 0x3020, 0x0000}) << "TYA 200 ";
    QTest::newRow("tya200 3.3 setpoint 12.34") << "tya200" << "setpoint" << words({0x70A3, 0x4145}) << "12.34";
    QTest::newRow("quantrol 2.6.1 SP1 25.0") << "quantrol" << "setpoint_sp1" << words({0x0000, 0x41C8}) << "25";
    QTest::newRow("quantrol 2.6.1 SP2 10.0") << "quantrol" << "setpoint_sp2" << words({0x0000, 0x4120}) << "10";
    QTest::newRow("quantrol 2.6.2 AL1 275.0") << "quantrol" << "limit_1_alarm_value" << words({0x8000, 0x4389}) << "275";
    QTest::newRow("quantrol 2.7.2 setpoint 550.0") << "quantrol" << "controller_setpoint" << words({0x8000, 0x4409}) << "550";
    QTest::newRow("quantrol 2.7.1 binary outputs 4") << "quantrol" << "binary_outputs" << words({0x0004})
                                                    << "0x0004 (output_k3)";
    QTest::newRow("dtron300 4 float 3000 = 80 00 45 3B") << "dtron300" << "setpoint_w1" << words({0x8000, 0x453B}) << "3000";
    QTest::newRow("dtron300 4 long 66051 = 00 01 02 03") << "dtron300" << "program_run_time" << words({0x0001, 0x0203})
                                                        << "66051";
    QTest::newRow("dtron300 3.3 Pb1 of parameter set 2 = 20") << "dtron300" << "ps2_pb1" << words({0x0000, 0x41A0}) << "20";
    QTest::newRow("quantrol enum setpoint 2") << "quantrol" << "setpoint_changeover" << words({0x0001}) << "Setpoint 2";
}

void tst_ValueCodec::manualExamples()
{
    QFETCH(QString, family);
    QFETCH(QString, id);
    QFETCH(QList<quint16>, registerWords);
    QFETCH(QString, text);
    const RegisterMap &map = ::family(family);
    const RegisterEntry *entry = map.entry(id);
    QVERIFY2(entry, qPrintable(id));

    const DecodedValue decoded = ValueCodec::decode(*entry, map, registerWords);
    QCOMPARE(decoded.status, ValueStatus::Ok);
    QCOMPARE(decoded.display, text);

    // And back, byte-exact. Floats are written with all the digits the float holds: the
    // manuals' 12.34 is 0x414570A3 = 12.3399992, one step below the float nearest to
    // 12.34 (0x414570A4), so typing "12.34" writes a value that reads back as 12.34 but
    // differs from the manual's bytes in the last bit.
    QString exact = text;
    if (entry->type == ValueType::Float) {
        const float f = ValueCodec::decodeFloat(registerWords[0], registerWords[1], map.protocol.floatWordOrder);
        exact = QString::number(double(f), 'g', 9);
        const QList<quint16> typed = ValueCodec::encodeFloat(text.toFloat(), map.protocol.floatWordOrder);
        QVERIFY(qAbs(int(typed[0]) - int(registerWords[0])) <= 1);
        QCOMPARE(typed[1], registerWords[1]);
    }
    if (entry->isWritable() && entry->type != ValueType::Bitfield) {
        const EncodeResult encoded = ValueCodec::encode(*entry, map, exact);
        QVERIFY2(encoded.ok(), qPrintable(encoded.error));
        QCOMPARE(encoded.words, registerWords);
    } else if (entry->type == ValueType::Float) {
        QCOMPARE(ValueCodec::encodeFloat(exact.toFloat(), map.protocol.floatWordOrder), registerWords);
    } else if (entry->type == ValueType::Int32) {
        QCOMPARE(ValueCodec::splitWords(exact.toUInt(), map.protocol.int32WordOrder), registerWords);
    }
}

void tst_ValueCodec::floatErrorValues_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QList<quint16>>("registerWords");
    QTest::addColumn<int>("status");
    QTest::addColumn<QString>("display");
    QTest::addColumn<QString>("statusName");

    QTest::newRow("ipc300 0xFF800000 -Inf underrange") << "ipc300" << words({0x0000, 0xFF80})
                                                       << int(ValueStatus::Underrange) << "Underrange" << "underrange";
    QTest::newRow("ipc300 0x7F800000 +Inf overrange") << "ipc300" << words({0x0000, 0x7F80})
                                                      << int(ValueStatus::Overrange) << "Overrange" << "overrange";
    QTest::newRow("ipc300 0x7FC00000 NaN invalid") << "ipc300" << words({0x0000, 0x7FC0})
                                                   << int(ValueStatus::Invalid) << "Invalid" << "invalid";
    QTest::newRow("tya200 other NaN pattern invalid") << "tya200" << words({0x0001, 0x7FC0})
                                                      << int(ValueStatus::Invalid) << "Invalid" << "invalid";
    QTest::newRow("ipc300 0xFF800000 in the wrong word order is a number")
            << "ipc300" << words({0xFF80, 0x0000}) << int(ValueStatus::Ok) << "9.165613e-41" << "ok";
}

void tst_ValueCodec::floatErrorValues()
{
    QFETCH(QString, family);
    QFETCH(QList<quint16>, registerWords);
    QFETCH(int, status);
    QFETCH(QString, display);
    QFETCH(QString, statusName);
    const RegisterMap &map = ::family(family);
    const RegisterEntry *entry = map.entry("load_current");
    QVERIFY(entry);
    const DecodedValue v = ValueCodec::decode(*entry, map, registerWords);
    QCOMPARE(int(v.status), status);
    QCOMPARE(v.display, display);
    QCOMPARE(valueStatusName(v.status), statusName);
    if (v.status != ValueStatus::Ok) {
        QVERIFY(!v.value.isValid());   // never a number for an error value
        QVERIFY(!ValueCodec::statusDescription(v.status, map).isEmpty());
        QVERIFY(ValueCodec::statusDescription(v.status, map) != v.display);   // the manual's own wording
    }
}

void tst_ValueCodec::encodeRefusesBadInput_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<QString>("id");
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("problem");

    QTest::newRow("setpoint above 100 %") << "ipc300" << "input_setpoint" << "100.5" << "outside the range";
    QTest::newRow("setpoint below 0 %") << "tya200" << "setpoint" << "-1" << "outside the range";
    QTest::newRow("alpha above 180 degrees") << "tya200" << "alpha_default" << "181" << "outside the range";
    QTest::newRow("not a number") << "ipc300" << "input_setpoint" << "12,5x" << "is not a number";
    QTest::newRow("infinity is no setpoint") << "ipc300" << "input_setpoint" << "inf" << "is not a number";
    QTest::newRow("read-only entry") << "ipc300" << "load_current" << "1" << "read-only";
    QTest::newRow("bool 2") << "ipc300" << "digital_output" << "2" << "not a boolean";
    QTest::newRow("enum value not defined") << "quantrol" << "setpoint_changeover" << "2" << "is not a value of";
    QTest::newRow("enum label not defined") << "quantrol" << "setpoint_changeover" << "Setpoint 3" << "is not a value of";
    QTest::newRow("int16 overflow") << "quantrol" << "controller_y0" << "40000" << "does not fit";
    QTest::newRow("unknown bit") << "quantrol" << "binary_output_control" << "output_k9" << "is not a bit of";
    QTest::newRow("override below -1999") << "quantrol" << "ram_controller_setpoint" << "-2000" << "outside the range";
    // Integers as a whole text: Qt's own parsers took these.
    QTest::newRow("hex with a sign") << "dtron300" << "manual_output" << "0x-1" << "is not a whole number";
    QTest::newRow("hex prefix twice") << "dtron300" << "manual_output" << "0x0x7F" << "is not a whole number";
    QTest::newRow("sign after a sign") << "dtron300" << "manual_output" << "+-1" << "is not a whole number";
    QTest::newRow("no bit between the plus signs") << "dtron300" << "controller_functions" << "+" << "is not a bit of";
    QTest::newRow("an empty bit") << "dtron300" << "controller_functions" << "automatic_mode++controller_off"
                                  << "is not a bit of";
    QTest::newRow("beyond the largest float") << "dtron300" << "setpoint" << "3.4028236e38" << "too large for a float";
}

void tst_ValueCodec::encodeRefusesBadInput()
{
    QFETCH(QString, family);
    QFETCH(QString, id);
    QFETCH(QString, input);
    QFETCH(QString, problem);
    const RegisterMap &map = ::family(family);
    const RegisterEntry *entry = map.entry(id);
    QVERIFY2(entry, qPrintable(id));
    const EncodeResult r = ValueCodec::encode(*entry, map, input);
    QVERIFY(!r.ok());
    QVERIFY(r.words.isEmpty());
    QVERIFY2(r.error.contains(problem), qPrintable(r.error));
}

void tst_ValueCodec::encodeCommandWordsAddActivation()
{
    const RegisterMap &q = family("quantrol");
    // Quantrol 4.2: output K1 = 0x8001, K2 = 0x8002.
    QCOMPARE(ValueCodec::encode(*q.entry("binary_output_control"), q, "output_k1").words, words({0x8001}));
    QCOMPARE(ValueCodec::encode(*q.entry("binary_output_control"), q, "output_k1+output_k2").words, words({0x8003}));
    const RegisterMap &d = family("dtron300");
    // dTRON 5.6: Logic 1 = 0x0081, Logic 2 = 0x0082.
    QCOMPARE(ValueCodec::encode(*d.entry("logic_1_2"), d, "logic_1").words, words({0x0081}));
    QCOMPARE(ValueCodec::encode(*d.entry("logic_1_2"), d, "logic_2").words, words({0x0082}));
    // dTRON 5.1: output 10 = 0x8200.
    QCOMPARE(ValueCodec::encode(*d.entry("binary_output_control"), d, "output_10").words, words({0x8200}));
}

void tst_ValueCodec::overrideAcceptsRestoreValue()
{
    const RegisterMap &q = family("quantrol");
    const RegisterEntry *e = q.entry("ram_controller_setpoint");
    QVERIFY(e);
    const EncodeResult r = ValueCodec::encode(*e, q, "200001");
    QVERIFY2(r.ok(), qPrintable(r.error));
    QCOMPARE(ValueCodec::decodeFloat(r.words[0], r.words[1], q.protocol.floatWordOrder), 200001.0f);
}

void tst_ValueCodec::decodeRefusesWrongWordCount()
{
    const RegisterMap &m = family("ipc300");
    const DecodedValue v = ValueCodec::decode(*m.entry("load_current"), m, words({0x70A3}));
    QCOMPARE(v.status, ValueStatus::DecodeError);
    QVERIFY(!v.value.isValid());
}

void tst_ValueCodec::floatExtremesRoundTrip_data()
{
    QTest::addColumn<float>("value");
    QTest::newRow("largest") << std::numeric_limits<float>::max();
    QTest::newRow("largest negative") << -std::numeric_limits<float>::max();
    QTest::newRow("smallest normal") << std::numeric_limits<float>::min();
    QTest::newRow("smallest denormal") << std::numeric_limits<float>::denorm_min();
    QTest::newRow("a third") << 1.0f / 3.0f;
}

void tst_ValueCodec::floatExtremesRoundTrip()
{
    // What a device reports is saved as exactText() and must encode to the same words.
    QFETCH(float, value);
    const RegisterMap &d = family("dtron300");
    const RegisterEntry &setpoint = *d.entry("setpoint");   // a float without a range
    const QList<quint16> reported = ValueCodec::encodeFloat(value, d.protocol.floatWordOrder);
    const QString saved = ValueCodec::exactText(setpoint, d, reported);
    const EncodeResult back = ValueCodec::encode(setpoint, d, saved);
    QVERIFY2(back.ok(), qPrintable(saved + ": " + back.error));
    QCOMPARE(back.words, reported);
}

QTEST_GUILESS_MAIN(tst_ValueCodec)
#include "tst_valuecodec.moc"
