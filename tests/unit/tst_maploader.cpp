// The map loader accepts good maps and refuses each kind of bad one with a message
// that names the file, the entry and the problem.
#include "protocol/familyregistry.h"
#include "protocol/maploader.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <functional>

#include <sys/stat.h>

using namespace jumo;

namespace {

QJsonObject validMap()
{
    return QJsonObject{
        {"format", 1},
        {"family", "testdev"},
        {"name", "Test device"},
        {"models", QJsonArray{"T1"}},
        {"manual", "none"},
        {"protocol",
         QJsonObject{{"readFunctions", QJsonArray{3, 4}}, {"writeFunctions", QJsonArray{6, 16}},
                     {"maxReadWords", 32}, {"maxWriteWords", 32}, {"floatWordOrder", "CDAB"},
                     {"int32WordOrder", "ABCD"}, {"baudRates", QJsonArray{9600}}, {"dataFormats", QJsonArray{"8N1"}},
                     {"addressMin", 1}, {"addressMax", 254}, {"alwaysAnswersAddress", QJsonValue()},
                     {"broadcast", true}, {"processingTimeMaxMs", 250}, {"turnaroundMs", 10},
                     {"busErrorTimeoutMs", QJsonValue()}}},
        {"identify", QJsonArray{QJsonObject{{"address", "0x0000"}, {"words", 1}, {"answers", true}}}},
        {"exceptions", QJsonObject{{"2", "Invalid address"}}},
        {"errorValues", QJsonValue()},
        {"entries",
         QJsonArray{
             QJsonObject{{"address", "0x0000"}, {"id", "value_a"}, {"label", "Value A"}, {"type", "float"},
                         {"access", "R"}, {"group", "1 Test"}},
             QJsonObject{{"address", "0x0002"}, {"id", "mode"}, {"label", "Mode"}, {"type", "enum"},
                         {"access", "RW"}, {"storage", "EEPROM"}, {"group", "1 Test"},
                         {"values", QJsonObject{{"0", "Off"}, {"1", "On"}}}},
             QJsonObject{{"address", "0x0003"}, {"id", "alarms"}, {"label", "Alarms"}, {"type", "bitfield"},
                         {"access", "R"}, {"group", "1 Test"},
                         {"bits", QJsonArray{QJsonObject{{"bit", 0}, {"id", "low"}, {"label", "Low"}, {"kind", "alarm"}},
                                             QJsonObject{{"bit", 15}, {"id", "high"}, {"label", "High"}, {"kind", "warning"}}}}},
             QJsonObject{{"address", "0x0004"}, {"id", "name"}, {"label", "Name"}, {"type", "text"}, {"bytes", 9},
                         {"access", "R"}, {"group", "1 Test"}},
         }},
    };
}

void editEntry(QJsonObject &map, int index, const std::function<void(QJsonObject &)> &edit)
{
    QJsonArray entries = map.value("entries").toArray();
    QJsonObject e = entries.at(index).toObject();
    edit(e);
    entries.replace(index, e);
    map.insert("entries", entries);
}

using Mutation = std::function<void(QJsonObject &)>;

// Sets one key of the protocol object.
Mutation protocolField(const QString &key, const QJsonValue &value)
{
    return [key, value](QJsonObject &m) {
        QJsonObject p = m["protocol"].toObject();
        p[key] = value;
        m["protocol"] = p;
    };
}

void appendEntry(QJsonObject &map, const QJsonObject &entry)
{
    QJsonArray entries = map.value("entries").toArray();
    entries.append(entry);
    map.insert("entries", entries);
}

} // namespace

Q_DECLARE_METATYPE(Mutation)

class tst_MapLoader : public QObject
{
    Q_OBJECT

private slots:
    void acceptsValidMap();
    void refusesBadMap_data();
    void refusesBadMap();
    void refusesMalformedJson();
    void refusesAKeyGivenTwice();
    void precisionFromTheMapOrTheUnit();
    void defaultsAreRead();
    void pollClassesFromTheMap_data();
    void pollClassesFromTheMap();
    void builtinMapsLoad();
    void faceplateFromTheMap();
    void userFolderReplacesBuiltinAndReportsBrokenFiles();
    void twoUserFilesOfOneFamilyAreRefused();
    void overlapsAreReportedOncePerGroup();
    void onlyRegularFilesAreRead();
    void aFolderNamedTwiceIsReadOnce();
};

void tst_MapLoader::acceptsValidMap()
{
    const MapLoadResult r = MapLoader::loadData(QJsonDocument(validMap()).toJson(), "test.json");
    QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
    QCOMPARE(r.map->entries().size(), 4);
    QCOMPARE(r.map->entry("name")->wordCount(), 5);
    QCOMPARE(r.map->entryAt(0x0001)->id, QString("value_a"));
    QCOMPARE(r.map->entryAt(0x0008)->id, QString("name"));
    QVERIFY(r.map->entryAt(0x0009) == nullptr);
}

