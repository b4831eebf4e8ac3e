// Texts people read that do not come from our own tr() calls go through a translation
// all the same: the families' names from the maps (the Quantrol's "universal PID
// controller") and Qt's own words for a serial port that is lost ("Resource error."),
// which our translation lists since Qt's may not be installed.
#include "commissioning/commissioningreport.h"
#include "protocol/familyregistry.h"
#include "protocol/translations.h"
#include "sim/ptypair.h"

#include <QModbusRtuSerialClient>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

using namespace jumo;

namespace {

// Translates only what the product offers for translation: Qt's messages of our table
// and the maps' family names, each as "[de] " and the English words.
class TableTranslator : public QTranslator
{
public:
    bool isEmpty() const override { return false; }
    QString translate(const char *context, const char *source, const char * = nullptr, int = -1) const override
    {
        for (const QtMessage &m : qtMessages()) {
            if (qstrcmp(context, m.context) == 0 && qstrcmp(source, m.source) == 0)
                return QStringLiteral("[de] ") + QString::fromUtf8(source);
        }
        if (qstrcmp(context, "jumo::maps") == 0 && qstrcmp(source, "Quantrol LC100 / LC200 / LC300 universal PID controller") == 0)
            return QStringLiteral("[de] ") + QString::fromUtf8(source);
        return {};
    }
};

} // namespace

class tst_TranslatedTexts : public QObject
{
    Q_OBJECT

private slots:
    void familyNameInTheLanguageShown();
    void lostSerialPortInTheLanguageShown();
};

// 26.15: "universal PID controller" in the report and on the page, in German too.
void tst_TranslatedTexts::familyNameInTheLanguageShown()
{
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    const auto quantrol = registry.family("quantrol");
    TableTranslator translator;
    QCoreApplication::installTranslator(&translator);
    const auto remove = qScopeGuard([&translator] { QCoreApplication::removeTranslator(&translator); });
    QCOMPARE(quantrol->displayName(), QString("[de] Quantrol LC100 / LC200 / LC300 universal PID controller"));
    const QString html = CommissioningReport(*quantrol, 3, [](const QString &) { return nullptr; }).html();
    QVERIFY2(html.contains("[de] Quantrol LC100 / LC200 / LC300 universal PID controller"), qPrintable(html.left(3000)));
}

// 26.15: Qt's words when the far end of a serial line goes ("Resource error.") are ones
// our translation has.
void tst_TranslatedTexts::lostSerialPortInTheLanguageShown()
{
    QTemporaryDir dir;
    PtyPair pair;
    QSignalSpy ready(&pair, &PtyPair::ready);
    pair.start(dir.path());
    QVERIFY(ready.wait(20000));
    TableTranslator translator;
    QCoreApplication::installTranslator(&translator);
    const auto remove = qScopeGuard([&translator] { QCoreApplication::removeTranslator(&translator); });
    QModbusRtuSerialClient client;
    client.setConnectionParameter(QModbusDevice::SerialPortNameParameter, pair.masterEnd());
    QVERIFY(client.connectDevice());
    QTRY_COMPARE(client.state(), QModbusDevice::ConnectedState);
    QSignalSpy errors(&client, &QModbusDevice::errorOccurred);
    pair.stop();
    QTRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty(), 20000);
    QVERIFY2(client.errorString().startsWith("[de] "), qPrintable(client.errorString()));
}

QTEST_MAIN(tst_TranslatedTexts)
#include "tst_translatedtexts.moc"
