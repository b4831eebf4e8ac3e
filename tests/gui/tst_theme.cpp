// The themes: in light, dark and high contrast every text the HMI colours by meaning (tile
// states, banners, write states, hints, error values) is readable on its background
// (WCAG contrast 4.5:1, 7:1 for the high-contrast theme), the palette too; a window
// started with a theme (for that run) switches live from the View menu, which is kept for the
// next start; tiles follow; the states of a tile differ in their border, not in colour alone.
#include "devicepage.h"
#include "devicetile.h"
#include "mainwindow.h"
#include "protocol/familyregistry.h"
#include "theme.h"
#include "trendview.h"

#include <QChart>
#include <QChartView>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>

#include <memory>
#include <QStyleOptionButton>
#include <QImage>
#include <QLabel>
#include <QPalette>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace jumo;

class tst_Theme : public QObject
{
    Q_OBJECT

private slots:
    void textIsReadableInEveryTheme_data();
    void textIsReadableInEveryTheme();
    void namesRoundTrip();
    void windowKeepsAndSwitchesItsTheme();
    void colouredTextFollowsTheTheme();
    void uncheckedBoxesAreVisible_data();
    void uncheckedBoxesAreVisible();
    void disabledFieldsLookDisabled_data();
    void disabledFieldsLookDisabled();
};

void tst_Theme::textIsReadableInEveryTheme_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<double>("least");
    QTest::newRow("light") << int(Theme::Kind::Light) << 4.5;
    QTest::newRow("dark") << int(Theme::Kind::Dark) << 4.5;
    QTest::newRow("high contrast") << int(Theme::Kind::HighContrast) << 7.0;
}

void tst_Theme::textIsReadableInEveryTheme()
{
    QFETCH(int, kind);
    QFETCH(double, least);
    Theme::apply(Theme::Kind(kind));
    using R = Theme::Role;
    auto check = [least](const char *what, const QColor &text, const QColor &background) {
        const double ratio = Theme::contrast(text, background);
        QVERIFY2(ratio >= least, qPrintable(QStringLiteral("%1: %2 on %3 is %4:1")
                                                    .arg(QLatin1String(what), text.name(), background.name())
                                                    .arg(ratio, 0, 'f', 2)));
    };
    for (R tile : {R::TileOk, R::TileUncertain, R::TileAlarm, R::TileWarning, R::TileOffline, R::TileIdle, R::TileWrongDevice})
        check("tile text", Theme::color(R::TileText), Theme::color(tile));
    check("info banner", Theme::color(R::InfoBannerText), Theme::color(R::InfoBanner));
    check("error banner", Theme::color(R::ErrorBannerText), Theme::color(R::ErrorBanner));
    check("neutral banner", Theme::color(R::NeutralBannerText), Theme::color(R::NeutralBanner));
    const QPalette palette = QApplication::palette();
    for (QPalette::ColorRole background : {QPalette::Window, QPalette::Base}) {
        for (R text : {R::Pending, R::Confirmed, R::Refused, R::Unknown, R::Hint, R::ErrorValue})
            check("state text", Theme::color(text), palette.color(background));
    }
    check("window text", palette.color(QPalette::WindowText), palette.color(QPalette::Window));
    check("text", palette.color(QPalette::Text), palette.color(QPalette::Base));
    check("button text", palette.color(QPalette::ButtonText), palette.color(QPalette::Button));
    check("highlighted text", palette.color(QPalette::HighlightedText), palette.color(QPalette::Highlight));
    QCOMPARE(Theme::isDark(), Theme::Kind(kind) != Theme::Kind::Light);
}