void tst_MapLoader::refusesBadMap_data()
{
    QTest::addColumn<Mutation>("mutation");
    QTest::addColumn<QString>("entry");     // what the message must name
    QTest::addColumn<QString>("problem");   // and the problem it must state

    QTest::newRow("unknown type") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["type"] = "double"; });
    }) << "entry 'value_a' (0x0000)" << "unknown type 'double'";
    QTest::newRow("unknown poll class") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["poll"] = "often"; });
    }) << "entry 'value_a' (0x0000)" << "unknown poll class 'often'";
    QTest::newRow("poll class of a write-only entry") << Mutation([](QJsonObject &m) {
        editEntry(m, 1, [](QJsonObject &e) {
            e["access"] = "W";
            e["poll"] = "alarm";
        });
    }) << "entry 'mode' (0x0002)" << "'poll' is only for entries that are read";
    QTest::newRow("duplicate id") << Mutation([](QJsonObject &m) {
        editEntry(m, 3, [](QJsonObject &e) { e["id"] = "mode"; });
    }) << "entry 'mode' (0x0004)" << "duplicate id";
    QTest::newRow("bit above 15") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", 16}, {"id", "x"}, {"label", "X"}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit 16" << "'bit' must be a whole number 0..15, not 16";
    QTest::newRow("negative bit") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", -1}, {"id", "x"}, {"label", "X"}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit -1" << "'bit' must be a whole number 0..15, not -1";
    QTest::newRow("bit defined twice") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", 3}, {"id", "x"}, {"label", "X"}, {"kind", "alarm"}},
                                   QJsonObject{{"bit", 3}, {"id", "y"}, {"label", "Y"}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit 3" << "bit defined twice";
    // A user map whose labels or bounds would make a write send another value.
    QTest::newRow("enum label that is another value's number") << Mutation([](QJsonObject &m) {
        editEntry(m, 1, [](QJsonObject &e) { e["values"] = QJsonObject{{"0", "1"}, {"1", "0"}}; });
    }) << "entry 'mode' (0x0002)" << "'values': the label '1' of 0 would be written as 1";
    QTest::newRow("enum labels differing in case only") << Mutation([](QJsonObject &m) {
        editEntry(m, 1, [](QJsonObject &e) { e["values"] = QJsonObject{{"0", "On"}, {"1", "on"}}; });
    }) << "entry 'mode' (0x0002)" << "'values': the label 'On' of 0 would be written as 1";
    QTest::newRow("stateFrom without a bit") << Mutation([](QJsonObject &m) {
        appendEntry(m, QJsonObject{{"address", "0x0010"}, {"id", "switches"}, {"label", "Switches"}, {"type", "bitfield"},
                                   {"access", "W"}, {"group", "1 Test"},
                                   {"bits", QJsonArray{QJsonObject{{"bit", 0}, {"id", "low"}, {"label", "Low"},
                                                                   {"kind", "command"}, {"stateFrom", "alarms"}}}}});
    }) << "entry 'switches', bit 0" << "'stateFrom' must name a single bit as ENTRY.BIT, not 'alarms'";
    QTest::newRow("action on a float") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) {
            e["access"] = "RW";
            e["action"] = true;
        });
    }) << "entry 'value_a' (0x0000)" << "'action' is for command words (bit fields, enums, integers), not for a float";
    QTest::newRow("min below what the type holds") << Mutation([](QJsonObject &m) {
        appendEntry(m, QJsonObject{{"address", "0x0010"}, {"id", "count"}, {"label", "Count"}, {"type", "uint16"},
                                   {"access", "RW"}, {"group", "1 Test"}, {"min", -5}});
    }) << "entry 'count' (0x0010)" << "'min' -5 is outside what a uint16 holds (0..65535)";
    QTest::newRow("max above what the type holds") << Mutation([](QJsonObject &m) {
        appendEntry(m, QJsonObject{{"address", "0x0010"}, {"id", "offset"}, {"label", "Offset"}, {"type", "int16"},
                                   {"access", "RW"}, {"group", "1 Test"}, {"max", 40000}});
    }) << "entry 'offset' (0x0010)" << "'max' 40000 is outside what a int16 holds (-32768..32767)";
    QTest::newRow("max beyond a float") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["max"] = 1e39; });
    }) << "entry 'value_a' (0x0000)" << "'max' 1e+39 is outside what a float holds";
    QTest::newRow("escape sequence in a label") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["label"] = QString("Value \x1b[2J"); });
    }) << "entry 'value_a' (0x0000)" << "'label' contains a control character (U+001b)";
    QTest::newRow("line end in a unit") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["unit"] = QString("V\nA"); });
    }) << "entry 'value_a' (0x0000)" << "'unit' contains a control character (U+000a)";
    QTest::newRow("control character in an enum label") << Mutation([](QJsonObject &m) {
        editEntry(m, 1, [](QJsonObject &e) { e["values"] = QJsonObject{{"0", "Off"}, {"1", QString("O\rn")}}; });
    }) << "entry 'mode' (0x0002)" << "'values' contains a control character (U+000d)";
    QTest::newRow("control character in a bit's label") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", 0}, {"id", "low"}, {"label", QString("Lo\tw")}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit 0" << "'label' contains a control character (U+0009)";
    QTest::newRow("overlapping words") << Mutation([](QJsonObject &m) {
        appendEntry(m, QJsonObject{{"address", "0x0001"}, {"id", "stray"}, {"label", "Stray"}, {"type", "uint16"},
                                   {"access", "R"}, {"group", "1 Test"}});
    }) << "entry 'stray' (0x0001)" << "overlap entry 'value_a' (0x0000..0x0001)";
    QTest::newRow("text overlapping the next entry") << Mutation([](QJsonObject &m) {
        editEntry(m, 3, [](QJsonObject &e) { e["address"] = "0x0002"; e["bytes"] = 4; });
    }) << "entry 'name' (0x0002)" << "overlap entry 'mode' (0x0002..0x0002)";
    QTest::newRow("enum without values") << Mutation([](QJsonObject &m) {
        editEntry(m, 1, [](QJsonObject &e) { e.remove("values"); });
    }) << "entry 'mode' (0x0002)" << "an enum needs 'values'";
    QTest::newRow("bit field without bits") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) { e["bits"] = QJsonArray(); });
    }) << "entry 'alarms' (0x0003)" << "a bit field needs 'bits'";
    QTest::newRow("alias of unknown entry") << Mutation([](QJsonObject &m) {
        appendEntry(m, QJsonObject{{"address", "0x0001"}, {"id", "hi"}, {"label", "Hi"}, {"type", "uint16"},
                                   {"access", "R"}, {"group", "1 Test"}, {"alias", "nothing"}});
    }) << "entry 'hi'" << "alias of unknown entry 'nothing'";
    QTest::newRow("malformed address") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["address"] = "12"; });
    }) << "entry 'value_a' (12)" << "'address' must be 0x followed by 4 hex digits";
    QTest::newRow("unknown access") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["access"] = "R/W"; });
    }) << "entry 'value_a'" << "unknown access 'R/W'";
    QTest::newRow("text without byte count") << Mutation([](QJsonObject &m) {
        editEntry(m, 3, [](QJsonObject &e) { e.remove("bytes"); });
    }) << "entry 'name'" << "a text needs 'bytes'";
    QTest::newRow("misspelt key") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["unti"] = "V"; });
    }) << "entry 'value_a'" << "unknown key 'unti'";
    QTest::newRow("storage on a read-only entry") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["storage"] = "RAM"; });
    }) << "entry 'value_a'" << "a read-only entry cannot have a storage";
    QTest::newRow("unknown word order") << protocolField("floatWordOrder", "little")
                                 << "protocol" << "'floatWordOrder' must be ABCD, CDAB, BADC or DCBA";
    QTest::newRow("no entries") << Mutation([](QJsonObject &m) { m["entries"] = QJsonArray(); })
                                << "test.json" << "'entries' must be a non-empty array";

    // Numbers that used to pass unchecked, or overflow a check.
    QTest::newRow("text bytes beyond a frame") << Mutation([](QJsonObject &m) {
        editEntry(m, 3, [](QJsonObject &e) { e["bytes"] = 2147483647; });
    }) << "entry 'name' (0x0004)" << "'bytes' must be a whole number 2..250, not 2147483647";
    QTest::newRow("reserved words beyond a frame") << Mutation([](QJsonObject &m) {
        appendEntry(m, QJsonObject{{"address", "0x0100"}, {"id", "gap"}, {"label", "Gap"}, {"type", "uint16"},
                                   {"access", "R"}, {"group", "1 Test"}, {"reserved", true}, {"words", 2147483647}});
    }) << "entry 'gap' (0x0100)" << "'words' must be a whole number 1..125, not 2147483647";
    QTest::newRow("bit width that overflows") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", 1}, {"width", 2147483647}, {"id", "x"}, {"label", "X"}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit 1" << "'width' must be a whole number 1..16, not 2147483647";
    QTest::newRow("bit field past bit 15") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", 8}, {"width", 9}, {"id", "x"}, {"label", "X"}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit 8" << "bit field of width 9 does not fit in 16 bits";
    QTest::newRow("id with a trailing newline") << Mutation([](QJsonObject &m) {
        editEntry(m, 1, [](QJsonObject &e) { e["id"] = "mode\n"; });
    }) << "entry 'mode\n' (0x0002)" << "id must be lower case letters, digits and '_'";
    QTest::newRow("family id with a trailing newline") << Mutation([](QJsonObject &m) { m["family"] = "testdev\n"; })
                                                       << "test.json" << "family id 'testdev\n' must be lower case";
    QTest::newRow("bit as a string") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", "3"}, {"id", "x"}, {"label", "X"}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit 3" << "'bit' must be a whole number 0..15, not 3";
    QTest::newRow("width as a string") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", 0}, {"width", "16"}, {"id", "x"}, {"label", "X"}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit 0" << "'width' must be a whole number 1..16, not 16";
    QTest::newRow("fraction of words") << protocolField("maxReadWords", 2.5)
                                 << "protocol" << "'maxReadWords' must be a whole number 1..127, not 2.5";
    QTest::newRow("probe words as a word") << Mutation([](QJsonObject &m) {
        m["identify"] = QJsonArray{QJsonObject{{"address", "0x0000"}, {"words", "two"}, {"answers", true}}};
    }) << "identify[0]" << "'words' must be a whole number 1..125, not two";
    QTest::newRow("broadcast as yes") << protocolField("broadcast", "yes")
                                 << "protocol" << "'broadcast' must be true or false, not yes";
    QTest::newRow("reserved as yes") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["reserved"] = "yes"; });
    }) << "entry 'value_a'" << "'reserved' must be true or false, not yes";
    QTest::newRow("format as a string") << Mutation([](QJsonObject &m) { m["format"] = "1"; })
                                        << "test.json" << "'format' must be a whole number 1..1, not 1";
    QTest::newRow("label as a number") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["unit"] = 5; });
    }) << "entry 'value_a'" << "'unit' must be a string, not 5";
    QTest::newRow("negative processing time") << protocolField("processingTimeMaxMs", -1)
                                 << "protocol" << "'processingTimeMaxMs' must be a number 0..1000, not -1";
    QTest::newRow("processing time of minutes") << protocolField("processingTimeMaxMs", 100000)
                                 << "protocol" << "'processingTimeMaxMs' must be a number 0..1000, not 100000";
    QTest::newRow("negative turnaround") << protocolField("turnaroundMs", -10)
                                 << "protocol" << "'turnaroundMs' must be a number 0..100, not -10";
    QTest::newRow("baud rates zero and negative") << protocolField("baudRates", QJsonArray{0, -9600})
                                 << "protocol" << "'baudRates' may contain only 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, not 0";
    QTest::newRow("read function 5") << protocolField("readFunctions", QJsonArray{3, 5})
                                 << "protocol" << "'readFunctions' may contain only 3, 4, not 5";
    QTest::newRow("always answering address 999") << protocolField("alwaysAnswersAddress", 999)
                                 << "protocol" << "'alwaysAnswersAddress' must be a whole number 1..255, not 999";
    QTest::newRow("always answering address 250") << protocolField("alwaysAnswersAddress", 250)
                                 << "protocol" << "'alwaysAnswersAddress' must be 1..247 or 255, not 250";
    QTest::newRow("alias of itself") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["alias"] = "value_a"; });
    }) << "entry 'value_a'" << "an entry cannot be an alias of itself";
    QTest::newRow("enum keys 1 and 01") << Mutation([](QJsonObject &m) {
        editEntry(m, 1, [](QJsonObject &e) { e["values"] = QJsonObject{{"0", "Off"}, {"1", "On"}, {"01", "Also on"}}; });
    }) << "entry 'mode' (0x0002)" << "enum value '01' must be a number 0..65535 with a text";
    QTest::newRow("exception code 02") << Mutation([](QJsonObject &m) {
        m["exceptions"] = QJsonObject{{"02", "Invalid address"}};
    }) << "exceptions" << "'02' is not an exception code with a text";
    QTest::newRow("decimals as a string") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["decimals"] = "1"; });
    }) << "entry 'value_a' (0x0000)" << "'decimals' must be a whole number 0..6, not 1";
    QTest::newRow("decimals beyond a float") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["decimals"] = 7; });
    }) << "entry 'value_a' (0x0000)" << "'decimals' must be a whole number 0..6, not 7";
    QTest::newRow("negative decimals") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["decimals"] = -1; });
    }) << "entry 'value_a' (0x0000)" << "'decimals' must be a whole number 0..6, not -1";
    QTest::newRow("fraction of a decimal") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["decimals"] = 1.5; });
    }) << "entry 'value_a' (0x0000)" << "'decimals' must be a whole number 0..6, not 1.5";
    QTest::newRow("no significant digit") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["significantDigits"] = 0; });
    }) << "entry 'value_a' (0x0000)" << "'significantDigits' must be a whole number 1..7, not 0";
    QTest::newRow("more significant digits than a float has") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["significantDigits"] = 9; });
    }) << "entry 'value_a' (0x0000)" << "'significantDigits' must be a whole number 1..7, not 9";
    QTest::newRow("decimals and significant digits") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) {
            e["decimals"] = 1;
            e["significantDigits"] = 4;
        });
    }) << "entry 'value_a' (0x0000)" << "give 'decimals' or 'significantDigits', not both";
    QTest::newRow("decimals of an enum") << Mutation([](QJsonObject &m) {
        editEntry(m, 1, [](QJsonObject &e) { e["decimals"] = 1; });
    }) << "entry 'mode' (0x0002)" << "'decimals' and 'significantDigits' are only for floats";
    QTest::newRow("unit of a text") << Mutation([](QJsonObject &m) {
        editEntry(m, 3, [](QJsonObject &e) { e["unit"] = "V"; });
    }) << "entry 'name' (0x0004)" << "a unit is only for numbers";
    QTest::newRow("configured unit nobody defines") << Mutation([](QJsonObject &m) {
        editEntry(m, 0, [](QJsonObject &e) { e["configuredUnit"] = "process_value"; });
    }) << "entry 'value_a' (0x0000)" << "'configuredUnit' names 'process_value', which 'configuredUnits' does not define";
    QTest::newRow("unit and configured unit") << Mutation([](QJsonObject &m) {
        m["configuredUnits"] = QJsonObject{{"process_value", "as set on the device"}};
        editEntry(m, 0, [](QJsonObject &e) {
            e["unit"] = "V";
            e["configuredUnit"] = "process_value";
        });
    }) << "entry 'value_a' (0x0000)" << "give 'unit' or 'configuredUnit', not both";
    QTest::newRow("configured unit without a text") << Mutation([](QJsonObject &m) {
        m["configuredUnits"] = QJsonObject{{"process_value", 1}};
    }) << "configuredUnits" << "'process_value' needs a text that says what decides the unit";
    QTest::newRow("configured unit with a bad id") << Mutation([](QJsonObject &m) {
        m["configuredUnits"] = QJsonObject{{"Process Value", "as set"}};
    }) << "configuredUnits" << "'Process Value' is no id";
    QTest::newRow("configured units as a list") << Mutation([](QJsonObject &m) {
        m["configuredUnits"] = QJsonArray{"process_value"};
    }) << "test.json" << "'configuredUnits' must be an object";
    QTest::newRow("short name longer than a list has room for") << Mutation([](QJsonObject &m) {
        m["shortName"] = "A short name that is not short at all";
    }) << "test.json" << "'shortName' must be 1 to 24 characters";
    QTest::newRow("blank short name") << Mutation([](QJsonObject &m) { m["shortName"] = " "; })
                                      << "test.json" << "'shortName' must be 1 to 24 characters";
    QTest::newRow("short name as a number") << Mutation([](QJsonObject &m) { m["shortName"] = 300; })
                                            << "test.json" << "'shortName' must be a string, not 300";
    auto faceplate = [](const QJsonObject &face) {
        return Mutation([face](QJsonObject &m) { m["faceplate"] = face; });
    };
    const QJsonArray oneValue{QJsonObject{{"entry", "value_a"}}};
    QTest::newRow("faceplate of an unknown kind") << faceplate({{"kind", "meter"}, {"values", oneValue}})
                                                  << "faceplate" << "unknown kind 'meter' (expected power_unit or process_controller)";
    QTest::newRow("faceplate without values") << faceplate({{"kind", "power_unit"}, {"values", QJsonArray()}})
                                              << "faceplate" << "'values' must be a non-empty array";
    QTest::newRow("faceplate value of no entry")
            << faceplate({{"kind", "power_unit"}, {"values", QJsonArray{QJsonObject{{"entry", "nope"}}}}})
            << "faceplate.values[0]" << "'nope' is not a readable entry";
    QTest::newRow("faceplate scale from an enum of words")
            << faceplate({{"kind", "power_unit"},
                          {"values", QJsonArray{QJsonObject{{"entry", "value_a"}, {"scale", "nominal"}, {"from", QJsonArray{"mode"}}}}}})
            << "faceplate.values[0]" << "the scale 'mode' must be a number, or an enum whose every text starts with one";
    QTest::newRow("faceplate range upside down")
            << faceplate({{"kind", "power_unit"},
                          {"values", QJsonArray{QJsonObject{{"entry", "value_a"}, {"scale", "range"}, {"min", 10}, {"max", 0}}}}})
            << "faceplate.values[0]" << "'max' must be above 'min'";
    QTest::newRow("faceplate bounds without a range")
            << faceplate({{"kind", "power_unit"}, {"values", QJsonArray{QJsonObject{{"entry", "value_a"}, {"max", 100}}}}})
            << "faceplate.values[0]" << "'min' and 'max' are only for the scale 'range'";
    QTest::newRow("faceplate mode on a whole bit field")
            << faceplate({{"kind", "process_controller"}, {"values", oneValue},
                          {"modes", QJsonArray{QJsonObject{{"when", "alarms"}, {"text", "Manual"}}}}})
            << "faceplate.modes[0]" << "'alarms' must be a readable bool entry or a single bit of a readable bit field";
    QTest::newRow("faceplate mode on an unknown bit")
            << faceplate({{"kind", "process_controller"}, {"values", oneValue},
                          {"modes", QJsonArray{QJsonObject{{"when", "alarms.middle"}, {"text", "Manual"}}}}})
            << "faceplate.modes[0]" << "refers to unknown bit 'middle' of 'alarms'";
    QTest::newRow("faceplate program without its time")
            << faceplate({{"kind", "process_controller"}, {"values", oneValue},
                          {"program", QJsonObject{{"segment", "value_a"}, {"segments", "value_a"}}}})
            << "faceplate.program" << "timeLeft";
    // With entries the faceplate cannot show: a second name of a word, a reserve, a word
    // that can only be written, a switch.
    auto withOddEntries = [](QJsonObject &m) {
        appendEntry(m, QJsonObject{{"address", "0x0000"}, {"id", "value_a_again"}, {"label", "Value A again"},
                                   {"type", "float"}, {"access", "R"}, {"group", "1 Test"}, {"alias", "value_a"}});
        appendEntry(m, QJsonObject{{"address", "0x0003"}, {"id", "alarms_again"}, {"label", "Alarms again"},
                                   {"type", "bitfield"}, {"access", "R"}, {"group", "1 Test"}, {"alias", "alarms"},
                                   {"bits", QJsonArray{QJsonObject{{"bit", 0}, {"id", "low"}, {"label", "Low"}, {"kind", "status"}}}}});
        appendEntry(m, QJsonObject{{"address", "0x0010"}, {"id", "reserve_10"}, {"label", "Reserve"}, {"type", "uint16"},
                                   {"access", "R"}, {"group", "1 Test"}, {"reserved", true}});
        appendEntry(m, QJsonObject{{"address", "0x0011"}, {"id", "command"}, {"label", "Command"}, {"type", "uint16"},
                                   {"access", "W"}, {"group", "1 Test"}});
        appendEntry(m, QJsonObject{{"address", "0x0012"}, {"id", "manual"}, {"label", "Manual"}, {"type", "bool"},
                                   {"access", "R"}, {"group", "1 Test"}});
        appendEntry(m, QJsonObject{{"address", "0x0013"}, {"id", "manual_again"}, {"label", "Manual again"}, {"type", "bool"},
                                   {"access", "R"}, {"group", "1 Test"}, {"alias", "manual"}});
    };
    auto oddFaceplate = [withOddEntries](const QJsonObject &face) {
        return Mutation([face, withOddEntries](QJsonObject &m) {
            withOddEntries(m);
            m["faceplate"] = face;
        });
    };
    auto oneRow = [](const QJsonObject &row) { return QJsonObject{{"kind", "power_unit"}, {"values", QJsonArray{row}}}; };
    QTest::newRow("faceplate value as a number") << faceplate({{"kind", "power_unit"}, {"values", QJsonArray{5}}})
                                                 << "faceplate.values[0]" << "entry";
    QTest::newRow("faceplate values as an object") << faceplate({{"kind", "power_unit"}, {"values", oneValue.first()}})
                                                   << "faceplate" << "'values' must be a non-empty array";
    QTest::newRow("faceplate min as a string")
            << faceplate(oneRow({{"entry", "value_a"}, {"scale", "range"}, {"min", "0"}, {"max", 10}}))
            << "faceplate.values[0]" << "'min' must be a number, not 0";
    QTest::newRow("faceplate from as a string")
            << faceplate(oneRow({{"entry", "value_a"}, {"scale", "nominal"}, {"from", "value_a"}}))
            << "faceplate.values[0]" << "'from' must be an array of strings";
    QTest::newRow("faceplate kind as a number") << faceplate({{"kind", 1}, {"values", oneValue}})
                                                << "faceplate" << "'kind' is missing or not a non-empty string";
    QTest::newRow("faceplate as an array") << Mutation([](QJsonObject &m) { m["faceplate"] = QJsonArray{}; })
                                           << "test.json" << "'faceplate' must be an object";
    QTest::newRow("faceplate value of a write-only entry") << oddFaceplate(oneRow({{"entry", "command"}}))
                                                           << "faceplate.values[0]" << "'command' is not a readable entry";
    QTest::newRow("faceplate value of an alias") << oddFaceplate(oneRow({{"entry", "value_a_again"}}))
                                                 << "faceplate.values[0]" << "'value_a_again' is not a readable entry";
    QTest::newRow("faceplate value of a reserve") << oddFaceplate(oneRow({{"entry", "reserve_10"}}))
                                                  << "faceplate.values[0]" << "'reserve_10'";
    QTest::newRow("faceplate primary of a reserve")
            << oddFaceplate({{"kind", "process_controller"}, {"primary", "reserve_10"}, {"values", oneValue}})
            << "faceplate.primary" << "'reserve_10'";
    QTest::newRow("faceplate bar of a text") << faceplate(oneRow({{"entry", "name"}, {"scale", "range"}}))
                                             << "faceplate.values[0]" << "'name'";
    QTest::newRow("faceplate bar of an enum of words") << faceplate(oneRow({{"entry", "mode"}, {"scale", "range"}}))
                                                       << "faceplate.values[0]" << "'mode'";
    QTest::newRow("faceplate bar of a bit field") << faceplate(oneRow({{"entry", "alarms"}, {"scale", "range"}}))
                                                  << "faceplate.values[0]" << "'alarms'";
    QTest::newRow("faceplate mode on an alias")
            << oddFaceplate({{"kind", "process_controller"}, {"values", oneValue},
                             {"modes", QJsonArray{QJsonObject{{"when", "manual_again"}, {"text", "Manual"}}}}})
            << "faceplate.modes[0]" << "'manual_again'";
    QTest::newRow("faceplate mode on a bit of an alias")
            << oddFaceplate({{"kind", "process_controller"}, {"values", oneValue},
                             {"modes", QJsonArray{QJsonObject{{"when", "alarms_again.low"}, {"text", "Low"}}}}})
            << "faceplate.modes[0]" << "'alarms_again.low'";
    QTest::newRow("faceplate scale from a reserve")
            << oddFaceplate(oneRow({{"entry", "value_a"}, {"scale", "limit"}, {"from", QJsonArray{"reserve_10"}}}))
            << "faceplate.values[0]" << "'reserve_10'";
    QTest::newRow("faceplate program as a list")
            << faceplate({{"kind", "process_controller"}, {"values", oneValue}, {"program", QJsonArray{"value_a"}}})
            << "faceplate" << "'program' must be an object";
    QTest::newRow("faceplate program segment of a text")
            << faceplate({{"kind", "process_controller"}, {"values", oneValue},
                          {"program", QJsonObject{{"segment", "name"}, {"segments", "value_a"}, {"timeLeft", "value_a"}}}})
            << "faceplate.program" << "'name'";
    QJsonArray seventeen;
    for (int i = 0; i < 17; ++i)
        seventeen.append(QJsonObject{{"entry", "value_a"}});
    QTest::newRow("faceplate of 17 rows") << faceplate({{"kind", "power_unit"}, {"values", seventeen}})
                                          << "faceplate" << "'values' has 17 rows; a faceplate shows at most 16";
    QTest::newRow("faceplate mode as a string")
            << faceplate({{"kind", "process_controller"}, {"values", oneValue}, {"modes", QJsonArray{"manual"}}})
            << "faceplate.modes[0]" << "'when'";
    // Defaults (the manual's factory settings): a value the entry can hold, of its type.
    const auto withDefault = [](int index, const QJsonValue &value, const std::function<void(QJsonObject &)> &more = {}) {
        return Mutation([=](QJsonObject &m) {
            editEntry(m, index, [&](QJsonObject &e) {
                e["default"] = value;
                if (more)
                    more(e);
            });
        });
    };
    const auto writableFloat = [](QJsonObject &e) {
        e["access"] = "RW";
        e["min"] = 0;
        e["max"] = 100;
    };
    QTest::newRow("default outside the range") << withDefault(0, 150, writableFloat) << "entry 'value_a' (0x0000)"
                                               << "'default' 150 is outside the entry's range 0..100";
    QTest::newRow("default below the range") << withDefault(0, -0.5, writableFloat) << "entry 'value_a' (0x0000)"
                                             << "'default' -0.5 is outside the entry's range 0..100";
    QTest::newRow("default as a string") << withDefault(0, "10", writableFloat) << "entry 'value_a' (0x0000)"
                                         << "'default' must be a number, not '10'";
    QTest::newRow("default that is no enum value") << withDefault(1, 2) << "entry 'mode' (0x0002)"
                                                   << "'default' 2 is none of the enum's values";
    QTest::newRow("default as an enum's label") << withDefault(1, "On") << "entry 'mode' (0x0002)"
                                                << "'default' must be a number, not 'On'";
    QTest::newRow("default of a read-only entry") << withDefault(0, 1) << "entry 'value_a' (0x0000)"
                                                  << "'default' is only for writable entries";
    QTest::newRow("default of a bit field") << withDefault(2, 0, [](QJsonObject &e) { e["access"] = "RW"; })
                                            << "entry 'alarms' (0x0003)" << "'default' is only for numbers, enums and booleans";
    QTest::newRow("fractional default of an integer") << withDefault(1, 2.5, [](QJsonObject &e) {
        e["type"] = "uint16";
        e.remove("values");
    }) << "entry 'mode' (0x0002)" << "'default' of a uint16 must be a whole number, not 2.5";
    QTest::newRow("negative default of an unsigned integer") << withDefault(1, -1, [](QJsonObject &e) {
        e["type"] = "uint16";
        e.remove("values");
    }) << "entry 'mode' (0x0002)" << "'default' -1 is outside the entry's range 0..65535";
    QTest::newRow("default of a boolean as a number") << withDefault(1, 0, [](QJsonObject &e) {
        e["type"] = "bool";
        e.remove("values");
    }) << "entry 'mode' (0x0002)" << "'default' of a boolean must be true or false, not 0";
}

