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

using Mutation = std::function<void(QJsonObject &)>;

void editEntry(QJsonObject &map, int index, const std::function<void(QJsonObject &)> &edit)
{
    QJsonArray entries = map.value("entries").toArray();
    QJsonObject e = entries.at(index).toObject();
    edit(e);
    entries.replace(index, e);
    map.insert("entries", entries);
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
    void builtinMapsLoad();
    void userFolderReplacesBuiltinAndReportsBrokenFiles();
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
    QTest::newRow("duplicate id") << Mutation([](QJsonObject &m) {
        editEntry(m, 3, [](QJsonObject &e) { e["id"] = "mode"; });
    }) << "entry 'mode' (0x0004)" << "duplicate id";
    QTest::newRow("bit above 15") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", 16}, {"id", "x"}, {"label", "X"}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit 16" << "bit number must be 0..15";
    QTest::newRow("negative bit") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", -1}, {"id", "x"}, {"label", "X"}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit -1" << "bit number must be 0..15";
    QTest::newRow("bit defined twice") << Mutation([](QJsonObject &m) {
        editEntry(m, 2, [](QJsonObject &e) {
            e["bits"] = QJsonArray{QJsonObject{{"bit", 3}, {"id", "x"}, {"label", "X"}, {"kind", "alarm"}},
                                   QJsonObject{{"bit", 3}, {"id", "y"}, {"label", "Y"}, {"kind", "alarm"}}};
        });
    }) << "entry 'alarms' (0x0003), bit 3" << "bit defined twice";
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
    QTest::newRow("unknown word order") << Mutation([](QJsonObject &m) {
        QJsonObject p = m["protocol"].toObject();
        p["floatWordOrder"] = "little";
        m["protocol"] = p;
    }) << "protocol" << "'floatWordOrder' must be ABCD, CDAB, BADC or DCBA";
    QTest::newRow("no entries") << Mutation([](QJsonObject &m) { m["entries"] = QJsonArray(); })
                                << "test.json" << "'entries' must be a non-empty array";
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

void tst_MapLoader::refusesMalformedJson()
{
    const MapLoadResult r = MapLoader::loadData("{ \"format\": 1, \"entries\": [ }", "broken.json");
    QVERIFY(!r.ok());
    QCOMPARE(r.errors.size(), 1);
    QVERIFY2(r.errors.first().startsWith("broken.json: malformed JSON at byte"), qPrintable(r.errors.first()));
}

void tst_MapLoader::builtinMapsLoad()
{
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    QVERIFY2(registry.errors().isEmpty(), qPrintable(registry.errors().join('\n')));
    QCOMPARE(registry.familyIds(), QStringList({"dtron300", "ipc300", "quantrol", "tya200"}));
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

QTEST_GUILESS_MAIN(tst_MapLoader)
#include "tst_maploader.moc"
