// The read planner makes as few requests as the family's limit allows, and never reads
// a write-only register, an undefined address or across one.
#include "bus/linetiming.h"
#include "protocol/familyregistry.h"
#include "protocol/maploader.h"
#include "protocol/readplanner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace jumo;

namespace {

const FamilyRegistry &registry()
{
    static const FamilyRegistry r = FamilyRegistry::load({}, true);
    return r;
}

// Every word a plan reads must belong to a readable, non-alias entry.
void verifyOnlyReadableWords(const RegisterMap &map, const ReadPlan &plan)
{
    for (const ReadBlock &b : plan.blocks) {
        QVERIFY(b.count >= 1);
        QVERIFY(b.count <= map.protocol.effectiveMaxReadWords());
        for (int a = b.start; a <= b.end(); ++a) {
            const RegisterEntry *e = map.entryAt(quint16(a));
            QVERIFY2(e, qPrintable(QString("%1 reads undefined %2").arg(map.family, formatAddress(quint16(a)))));
            QVERIFY2(e->isReadable(), qPrintable(QString("%1 reads write-only %2").arg(map.family, e->id)));
            // A block never cuts a multi-word value in half.
            if (a == b.start)
                QCOMPARE(e->address, b.start);
            if (a == b.end())
                QCOMPARE(e->lastAddress(), b.end());
        }
    }
}

// A lower bound on the number of requests: each run of contiguous readable words needs
// ceil(words / limit) requests at least.
int lowerBound(const RegisterMap &map)
{
    int requests = 0;
    int runWords = 0;
    int previousEnd = -2;
    for (const RegisterEntry &e : map.entries()) {
        if (!e.alias.isEmpty())
            continue;
        const bool continues = e.isReadable() && int(e.address) == previousEnd + 1 && runWords > 0;
        if (!continues && runWords > 0) {
            requests += (runWords + map.protocol.effectiveMaxReadWords() - 1) / map.protocol.effectiveMaxReadWords();
            runWords = 0;
        }
        if (e.isReadable())
            runWords += e.wordCount();
        previousEnd = e.isReadable() ? e.lastAddress() : -2;
    }
    if (runWords > 0)
        requests += (runWords + map.protocol.effectiveMaxReadWords() - 1) / map.protocol.effectiveMaxReadWords();
    return requests;
}

} // namespace

class tst_ReadPlanner : public QObject
{
    Q_OBJECT

private slots:
    void fullDevicePlan_data();
    void fullDevicePlan();
    void mergesOnlyThroughDefinedRegisters();
    void bridgesOnlyGapsCheaperThanARequest();
    void respectsWordLimit();
    void refusesWriteOnlyAndUnknown();
    void neverSplitsAValue();
};

void tst_ReadPlanner::fullDevicePlan_data()
{
    QTest::addColumn<QString>("family");
    QTest::addColumn<int>("requests");
    // Counted by hand from the manuals' tables: IPC 300 0x0000-0x0021, 0x0023-0x00F0,
    // 0x00F2-0x0116 (0x0022 undefined, 0x00F1 write-only), one more because 0x0023-0x00F0
    // is 206 words > 125.
    QTest::newRow("ipc300") << "ipc300" << 4;
    QTest::newRow("tya200") << "tya200" << 5;
    QTest::newRow("quantrol") << "quantrol" << 9;
    QTest::newRow("dtron300") << "dtron300" << 16;
}

void tst_ReadPlanner::fullDevicePlan()
{
    QFETCH(QString, family);
    QFETCH(int, requests);
    const RegisterMap &map = *registry().family(family);
    const ReadPlan plan = ReadPlanner::plan(map);
    QVERIFY2(plan.errors.isEmpty(), qPrintable(plan.errors.join('\n')));
    verifyOnlyReadableWords(map, plan);
    QCOMPARE(int(plan.blocks.size()), requests);
    QCOMPARE(int(plan.blocks.size()), lowerBound(map));   // greedy is optimal here
    int readable = 0;
    int planned = 0;
    for (const RegisterEntry &e : map.entries())
        readable += e.isReadable() && e.alias.isEmpty();
    for (const ReadBlock &b : plan.blocks)
        planned += int(b.entries.size());
    QCOMPARE(planned, readable);
}

void tst_ReadPlanner::mergesOnlyThroughDefinedRegisters()
{
    const RegisterMap &map = *registry().family("ipc300");
    // Load voltage (0x00AF) and load current (0x00B1) are adjacent: one request.
    ReadPlan plan = ReadPlanner::plan(map, QStringList{"load_voltage", "load_current"});
    QCOMPARE(plan.blocks.size(), 1);
    QCOMPARE(plan.blocks[0].start, quint16(0x00AF));
    QCOMPARE(plan.blocks[0].count, quint16(4));
    // Inspection ID ends at 0x0021, 0x0022 is undefined: the order code needs its own request.
    plan = ReadPlanner::plan(map, QStringList{"inspection_id", "order_code"});
    QCOMPARE(plan.blocks.size(), 2);
    // Binary signal 2 (0x00F0) and min. alarm (0x00F2) are separated by the write-only 0x00F1.
    const RegisterEntry *writeOnly = map.entryAt(0x00F1);
    QVERIFY(writeOnly && !writeOnly->isReadable());
    plan = ReadPlanner::plan(map, QList<const RegisterEntry *>{map.entryAt(0x00F0), map.entryAt(0x00F2)});
    QCOMPARE(plan.blocks.size(), 2);
    verifyOnlyReadableWords(map, plan);
    // Far apart but connected through readable registers: bridged in one request.
    plan = ReadPlanner::plan(map, QStringList{"load_voltage", "device_temperature_c"});
    QCOMPARE(plan.blocks.size(), 1);
}