void tst_MapLoader::pollClassesFromTheMap_data()
{
    QTest::addColumn<QString>("entry");
    QTest::addColumn<QString>("poll");       // the entry's "poll", or empty
    QTest::addColumn<QString>("expected");
    QTest::newRow("measured value: live") << "value_a" << "" << "live";
    QTest::newRow("writable parameter: setting") << "mode" << "" << "setting";
    QTest::newRow("alarm and warning bits: alarm") << "alarms" << "" << "alarm";
    QTest::newRow("text: setting") << "name" << "" << "setting";
    QTest::newRow("override, live to alarm") << "value_a" << "alarm" << "alarm";
    QTest::newRow("override, alarm to live") << "alarms" << "live" << "live";
    QTest::newRow("override, setting to live") << "mode" << "live" << "live";
}

void tst_MapLoader::pollClassesFromTheMap()
{
    QFETCH(QString, entry);
    QFETCH(QString, poll);
    QFETCH(QString, expected);
    QJsonObject json = validMap();
    const int index = QStringList{"value_a", "mode", "alarms", "name"}.indexOf(entry);
    if (!poll.isEmpty())
        editEntry(json, index, [&poll](QJsonObject &e) { e["poll"] = poll; });
    const MapLoadResult r = MapLoader::loadData(QJsonDocument(json).toJson(), "test.json");
    QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
    QCOMPARE(pollClassName(r.map->entry(entry)->pollClass), expected);
}

