// The identity check in simulated time: a device is confirmed only when the scan, with
// every family's identify probes in scan order, names the family the user named; what
// answers instead is named; a silent address is told apart from a wrong device.
#include "bus/identitycheck.h"
#include "fakeline.h"

#include <QSignalSpy>
#include <QTest>

using namespace jumo;
using namespace jumo::test;

class tst_IdentityCheck : public QObject
{
    Q_OBJECT

private slots:
    void verdicts_data();
    void verdicts();
    void everyClaimIsCheckedInTurn();
    void familiesWithTheSameProbesConfirmEachOther();
    void aProbeLostPartWayIsNoWrongDevice();

private:
    static QList<IdentityCheck::Finding> check(
            Line &line, const QList<IdentityCheck::Claim> &claims, Job::Result *result = nullptr,
            const QList<std::shared_ptr<const RegisterMap>> &known = families().families());
};

QList<IdentityCheck::Finding> tst_IdentityCheck::check(Line &line, const QList<IdentityCheck::Claim> &claims,
                                                       Job::Result *result,
                                                       const QList<std::shared_ptr<const RegisterMap>> &known)
{
    if (!line.bus->open())
        return {};
    IdentityCheck check(*line.bus, known);
    QSignalSpy finished(&check, &Job::finished);
    check.start(claims);
    if (!line.runUntil([&] { return finished.count() == 1; }, 60000))
        return {};
    if (result)
        *result = check.result();
    return check.findings();
}

void tst_IdentityCheck::verdicts_data()
{
    QTest::addColumn<QString>("answers");   // the family at address 4, empty for none
    QTest::addColumn<QString>("named");
    QTest::addColumn<int>("verdict");
    QTest::addColumn<QString>("found");
    using V = IdentityCheck::Verdict;
    QTest::newRow("dtron300 named, dtron300 answers") << "dtron300" << "dtron300" << int(V::Confirmed) << "dtron300";
    QTest::newRow("quantrol named, dtron300 answers") << "dtron300" << "quantrol" << int(V::OtherFamily) << "dtron300";
    QTest::newRow("dtron300 named, quantrol answers") << "quantrol" << "dtron300" << int(V::OtherFamily) << "quantrol";
    QTest::newRow("quantrol named, ipc300 answers") << "ipc300" << "quantrol" << int(V::OtherFamily) << "ipc300";
    QTest::newRow("ipc300 named, tya200 answers") << "tya200" << "ipc300" << int(V::OtherFamily) << "tya200";
    QTest::newRow("tya200 named, tya200 answers") << "tya200" << "tya200" << int(V::Confirmed) << "tya200";
    QTest::newRow("ipc300 named, nobody answers") << "" << "ipc300" << int(V::Silent) << "";
}

void tst_IdentityCheck::verdicts()
{
    QFETCH(QString, answers);
    QFETCH(QString, named);
    QFETCH(int, verdict);
    QFETCH(QString, found);
    Line line(answers.isEmpty() ? QList<QPair<QString, int>>{} : QList<QPair<QString, int>>{{answers, 4}});
    Job::Result result = Job::Result::None;
    const QList<IdentityCheck::Finding> findings = check(line, {{4, families().family(named)}}, &result);
    QCOMPARE(findings.size(), 1);
    QCOMPARE(int(findings[0].verdict), verdict);
    QCOMPARE(findings[0].found ? findings[0].found->family : QString(), found);
    QCOMPARE(result, verdict == int(IdentityCheck::Verdict::Confirmed) ? Job::Result::Succeeded : Job::Result::Failed);
    if (verdict == int(IdentityCheck::Verdict::OtherFamily))
        QVERIFY2(IdentityCheck::describe(findings[0]).contains(QStringLiteral("is a %1").arg(found)),
                 qPrintable(IdentityCheck::describe(findings[0])));
    // Nothing but reads went out.
    for (const FakeTransport::Sent &s : std::as_const(line.transport->sent))
        QVERIFY(!s.request.isWrite());
}

void tst_IdentityCheck::everyClaimIsCheckedInTurn()
{
    Line line({{"ipc300", 1}, {"dtron300", 4}});
    Job::Result result = Job::Result::None;
    const QList<IdentityCheck::Finding> findings =
            check(line, {{1, families().family("ipc300")}, {4, families().family("dtron300")},
                         {5, families().family("dtron300")}},
                  &result);
    QCOMPARE(findings.size(), 3);
    QCOMPARE(findings[0].verdict, IdentityCheck::Verdict::Confirmed);
    QCOMPARE(findings[1].verdict, IdentityCheck::Verdict::Confirmed);
    QCOMPARE(findings[2].verdict, IdentityCheck::Verdict::Silent);
    QCOMPARE(result, Job::Result::Failed);
}

void tst_IdentityCheck::familiesWithTheSameProbesConfirmEachOther()
{
    // A user's variant of a family (another id, the same identify probes) is scanned
    // after the built-in one; a device cannot tell them apart, so either is confirmed.
    RegisterMap variant = *families().family("dtron300");
    variant.family = QStringLiteral("dtron300_plant");
    variant.scanPriority = families().family("dtron300")->scanPriority;
    auto plant = std::make_shared<const RegisterMap>(variant);
    Line line({{"dtron300", 4}});
    QList<std::shared_ptr<const RegisterMap>> known = families().families();
    known << plant;
    Job::Result result = Job::Result::None;
    const QList<IdentityCheck::Finding> findings = check(line, {{4, plant}}, &result, known);
    QCOMPARE(findings.size(), 1);
    QCOMPARE(findings[0].verdict, IdentityCheck::Verdict::Confirmed);
    QCOMPARE(result, Job::Result::Succeeded);
}

void tst_IdentityCheck::aProbeLostPartWayIsNoWrongDevice()
{
    // A quantrol answers its first probe (exception 02 at 0x4009); both tries of the
    // second (0x0020) are lost on a noisy line. That is no answer, not another device:
    // a wrong-device verdict would lock the right one out until it goes offline.
    Line line({{"quantrol", 4}});
    QVERIFY(line.bus->open());
    int lost = 0;
    line.transport->drop = [&lost](const ModbusRequest &r) {
        return r.start == 0x0020 && lost < 2 && ++lost > 0;
    };
    IdentityCheck check(*line.bus, families().families());
    QSignalSpy finished(&check, &Job::finished);
    check.start({{4, families().family("quantrol")}});
    QVERIFY(line.runUntil([&] { return finished.count() == 1; }, 60000));
    QCOMPARE(lost, 2);
    QCOMPARE(check.findings().size(), 1);
    QCOMPARE(check.findings()[0].verdict, IdentityCheck::Verdict::Silent);
    QVERIFY(!check.foundOtherDevice());

    // Asked again once the line is quiet, it is confirmed.
    check.start({{4, families().family("quantrol")}});
    QVERIFY(line.runUntil([&] { return finished.count() == 2; }, 60000));
    QCOMPARE(check.findings()[0].verdict, IdentityCheck::Verdict::Confirmed);
}

QTEST_GUILESS_MAIN(tst_IdentityCheck)
#include "tst_identitycheck.moc"
