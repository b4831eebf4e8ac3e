// CRC16 and RTU framing against every example frame of the four manuals
// (tests/data/*-frames.tsv). The manuals' errata are named here: frames with a wrong
// CRC, a stated value that does not match the bytes, and register addresses that do
// not match the address tables.
#include "protocol/familyregistry.h"
#include "protocol/rtuframe.h"
#include "protocol/valuecodec.h"

#include <QFile>
#include <QSet>
#include <QTest>

using namespace jumo;

namespace {

struct Frame
{
    QString family;
    QString name;
    QByteArray bytes;
    bool crcOk = false;
    QString value;   // "float:12.34", "uint16:45", "text:IPC300", "-"
};

QList<Frame> allFrames()
{
    QList<Frame> frames;
    for (const QString family : {"ipc300", "tya200", "quantrol", "dtron300"}) {
        QFile file(QStringLiteral(JUMO_TEST_DATA_DIR "/%1-frames.tsv").arg(family));
        if (!file.open(QIODevice::ReadOnly))
            qFatal("cannot open %s", qPrintable(file.fileName()));
        const QList<QByteArray> lines = file.readAll().split('\n');
        for (qsizetype i = 1; i < lines.size(); ++i) {
            const QStringList f = QString::fromUtf8(lines[i]).split('\t');
            if (f.size() < 4)
                continue;
            frames << Frame{family, f[0], *RtuFrame::fromHex(f[1]), f[2] == "ok", f[3]};
        }
    }
    return frames;
}

QString baseName(const QString &name)
{
    for (const char *suffix : {"_request", "_response", "_instruction"}) {
        if (name.endsWith(QLatin1String(suffix)))
            return name.chopped(int(qstrlen(suffix)));
    }
    return name;
}

const FamilyRegistry &registry()
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return r;
}

// Errata of the manuals' example frames, named so a reader can find them.
const QSet<QString> wrongCrc{
    "quantrol/read_setpoints_sp1_sp2_response",                // 2.6.1 prints 4A93, correct 4A9E
    "quantrol/write_limit_1_alarm_value_low_word_instruction",   // 2.6.2: CRCs of address 0x0057
    "quantrol/write_limit_1_alarm_value_low_word_response",
    "quantrol/write_limit_1_alarm_value_high_word_instruction",  // and of 0x0058
    "quantrol/write_limit_1_alarm_value_high_word_response",
};
const QSet<QString> wrongValue{
    "ipc300/read_load_current_response",   // 3.1 states 12.24 A, the bytes are 12.34
};
const QSet<QString> wrongAddress{
    "ipc300/read_float_example_request",     // 4.1.2 reads a float at 0x0104, a bool in 5.2.7
    "tya200/read_load_current_request",      // 3.1 uses 0x003C, table 5.3 has 0x0102
    "tya200/write_external_inhibit_request", // 3.2 uses 0x0074, table 5.5 has 0x0147
    "tya200/write_external_inhibit_response",
    "tya200/write_setpoint_request",         // 3.3 uses 0x0044, table 5.3 has 0x010A
    "tya200/write_setpoint_response",
    "tya200/crc_example_read_request",       // 2.7 reads 0x00CE, defined on IPC 300 only
    "quantrol/crc_example_read_00ce_request",
    "quantrol/crc_example_read_00ce_response",
    "dtron300/crc_example_read_request",
};

} // namespace

Q_DECLARE_METATYPE(Frame)

class tst_RtuFrame : public QObject
{
    Q_OBJECT

    static void addFrameRows();

private slots:
    void crc16KnownValues();
    void crcOfManualFrames();
    void crcOfManualFrames_data() { addFrameRows(); }
    void frameLength();
    void frameLength_data() { addFrameRows(); }
    void statedValues();
    void statedValues_data() { addFrameRows(); }
    void addressesMatchTables();
    void addressesMatchTables_data() { addFrameRows(); }
    void buildAppendsCrcLowByteFirst();
    void rejectsShortAndCorruptFrames();
};

void tst_RtuFrame::crc16KnownValues()
{
    // Chapter 2.7 of IPC 300, TYA 200 and dTRON: CRC16 of 07 03 00 CE 00 02 is 0x92A5.
    QCOMPARE(RtuFrame::crc16(QByteArray::fromHex("070300CE0002")), quint16(0x92A5));
    QCOMPARE(RtuFrame::crc16(QByteArray::fromHex("070304000041C8")), quint16(0xF5AD));
    QCOMPARE(RtuFrame::crc16(QByteArray()), quint16(0xFFFF));
}

void tst_RtuFrame::addFrameRows()
{
    QTest::addColumn<Frame>("frame");
    for (const Frame &f : allFrames())
        QTest::addRow("%s %s", qPrintable(f.family), qPrintable(f.name)) << f;
}

void tst_RtuFrame::crcOfManualFrames()
{
    QFETCH(Frame, frame);
    const QString key = frame.family + '/' + frame.name;
    QCOMPARE(RtuFrame::hasValidCrc(frame.bytes), frame.crcOk);
    QCOMPARE(RtuFrame::hasValidCrc(frame.bytes), !wrongCrc.contains(key));
    // Rebuilding the frame gives the correct CRC whatever the manual printed.
    const QByteArray rebuilt = RtuFrame::build(quint8(frame.bytes[0]), frame.bytes.mid(1, frame.bytes.size() - 3));
    QVERIFY(RtuFrame::hasValidCrc(rebuilt));
    QCOMPARE(rebuilt.chopped(2), frame.bytes.chopped(2));
}