void tst_MapLoader::defaultsAreRead()
{
    QJsonObject map = validMap();
    editEntry(map, 0, [](QJsonObject &e) {
        e["access"] = "RW";
        e["min"] = 0;
        e["max"] = 100;
        e["default"] = 10;
    });
    editEntry(map, 1, [](QJsonObject &e) { e["default"] = 1; });
    appendEntry(map, QJsonObject{{"address", "0x0010"}, {"id", "output"}, {"label", "Output"}, {"type", "bool"},
                                 {"access", "RW"}, {"group", "1 Test"}, {"default", false}});
    appendEntry(map, QJsonObject{{"address", "0x0011"}, {"id", "delay"}, {"label", "Delay"}, {"type", "int16"},
                                 {"access", "RW"}, {"group", "1 Test"}, {"default", -5}});
    const MapLoadResult r = MapLoader::loadData(QJsonDocument(map).toJson(), "test.json");
    QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
    QCOMPARE(r.map->entry("value_a")->defaultValue, std::optional<double>(10));
    QCOMPARE(r.map->entry("mode")->defaultValue, std::optional<double>(1));
    QCOMPARE(r.map->entry("output")->defaultValue, std::optional<double>(0));
    QCOMPARE(r.map->entry("delay")->defaultValue, std::optional<double>(-5));
    QVERIFY(!r.map->entry("alarms")->defaultValue);   // none given: none known
}