void tst_ReadPlanner::bridgesOnlyGapsCheaperThanARequest()
{
    // Issue 22: the IPC 300's faceplate was 177 words in 2 requests. A gap is read through
    // only where its words cost less wire time than one more request.
    const RegisterMap &map = *registry().family("ipc300");
    const RegisterEntry *voltage = map.entry("load_voltage");
    const RegisterEntry *temperature = map.entry("device_temperature_c");
    const int gap = int(temperature->address) - int(voltage->lastAddress()) - 1;
    QVERIFY(gap > 0);
    const QList<const RegisterEntry *> wanted{voltage, temperature};
    QCOMPARE(ReadPlanner::plan(map, wanted, gap).blocks.size(), 1);
    QCOMPARE(ReadPlanner::plan(map, wanted, gap - 1).blocks.size(), 2);
    QCOMPARE(ReadPlanner::plan(map, wanted).blocks.size(), 1);

    // A request's fixed cost in words: a slower line pays more per word than per request.
    const int at38400 = LineTiming::bridgeableGapWords(*LineFormat::parse(38400, "8N1"), map.protocol);
    const int at9600 = LineTiming::bridgeableGapWords(*LineFormat::parse(9600, "8N1"), map.protocol);
    QVERIFY2(at38400 >= 15 && at38400 <= 30, qPrintable(QString::number(at38400)));
    QVERIFY2(at9600 >= 8 && at9600 < at38400, qPrintable(QString::number(at9600)));
}

void tst_ReadPlanner::respectsWordLimit()
{
    const RegisterMap &map = *registry().family("quantrol");
    const ReadPlan plan = ReadPlanner::plan(map, QStringList{"ramp_end_value", "timer_status"});
    // 0x002F..0x0046 is 24 words: one request within the 32-word limit.
    QCOMPARE(plan.blocks.size(), 1);
    QCOMPARE(plan.blocks[0].count, quint16(24));
    const RegisterMap &dtron = *registry().family("dtron300");
    const ReadPlan full = ReadPlanner::plan(dtron);
    for (const ReadBlock &b : full.blocks)
        QVERIFY(b.count <= 32);
}

void tst_ReadPlanner::refusesWriteOnlyAndUnknown()
{
    const RegisterMap &map = *registry().family("quantrol");
    const ReadPlan plan = ReadPlanner::plan(map, QStringList{"controller_functions", "no_such_entry", "controller_status"});
    QCOMPARE(plan.blocks.size(), 1);
    QCOMPARE(plan.errors.size(), 2);
    QVERIFY(plan.errors.join('\n').contains("no_such_entry"));
    QVERIFY(plan.errors.join('\n').contains("write-only"));
}

void tst_ReadPlanner::neverSplitsAValue()
{
    // A map with a limit of 3 words and floats back to back: no block may end inside a float.
    QJsonArray entries;
    for (int i = 0; i < 5; ++i)
        entries.append(QJsonObject{{"address", QString("0x%1").arg(i * 2, 4, 16, QChar('0'))},
                                   {"id", QString("f%1").arg(i)}, {"label", "F"}, {"type", "float"},
                                   {"access", "R"}, {"group", "1"}});
    const QJsonObject json{
        {"format", 1}, {"family", "small"}, {"name", "Small"},
        {"protocol", QJsonObject{{"readFunctions", QJsonArray{3}}, {"writeFunctions", QJsonArray{16}},
                                 {"maxReadWords", 3}, {"maxWriteWords", 3}, {"floatWordOrder", "CDAB"},
                                 {"int32WordOrder", "ABCD"}, {"baudRates", QJsonArray{9600}},
                                 {"dataFormats", QJsonArray{"8N1"}}, {"addressMin", 1}, {"addressMax", 247},
                                 {"processingTimeMaxMs", 1}}},
        {"identify", QJsonArray{QJsonObject{{"address", "0x0000"}, {"words", 1}, {"answers", true}}}},
        {"exceptions", QJsonObject{{"2", "x"}}}, {"errorValues", QJsonValue()}, {"entries", entries}};
    const MapLoadResult r = MapLoader::loadData(QJsonDocument(json).toJson(), "small.json");
    QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
    const ReadPlan plan = ReadPlanner::plan(*r.map);
    QCOMPARE(plan.blocks.size(), 5);
    verifyOnlyReadableWords(*r.map, plan);
}

QTEST_GUILESS_MAIN(tst_ReadPlanner)
#include "tst_readplanner.moc"