void tst_RtuFrame::frameLength()
{
    QFETCH(Frame, frame);
    const bool isResponse = frame.name.endsWith("_response");
    const auto direction = isResponse ? RtuFrame::Direction::Response : RtuFrame::Direction::Request;
    // A write-one-word response equals the request; the length rule is the same.
    QCOMPARE(RtuFrame::expectedLength(frame.bytes, direction), std::optional<int>(int(frame.bytes.size())));
    QCOMPARE(RtuFrame::expectedLength(frame.bytes.left(1), direction), std::nullopt);
}

void tst_RtuFrame::statedValues()
{
    QFETCH(Frame, frame);
    if (frame.value == "-")
        QSKIP("the manual states no value for this frame");
    const QString key = frame.family + '/' + frame.name;
    const RegisterMap &map = *registry().family(frame.family);
    const quint8 function = quint8(frame.bytes[1]);
    QList<quint16> words;
    int first = 0;
    int count = 0;
    if (function == 0x03 || function == 0x04) {
        first = 3;
        count = quint8(frame.bytes[2]) / 2;
    } else if (function == 0x06) {
        first = 4;
        count = 1;
    } else if (function == 0x10) {
        first = 7;
        count = quint8(frame.bytes[6]) / 2;
    }
    for (int i = 0; i < count; ++i)
        words << quint16(quint8(frame.bytes[first + 2 * i]) << 8 | quint8(frame.bytes[first + 2 * i + 1]));

    const QString type = frame.value.section(':', 0, 0);
    const QString stated = frame.value.section(':', 1);
    QStringList decoded;
    if (type == "float") {
        for (int i = 0; i + 1 < words.size(); i += 2)
            decoded << ValueCodec::formatFloat(ValueCodec::decodeFloat(words[i], words[i + 1], map.protocol.floatWordOrder));
    } else if (type == "uint16") {
        decoded << QString::number(words.value(0));
    } else if (type == "text") {
        RegisterEntry text;
        text.type = ValueType::Text;
        text.textBytes = int(words.size()) * 2;
        decoded << ValueCodec::decode(text, map, words).display;
    } else {
        QFAIL(qPrintable("unknown value type " + type));
    }
    QStringList expected;
    for (const QString &v : stated.split(','))
        expected << (type == "float" ? ValueCodec::formatFloat(v.toDouble()) : v);
    const bool matches = type == "text" ? decoded.join(',').trimmed() == expected.join(',').trimmed()
                                        : decoded == expected;
    QVERIFY2(matches != wrongValue.contains(key),
             qPrintable(QString("decoded %1, manual states %2").arg(decoded.join(','), expected.join(','))));
}

void tst_RtuFrame::addressesMatchTables()
{
    QFETCH(Frame, frame);
    const quint8 function = quint8(frame.bytes[1]);
    const bool isReadResponse = (function == 0x03 || function == 0x04) && frame.name.endsWith("_response");
    if (isReadResponse)
        QSKIP("a read response carries no address");
    const QString key = frame.family + '/' + frame.name;
    const RegisterMap &map = *registry().family(frame.family);
    const quint16 address = quint16(quint8(frame.bytes[2]) << 8 | quint8(frame.bytes[3]));
    const RegisterEntry *entry = map.entryAt(address);
    bool matches = entry && (entry->address == address || function == 0x06);

    // Compare the value type with what the frame (or its partner) says it carries.
    QString carried;
    for (const Frame &other : allFrames()) {
        if (other.family == frame.family && baseName(other.name) == baseName(frame.name) && other.value != "-")
            carried = other.value.section(':', 0, 0);
    }
    if (matches && carried == "float" && function != 0x06)
        matches = entry->type == ValueType::Float;

    QVERIFY2(matches != wrongAddress.contains(key),
             qPrintable(QString("address %1 -> %2").arg(formatAddress(address), entry ? entry->id : QString("nothing"))));
}

void tst_RtuFrame::buildAppendsCrcLowByteFirst()
{
    // IPC 300 3.1: 01 03 00 B1 00 02, CRC 0x2C94 sent as 94 2C.
    QCOMPARE(RtuFrame::build(0x01, QByteArray::fromHex("0300B10002")), QByteArray::fromHex("010300B10002942C"));
}

void tst_RtuFrame::rejectsShortAndCorruptFrames()
{
    QVERIFY(!RtuFrame::hasValidCrc(QByteArray::fromHex("0103")));
    QByteArray frame = QByteArray::fromHex("010300B10002942C");
    QVERIFY(RtuFrame::hasValidCrc(frame));
    frame[3] = char(0xB2);
    QVERIFY(!RtuFrame::hasValidCrc(frame));
    QCOMPARE(RtuFrame::expectedLength(QByteArray::fromHex("0183"), RtuFrame::Direction::Response), std::optional<int>(5));
    QCOMPARE(RtuFrame::expectedLength(QByteArray::fromHex("0142"), RtuFrame::Direction::Response), std::optional<int>(-1));
    QCOMPARE(RtuFrame::fromHex("01 0G"), std::nullopt);
}

QTEST_GUILESS_MAIN(tst_RtuFrame)
#include "tst_rtuframe.moc"