void tst_MapLoader::precisionFromTheMapOrTheUnit()
{
    QJsonObject map = validMap();
    map["shortName"] = "Test";
    map["configuredUnits"] = QJsonObject{{"process_value", "as set on the device"}};
    editEntry(map, 0, [](QJsonObject &e) { e["unit"] = "A"; });
    appendEntry(map, QJsonObject{{"address", "0x0010"}, {"id", "voltage"}, {"label", "Voltage"}, {"type", "float"},
                                 {"access", "R"}, {"group", "1 Test"}, {"unit", "V"}, {"significantDigits", 3}});
    appendEntry(map, QJsonObject{{"address", "0x0012"}, {"id", "pv"}, {"label", "Process value"}, {"type", "float"},
                                 {"access", "R"}, {"group", "1 Test"}, {"configuredUnit", "process_value"},
                                 {"decimals", 2}});
    appendEntry(map, QJsonObject{{"address", "0x0014"}, {"id", "ratio"}, {"label", "Ratio"}, {"type", "float"},
                                 {"access", "R"}, {"group", "1 Test"}});
    const MapLoadResult r = MapLoader::loadData(QJsonDocument(map).toJson(), "test.json");
    QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
    QCOMPARE(r.map->shortName, QString("Test"));
    QCOMPARE(r.map->entry("value_a")->precision, DisplayPrecision::significant(4));   // amperes by default
    QVERIFY(!r.map->entry("value_a")->precisionFromMap);
    QCOMPARE(r.map->entry("voltage")->precision, DisplayPrecision::significant(3));
    QVERIFY(r.map->entry("voltage")->precisionFromMap);
    QCOMPARE(r.map->entry("pv")->precision, DisplayPrecision::decimals(2));
    QCOMPARE(r.map->entry("pv")->configuredUnit, QString("process_value"));
    QCOMPARE(r.map->configuredUnits.value("process_value"), QString("as set on the device"));
    QCOMPARE(r.map->entry("ratio")->precision, DisplayPrecision::decimals(1));
    // Without a short name, lists show the name.
    const MapLoadResult plain = MapLoader::loadData(QJsonDocument(validMap()).toJson(), "test.json");
    QCOMPARE(plain.map->shortName, QString("Test device"));
}