void tst_Theme::namesRoundTrip()
{
    for (Theme::Kind kind : Theme::kinds())
        QCOMPARE(Theme::fromName(Theme::name(kind)), std::optional<Theme::Kind>(kind));
    QVERIFY(!Theme::fromName(QStringLiteral("purple")));
    QVERIFY(!Theme::fromName(QString()));
    QVERIFY(!Theme::fromName(QStringLiteral(" ")));
    // Typed by hand: any case, stray blanks.
    QCOMPARE(Theme::fromName(QStringLiteral("Dark")), std::optional<Theme::Kind>(Theme::Kind::Dark));
    QCOMPARE(Theme::fromName(QStringLiteral(" HIGH-CONTRAST ")), std::optional<Theme::Kind>(Theme::Kind::HighContrast));
}

void tst_Theme::windowKeepsAndSwitchesItsTheme()
{
    const FamilyRegistry registry = FamilyRegistry::load({}, true);
    QTemporaryDir dir;
    MainWindow::Options options;
    options.settingsFile = dir.filePath(QStringLiteral("theme.ini"));
    options.logFolder = dir.filePath(QStringLiteral("logs"));
    options.theme = QStringLiteral("dark");
    // The colour the faceplate is painted with, away from its frame and text.
    auto background = [](DeviceTile *tile) {
        const QImage image = tile->grab().toImage();
        return image.pixelColor(7, image.height() / 2).name();
    };
    {
        MainWindow window(registry, options);
        window.addDevice(registry.family(QStringLiteral("ipc300")), 1);
        window.show();
        QCOMPARE(Theme::current(), Theme::Kind::Dark);
        QVERIFY(QApplication::palette().color(QPalette::Window).lightness() < 128);
        DeviceTile *tile = window.deviceTile(QStringLiteral("ipc300"), 1);
        QVERIFY(tile);
        // Disconnected: the idle colour of the dark theme, a dotted border.
        QCOMPARE(background(tile), Theme::color(Theme::Role::TileIdle).name());
        QCOMPARE(tile->summaryText(), QStringLiteral("Disconnected"));
        // The trend's chart draws its own background: dark too.
        window.showDevice(QStringLiteral("ipc300"), 1);
        DevicePage *page = window.devicePage(QStringLiteral("ipc300"), 1);
        QVERIFY(page);
        auto *chartView = page->trend()->findChild<QChartView *>();
        QVERIFY(chartView);
        QCOMPARE(chartView->chart()->theme(), QChart::ChartThemeDark);
        auto *light = window.findChild<QAction *>(QStringLiteral("theme_light"));
        QVERIFY(light);
        light->trigger();
        QCOMPARE(chartView->chart()->theme(), QChart::ChartThemeLight);
        window.showOverview();   // a hidden tile takes its colours when shown
        QTRY_VERIFY(tile->isVisible());
        QCOMPARE(Theme::current(), Theme::Kind::Light);
        QVERIFY(QApplication::palette().color(QPalette::Window).lightness() >= 128);
        QCOMPARE(background(tile), Theme::color(Theme::Role::TileIdle).name());
        QVERIFY(light->isChecked());
        // Another state has another word (and shape and frame) as well as another colour.
        DeviceCondition lost;
        lost.state = DeviceCondition::State::LineLost;
        tile->setCondition(lost);
        QCOMPARE(tile->summaryText(), QStringLiteral("Line lost"));
        QCOMPARE(background(tile), Theme::color(Theme::Role::TileOffline).name());
    }
    // The choice is kept for the next start.
    options.theme.clear();
    MainWindow again(registry, options);
    QCOMPARE(Theme::current(), Theme::Kind::Light);
}

void tst_Theme::colouredTextFollowsTheTheme()
{
    // A write state shown in the light theme is coloured for the dark one after a switch
    // (a green fit for white would be unreadable on the dark window).
    Theme::apply(Theme::Kind::Light);
    QLabel state(QStringLiteral("Confirmed"));
    Theme::colourText(&state, Theme::Role::Confirmed, QStringLiteral("font-weight: bold"));
    const QString light = Theme::color(Theme::Role::Confirmed).name();
    QVERIFY(state.styleSheet().contains(light));
    Theme::apply(Theme::Kind::Dark);
    Theme::restyleWidgets();
    const QString dark = Theme::color(Theme::Role::Confirmed).name();
    QVERIFY(dark != light);
    QVERIFY2(state.styleSheet().contains(dark) && state.styleSheet().contains("bold"), qPrintable(state.styleSheet()));
    Theme::plain(&state);
    Theme::apply(Theme::Kind::Light);
    Theme::restyleWidgets();
    QVERIFY(state.styleSheet().isEmpty());
}

