// The filter of the journal and audit pages, on the lines as they are in the log: a text
// in a shown column's value, regardless of case, the time as shown (local time); never
// a key, a hidden column, a cut line or a line that is no record.
#include "logs/recordfilter.h"

#include <QDateTime>
#include <QTest>

using namespace jumo;

class tst_RecordFilter : public QObject
{
    Q_OBJECT

private slots:
    void matches_data();
    void matches();
};

void tst_RecordFilter::matches_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QByteArray>("line");
    QTest::addColumn<bool>("match");
    const QByteArray record = R"({"bit":7,"device":"ipc300@1","id":"malfunction_signal_1.fuse_failure","label":"Fuse failure","message":"hidden words","state":"set","time":"2024-03-01T12:34:56.789Z"})";
    QTest::newRow("a value") << "fuse" << record << true;
    QTest::newRow("a value, other case") << "IPC300@1" << record << true;
    QTest::newRow("a number") << "7" << record << true;
    QTest::newRow("a key only") << "device" << record << false;
    QTest::newRow("a key and a colon") << "label\":" << record << false;
    QTest::newRow("a column not shown") << "hidden" << record << false;
    QTest::newRow("in no value") << "overtemperature" << record << false;
    QTest::newRow("the empty text: any record") << "" << record << true;
    QTest::newRow("a cut line") << "fuse" << QByteArray(R"({"label":"Fuse fail)") << false;
    QTest::newRow("the empty text: no cut line") << "" << QByteArray(R"({"label":"Fuse fail)") << false;
    QTest::newRow("not a record") << "fuse" << QByteArray(R"(["fuse"])") << false;
    QTest::newRow("broken inside braces") << "fuse" << QByteArray(R"({"label":"fuse",})") << false;
    QTest::newRow("quotes, escaped in the line") << "\"out of range\""
                                                 << QByteArray(R"({"label":"refused: \"out of range\""})") << true;
    QTest::newRow("an escaped letter") << "fuse" << QByteArray(R"({"label":"f\u0075se"})") << true;
    QTest::newRow("beyond ASCII, other case") << "übertemp" << QByteArray(R"({"label":"Übertemperatur"})") << true;
    const QString shown = QDateTime::fromString("2024-03-01T12:34:56.789Z", Qt::ISODateWithMs)
                                  .toLocalTime()
                                  .toString("yyyy-MM-dd HH:mm:ss.zzz");
    QTest::newRow("the time as shown") << shown.left(16) << record << true;
    QTest::newRow("the time to the millisecond") << shown << record << true;
}

void tst_RecordFilter::matches()
{
    QFETCH(QString, text);
    QFETCH(QByteArray, line);
    RecordFilter filter(text, {"time", "device", "bit", "id", "label", "state"});
    QTEST(filter.matches(line), "match");
}

QTEST_GUILESS_MAIN(tst_RecordFilter)
#include "tst_recordfilter.moc"