void tst_MapLoader::refusesBadMap()
{
    QFETCH(Mutation, mutation);
    QFETCH(QString, entry);
    QFETCH(QString, problem);
    QJsonObject map = validMap();
    mutation(map);
    const MapLoadResult r = MapLoader::loadData(QJsonDocument(map).toJson(), "test.json");
    QVERIFY(!r.ok());
    QVERIFY(!r.errors.isEmpty());
    const QString message = r.errors.join('\n');
    QVERIFY2(message.startsWith("test.json: "), qPrintable(message));
    QVERIFY2(message.contains(entry), qPrintable(message));
    QVERIFY2(message.contains(problem), qPrintable(message));
}

void tst_MapLoader::faceplateFromTheMap()
{
    // Without a faceplate, the map's overview values are its rows, with their labels.
    QJsonObject plain = validMap();
    plain["overview"] = QJsonArray{"value_a"};
    const MapLoadResult r = MapLoader::loadData(QJsonDocument(plain).toJson(), "test.json");
    QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
    QCOMPARE(r.map->faceplate.values.size(), 1);
    QCOMPARE(r.map->faceplate.values[0].label, QString("Value A"));
    QCOMPARE(r.map->faceplate.values[0].scale, FaceplateValue::Scale::None);
    // A long overview gives a faceplate of as many rows as one shows.
    QJsonArray many;
    for (int i = 0; i < 20; ++i)
        many.append("value_a");
    plain["overview"] = many;
    const MapLoadResult longOverview = MapLoader::loadData(QJsonDocument(plain).toJson(), "test.json");
    QVERIFY2(longOverview.ok(), qPrintable(longOverview.errors.join('\n')));
    QCOMPARE(longOverview.map->faceplate.values.size(), 16);

    // The built-in maps: bars against nominal values and limits, modes, the dTRON's program.
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    const FaceplateSpec &ipc = registry.family("ipc300")->faceplate;
    QCOMPARE(ipc.kind, FaceplateSpec::Kind::PowerUnit);
    QCOMPARE(ipc.values.size(), 4);
    QCOMPARE(ipc.values[2].entry, QString("load_current"));
    QCOMPARE(ipc.values[2].scale, FaceplateValue::Scale::Nominal);
    QCOMPARE(ipc.values[2].scaleFrom, QStringList{"nominal_current"});
    const FaceplateSpec &tya = registry.family("tya200")->faceplate;
    QCOMPARE(tya.values[3].scaleFrom, QStringList({"nominal_voltage", "rated_current"}));
    const FaceplateSpec &dtron = registry.family("dtron300")->faceplate;
    QCOMPARE(dtron.kind, FaceplateSpec::Kind::ProcessController);
    QCOMPARE(dtron.primary, QString("filtered_process_value"));
    QVERIFY(dtron.hasProgram());
    QCOMPARE(dtron.modes.size(), 2);
    QVERIFY(!registry.family("quantrol")->faceplate.hasProgram());
    // Nominal values kept as enums count by their number.
    QCOMPARE(leadingNumber("100 A"), std::optional<double>(100));
    QCOMPARE(leadingNumber("2.5 kW"), std::optional<double>(2.5));
    QCOMPARE(leadingNumber("customer-specific"), std::nullopt);
}