QTEST_MAIN(tst_Theme)
void tst_Theme::uncheckedBoxesAreVisible_data()
{
    QTest::addColumn<int>("kind");
    QTest::newRow("light") << int(Theme::Kind::Light);
    QTest::newRow("dark") << int(Theme::Kind::Dark);
    QTest::newRow("high contrast") << int(Theme::Kind::HighContrast);
}

// An unchecked box must stand out from the field it is on (3:1, as for any control's
// edge): Fusion's dark outline vanished on the dark theme's Base.
void tst_Theme::uncheckedBoxesAreVisible()
{
    QFETCH(int, kind);
    Theme::apply(Theme::Kind(kind));
    QCheckBox box(QStringLiteral("Load voltage"));
    box.resize(box.sizeHint());
    box.ensurePolished();
    QStyleOptionButton option;
    option.initFrom(&box);
    const QRect indicator = box.style()->subElementRect(QStyle::SE_CheckBoxIndicator, &option, &box);
    const QImage image = box.grab().toImage();
    const QColor window = box.palette().color(QPalette::Window);
    double best = 0;
    for (int y = indicator.top(); y <= indicator.bottom(); ++y) {
        for (int x = indicator.left(); x <= indicator.right(); ++x)
            best = std::max(best, Theme::contrast(image.pixelColor(x, y), window));
    }
    QVERIFY2(best >= 3.0, qPrintable(QStringLiteral("box edge at most %1:1 against the window").arg(best, 0, 'f', 2)));
    Theme::apply(Theme::Kind::Light);
}

void tst_Theme::disabledFieldsLookDisabled_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("widget");
    // Light and dark are Fusion's own fields; high contrast draws their edges itself.
    QTest::newRow("high contrast, combo box") << int(Theme::Kind::HighContrast) << "combo";
    QTest::newRow("high contrast, text field") << int(Theme::Kind::HighContrast) << "edit";
}

// 26.16: a disabled field must not look like one that takes input. In high contrast the
// white edge of every field made a disabled combo box look enabled: its brightest pixel
// (edge, text, arrow) must be well off the enabled one's.
void tst_Theme::disabledFieldsLookDisabled()
{
    QFETCH(int, kind);
    QFETCH(QString, widget);
    Theme::apply(Theme::Kind(kind));
    const auto light = qScopeGuard([] { Theme::apply(Theme::Kind::Light); });
    auto make = [&widget](bool enabled) -> std::unique_ptr<QWidget> {
        std::unique_ptr<QWidget> w;
        if (widget == "combo") {
            auto *box = new QComboBox;
            box->addItems({QStringLiteral("Automatic"), QStringLiteral("Manual")});
            w.reset(box);
        } else {
            w.reset(new QLineEdit(QStringLiteral("42.5")));
        }
        w->setEnabled(enabled);
        w->resize(160, w->sizeHint().height());
        w->ensurePolished();
        return w;
    };
    // The text's contrast against the window: what tells a field's state at a glance.
    auto strongest = [](QWidget *w) {
        const QImage image = w->grab().toImage();
        const QColor window = w->palette().color(QPalette::Window);
        double best = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x)
                best = std::max(best, Theme::contrast(image.pixelColor(x, y), window));
        }
        return best;
    };
    const auto enabled = make(true);
    const auto disabled = make(false);
    const double on = strongest(enabled.get());
    const double off = strongest(disabled.get());
    QVERIFY2(off < on * 0.75, qPrintable(QStringLiteral("enabled %1:1, disabled %2:1").arg(on, 0, 'f', 2).arg(off, 0, 'f', 2)));
}

#include "tst_theme.moc"