void tst_MapLoader::refusesMalformedJson()
{
    const MapLoadResult r = MapLoader::loadData("{ \"format\": 1, \"entries\": [ }", "broken.json");
    QVERIFY(!r.ok());
    QCOMPARE(r.errors.size(), 1);
    QVERIFY2(r.errors.first().startsWith("broken.json: malformed JSON at byte"), qPrintable(r.errors.first()));
}

void tst_MapLoader::refusesAKeyGivenTwice()
{
    // Qt's parser keeps one of the two values silently: an address given twice in an
    // entry would put it at either.
    QByteArray json = QJsonDocument(validMap()).toJson(QJsonDocument::Compact);
    const qsizetype at = json.indexOf("\"address\":");
    QVERIFY(at > 0);
    json.insert(at, "\"address\": \"0x0999\", ");
    const MapLoadResult r = MapLoader::loadData(json, "twice.json");
    QVERIFY(!r.ok());
    QCOMPARE(r.errors.size(), 1);
    QVERIFY2(r.errors.first().startsWith("twice.json: malformed JSON at byte"), qPrintable(r.errors.first()));
    QVERIFY2(r.errors.first().contains("'address' given twice"), qPrintable(r.errors.first()));
}

void tst_MapLoader::builtinMapsLoad()
{
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    QVERIFY2(registry.errors().isEmpty(), qPrintable(registry.errors().join('\n')));
    QCOMPARE(registry.familyIds(), QStringList({"dtron300", "ipc300", "quantrol", "tya200"}));
    // Every float of the built-in maps has its unit, fixed or set on the device.
    for (const auto &map : registry.families()) {
        QVERIFY2(!map->shortName.isEmpty() && map->shortName.size() <= 12, qPrintable(map->shortName));
        for (const RegisterEntry &e : map->entries()) {
            if (e.type == ValueType::Float && !e.reserved)
                QVERIFY2(!e.unit.isEmpty() || !e.configuredUnit.isEmpty(), qPrintable(map->family + ": " + e.id));
        }
    }
}

void tst_MapLoader::userFolderReplacesBuiltinAndReportsBrokenFiles()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QJsonObject replacement = validMap();
    replacement["family"] = "ipc300";
    replacement["name"] = "Replaced IPC";
    QFile good(dir.filePath("ipc300.json"));
    QVERIFY(good.open(QIODevice::WriteOnly));
    good.write(QJsonDocument(replacement).toJson());
    good.close();
    QFile bad(dir.filePath("zz-broken.json"));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write("not json");
    bad.close();

    const FamilyRegistry registry = FamilyRegistry::load({dir.path()}, true);
    QCOMPARE(registry.family("ipc300")->name, QString("Replaced IPC"));
    QCOMPARE(registry.families().size(), 4);
    QCOMPARE(registry.errors().size(), 1);
    QVERIFY(registry.errors().first().contains("zz-broken.json: malformed JSON"));
}

void tst_MapLoader::twoUserFilesOfOneFamilyAreRefused()
{
    QTemporaryDir first;
    QTemporaryDir second;
    QJsonObject a = validMap();
    a["name"] = "First";
    QJsonObject b = validMap();
    b["name"] = "Second";
    for (const auto &[dir, map] : {std::make_pair(&first, a), std::make_pair(&second, b)}) {
        QFile f(dir->filePath("testdev.json"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QJsonDocument(map).toJson());
    }
    const FamilyRegistry registry = FamilyRegistry::load({first.path(), second.path()}, true);
    QVERIFY(!registry.family("testdev"));   // not silently the later one
    QCOMPARE(registry.errors().size(), 1);
    QVERIFY2(registry.errors().first().contains("family 'testdev' is defined by each of these files"),
             qPrintable(registry.errors().first()));
    QVERIFY(registry.errors().first().contains(first.filePath("testdev.json")));
    QVERIFY(registry.errors().first().contains(second.filePath("testdev.json")));
    QCOMPARE(registry.families().size(), 4);
}

void tst_MapLoader::overlapsAreReportedOncePerGroup()
{
    // 5000 entries at one address: one message (it used to be 12.5 million).
    QJsonObject map = validMap();
    QJsonArray entries = map["entries"].toArray();
    for (int i = 0; i < 5000; ++i)
        entries.append(QJsonObject{{"address", "0x0100"}, {"id", QStringLiteral("same_%1").arg(i)}, {"label", "Same"},
                                   {"type", "uint16"}, {"access", "R"}, {"group", "1 Test"}});
    map["entries"] = entries;
    MapLoadResult r = MapLoader::loadData(QJsonDocument(map).toJson(), "many.json");
    QVERIFY(!r.ok());
    QCOMPARE(r.errors.size(), 1);
    QVERIFY2(r.errors.first().contains("entry 'same_1' (0x0100): words 0x0100..0x0100 overlap entry 'same_0'"),
             qPrintable(r.errors.first()));
    QVERIFY2(r.errors.first().contains("and 4995 more entries"), qPrintable(r.errors.first()));

    // 30 separate pairs: 20 messages and a count of the rest.
    map = validMap();
    entries = map["entries"].toArray();
    for (int i = 0; i < 30; ++i) {
        const QString address = QStringLiteral("0x%1").arg(0x1000 + i * 16, 4, 16, QLatin1Char('0'));
        entries.append(QJsonObject{{"address", address}, {"id", QStringLiteral("a_%1").arg(i)}, {"label", "A"},
                                   {"type", "float"}, {"access", "R"}, {"group", "1 Test"}});
        entries.append(QJsonObject{{"address", address}, {"id", QStringLiteral("b_%1").arg(i)}, {"label", "B"},
                                   {"type", "uint16"}, {"access", "R"}, {"group", "1 Test"}});
    }
    map["entries"] = entries;
    r = MapLoader::loadData(QJsonDocument(map).toJson(), "pairs.json");
    QCOMPARE(r.errors.size(), 21);
    QVERIFY2(r.errors.last().contains("10 more group(s) of overlapping entries not listed"), qPrintable(r.errors.last()));
}

void tst_MapLoader::onlyRegularFilesAreRead()
{
    QTemporaryDir dir;
    QVERIFY(QFile::link("/dev/zero", dir.filePath("zero.json")));   // would be read forever
    QVERIFY(::mkfifo(QFile::encodeName(dir.filePath("fifo.json")).constData(), 0600) == 0);   // would block
    QFile big(dir.filePath("big.json"));
    QVERIFY(big.open(QIODevice::WriteOnly));
    QVERIFY(big.resize(MapLoader::maxFileBytes + 1));
    big.close();
    const FamilyRegistry registry = FamilyRegistry::load({dir.path()}, true);
    QCOMPARE(registry.families().size(), 4);
    const QString errors = registry.errors().join('\n');
    QCOMPARE(registry.errors().size(), 3);
    QVERIFY2(errors.contains(dir.filePath("zero.json") + ": not a regular file"), qPrintable(errors));
    QVERIFY2(errors.contains(dir.filePath("fifo.json") + ": not a regular file"), qPrintable(errors));
    QVERIFY2(errors.contains(dir.filePath("big.json") + ": too big"), qPrintable(errors));
}

void tst_MapLoader::aFolderNamedTwiceIsReadOnce()
{
    // JUMO_MAP_PATH=a:a (or a:a/, or the data folder named as well): its files are not
    // two definitions of their families.
    QTemporaryDir dir;
    QFile f(dir.filePath("testdev.json"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QJsonDocument(validMap()).toJson());
    f.close();
    FamilyRegistry registry = FamilyRegistry::load({dir.path(), dir.path() + "/", dir.path() + "/."}, true);
    QVERIFY2(registry.errors().isEmpty(), qPrintable(registry.errors().join('\n')));
    QVERIFY(registry.family("testdev"));
    const QByteArray before = qgetenv("JUMO_MAP_PATH");
    qputenv("JUMO_MAP_PATH", QFile::encodeName(dir.path() + ":" + dir.path()));
    registry = FamilyRegistry::loadDefault();
    qputenv("JUMO_MAP_PATH", before);
    QVERIFY2(registry.errors().isEmpty(), qPrintable(registry.errors().join('\n')));
    QVERIFY(registry.family("testdev"));
}

QTEST_GUILESS_MAIN(tst_MapLoader)
#include "tst_maploader.moc"
