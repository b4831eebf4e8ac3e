// Nothing cut off at 1280x800, in English and German: the HMI against the simulator,
// every page of every family's device page (the parameter editor with a change waiting),
// the overview and the device list. Every visible label, button, tab, group box title
// and item view cell (a tree's expanded rows too) must show its whole
// text (a text cut with "…" and the whole of it in the tooltip counts as shown), lie
// within the widgets around it, and no device page may scroll sideways.
#include "connectionbar.h"
#include "devicepage.h"
#include "devicetile.h"
#include "elidedlabel.h"
#include "mainwindow.h"
#include "overviewpage.h"
#include "models/livevaluesmodel.h"
#include "models/parametereditmodel.h"
#include "parametereditor.h"
#include "protocol/translations.h"
#include "testpeers.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QCheckBox>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QStandardItemModel>
#include <QStyle>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QTest>
#include <QTextDocument>
#include <QTreeView>
#include <QToolButton>
#include <QVBoxLayout>

using namespace jumo;
using namespace jumo::test;

namespace {

constexpr QChar ellipsis(0x2026);

// A text that does not fit, where, and why.
struct Cut
{
    QString where;
    QString text;
    QString problem;
};

QString plainText(const QLabel *label)
{
    if (label->textFormat() == Qt::PlainText || !Qt::mightBeRichText(label->text()))
        return label->text();
    QTextDocument doc;
    doc.setHtml(label->text());
    return doc.toPlainText();
}

// Shown cut with "…", and the tooltip has what the "…" stands for.
bool elidedWithTooltip(const QString &shown, const QString &tooltip)
{
    const qsizetype at = shown.indexOf(ellipsis);
    return at >= 0 && !tooltip.isEmpty() && tooltip.contains(shown.left(at).trimmed());
}

QString widestLine(const QFontMetrics &fm, const QString &text, int *width)
{
    QString widest;
    *width = 0;
    for (const QString &line : text.split(QLatin1Char('\n'))) {
        if (fm.horizontalAdvance(line) > *width) {
            *width = fm.horizontalAdvance(line);
            widest = line;
        }
    }
    return widest;
}

// Checks every visible widget under a root for text that does not fit.
class FitChecker
{
public:
    explicit FitChecker(QWidget *root) : m_root(root) { }

    QList<Cut> check()
    {
        m_cuts.clear();
        QList<QWidget *> widgets = m_root->findChildren<QWidget *>();
        widgets.prepend(m_root);
        for (QWidget *w : std::as_const(widgets)) {
            if (!w->isVisible() || insideComplexWidget(w))
                continue;
            if (auto *label = qobject_cast<QLabel *>(w))
                checkLabel(label);
            else if (auto *button = qobject_cast<QAbstractButton *>(w))
                checkButton(button);
            else if (auto *view = qobject_cast<QAbstractItemView *>(w))
                checkView(view);
            else if (auto *tabs = qobject_cast<QTabBar *>(w))
                checkTabBar(tabs);
            else if (auto *box = qobject_cast<QGroupBox *>(w))
                checkGroupBox(box);
        }
        return m_cuts;
    }

    // The device pages never scroll sideways.
    QList<Cut> horizontalScrollBars()
    {
        QList<Cut> cuts;
        for (QAbstractScrollArea *area : m_root->findChildren<QAbstractScrollArea *>()) {
            if (area->isVisible() && area->horizontalScrollBar()->isVisible())
                cuts << Cut{describe(area), QString(), QStringLiteral("has a horizontal scroll bar")};
        }
        return cuts;
    }

    QString describe(const QWidget *w) const
    {
        QStringList path;
        for (const QWidget *p = w; p && p != m_root->parentWidget(); p = p->parentWidget()) {
            if (!p->objectName().isEmpty() || p == w)
                path.prepend(QStringLiteral("%1(%2)").arg(QString::fromLatin1(p->metaObject()->className()),
                                                          p->objectName()));
        }
        return path.join(QLatin1Char('/'));
    }

private:
    // A combo box's line edit or a spin box's buttons are the widget's own business.
    static bool insideComplexWidget(const QWidget *w)
    {
        for (const QObject *p = w->parent(); p; p = p->parent()) {
            if (p->inherits("QComboBox") || p->inherits("QAbstractSpinBox") || p->inherits("QLineEdit")
                || p->inherits("QScrollBar"))
                return true;
        }
        return false;
    }

    void cut(const QWidget *w, const QString &text, const QString &problem)
    {
        m_cuts << Cut{describe(w), text, problem};
    }

    // The widget lies within each widget around it: across everywhere, and up and down
    // until a scroll area's viewport (content may scroll vertically, never sideways).
    void checkInside(const QWidget *w, const QString &text)
    {
        bool vertical = true;
        for (const QWidget *a = w->parentWidget(); a && !a->isWindow(); a = a->parentWidget()) {
            const auto *area = qobject_cast<const QAbstractScrollArea *>(a->parentWidget());
            if (area && area->viewport() == a)
                vertical = false;
            const QRect r(w->mapTo(a, QPoint(0, 0)), w->size());
            if (r.left() < -1 || r.right() > a->width())
                return cut(w, text, QStringLiteral("runs past the %1 edge of %2")
                                            .arg(r.left() < -1 ? QStringLiteral("left") : QStringLiteral("right"),
                                                 describe(a)));
            if (vertical && (r.top() < -1 || r.bottom() > a->height()))
                return cut(w, text, QStringLiteral("runs past the top or bottom of %1").arg(describe(a)));
        }
    }

    void checkLabel(QLabel *label)
    {
        const QString text = plainText(label).trimmed();
        if (text.isEmpty() || !label->pixmap().isNull())
            return;
        checkInside(label, text);
        if (elidedWithTooltip(text, label->toolTip()))
            return;
        if (label->wordWrap()) {
            if (label->minimumSizeHint().width() > label->width() + 1)
                cut(label, text, QStringLiteral("a word is wider than the label (%1 > %2 px)")
                                         .arg(label->minimumSizeHint().width()).arg(label->width()));
            else if (label->heightForWidth(label->width()) > label->height() + 1)
                cut(label, text, QStringLiteral("the wrapped text is taller than the label (%1 > %2 px)")
                                         .arg(label->heightForWidth(label->width())).arg(label->height()));
            return;
        }
        const QSize need = label->sizeHint();
        if (need.width() > label->width() + 1)
            cut(label, text, QStringLiteral("wider than the label (%1 > %2 px)").arg(need.width()).arg(label->width()));
        else if (need.height() > label->height() + 1)
            cut(label, text, QStringLiteral("taller than the label (%1 > %2 px)").arg(need.height()).arg(label->height()));
    }

    void checkButton(QAbstractButton *button)
    {
        const QString text = button->text().remove(QLatin1Char('&'));
        if (text.isEmpty())
            return;
        checkInside(button, text);
        int need = button->sizeHint().width();
        if (qobject_cast<QPushButton *>(button)) {
            // The style's minimum width of a push button is no text of its own.
            const int margin = button->style()->pixelMetric(QStyle::PM_ButtonMargin, nullptr, button);
            const int icon = button->icon().isNull() ? 0 : button->iconSize().width() + 4;
            need = std::min(need, button->fontMetrics().horizontalAdvance(text) + 2 * margin + icon);
        }
        if (need > button->width() + 1)
            cut(button, text, QStringLiteral("wider than the button (%1 > %2 px)").arg(need).arg(button->width()));
    }

    void checkTabBar(QTabBar *bar)
    {
        // Scroll arrows mean tabs are out of sight.
        for (const QToolButton *arrow : bar->findChildren<QToolButton *>()) {
            if (arrow->isVisible())
                return cut(bar, bar->tabText(0), QStringLiteral("the tabs do not fit: scroll arrows are shown"));
        }
        const int space = bar->style()->pixelMetric(QStyle::PM_TabBarTabHSpace, nullptr, bar);
        for (int i = 0; i < bar->count(); ++i) {
            const QString text = bar->tabText(i).remove(QLatin1Char('&'));
            const int need = bar->fontMetrics().horizontalAdvance(text) + space;
            if (need > bar->tabRect(i).width() + 1 && !bar->tabToolTip(i).contains(text))
                cut(bar, text, QStringLiteral("tab narrower than its text (%1 > %2 px)").arg(need).arg(bar->tabRect(i).width()));
            if (bar->tabRect(i).right() > bar->width())
                cut(bar, text, QStringLiteral("tab runs past the tab bar"));
        }
    }

    void checkGroupBox(QGroupBox *box)
    {
        checkInside(box, box->title());
        if (box->minimumSizeHint().width() > box->width() + 1)
            cut(box, box->title(), QStringLiteral("group box narrower than its title or contents (%1 > %2 px)")
                                           .arg(box->minimumSizeHint().width()).arg(box->width()));
    }

    void checkView(QAbstractItemView *view)
    {
        if (qobject_cast<QHeaderView *>(view) || !view->model())
            return;
        checkInside(view, QString());
        const QAbstractItemModel *model = view->model();
        const auto *table = qobject_cast<QTableView *>(view);
        const auto *list = qobject_cast<QListView *>(view);
        const auto *tree = qobject_cast<QTreeView *>(view);
        checkRows(view, view->rootIndex());
        const QHeaderView *header = table ? table->horizontalHeader() : tree ? tree->header() : nullptr;
        Q_UNUSED(list)
        if (!header || !header->isVisible())
            return;
        const int headerMargin = header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
        for (int section = 0; section < header->count(); ++section) {
            if (header->isSectionHidden(section))
                continue;
            const QString text = model->headerData(section, Qt::Horizontal).toString();
            const int need = header->fontMetrics().horizontalAdvance(text) + 2 * headerMargin;
            if (need > header->sectionSize(section) + 1)
                m_cuts << Cut{describe(view), text, QStringLiteral("header narrower than its title (%1 > %2 px)")
                                                           .arg(need).arg(header->sectionSize(section))};
        }
    }

    // The rows under a parent, and in a tree those under each expanded row.
    void checkRows(QAbstractItemView *view, const QModelIndex &parent)
    {
        const QAbstractItemModel *model = view->model();
        const QRect viewport = view->viewport()->rect();
        const auto *table = qobject_cast<QTableView *>(view);
        const auto *list = qobject_cast<QListView *>(view);
        const auto *tree = qobject_cast<QTreeView *>(view);
        const bool wraps = (table && table->wordWrap()) || (list && list->wordWrap());
        const int margin = 2 * (view->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, view) + 1);
        for (int row = 0; row < model->rowCount(parent); ++row) {
            for (int column = 0; column < model->columnCount(parent); ++column) {
                if ((table && table->isColumnHidden(column)) || (tree && tree->isColumnHidden(column)))
                    continue;
                const QModelIndex index = model->index(row, column, parent);
                const QRect rect = view->visualRect(index);
                const QString text = index.data().toString();
                if (text.isEmpty() || !rect.isValid() || !rect.intersects(viewport))
                    continue;
                const QString where = QStringLiteral("%1 cell %2,%3%4")
                                              .arg(describe(view))
                                              .arg(row)
                                              .arg(column)
                                              .arg(parent.isValid() ? QStringLiteral(" under %1").arg(parent.row()) : QString());
                if (rect.right() > viewport.right() + 1) {
                    m_cuts << Cut{where, text, QStringLiteral("runs past the view's right edge")};
                    continue;
                }
                // A list that wraps lays each item out to fit its width.
                if (list && wraps)
                    continue;
                const QFontMetrics fm(index.data(Qt::FontRole).isValid() ? index.data(Qt::FontRole).value<QFont>()
                                                                         : view->font());
                const bool hasTip = index.data(Qt::ToolTipRole).toString().contains(text);
                if (table && wraps) {
                    // Wrapped in a row of fixed height: the lines must fit in it.
                    const int height = fm.boundingRect(QRect(0, 0, std::max(1, rect.width() - margin), 100000),
                                                       Qt::TextWordWrap, text).height();
                    if (height > rect.height() + 1 && !hasTip)
                        m_cuts << Cut{where, text, QStringLiteral("wrapped cell text taller than its row (%1 > %2 px)")
                                                           .arg(height).arg(rect.height())};
                    continue;
                }
                int width = 0;
                widestLine(fm, text, &width);
                int need = width + margin;
                if (!index.data(Qt::DecorationRole).isNull())
                    need += view->iconSize().isValid() ? view->iconSize().width() + 4 : 20;
                if (index.data(Qt::CheckStateRole).isValid())
                    need += view->style()->pixelMetric(QStyle::PM_IndicatorWidth, nullptr, view) + 4;
                const bool elides = view->textElideMode() != Qt::ElideNone;
                if (need > rect.width() + 1 && !(elides && hasTip))
                    m_cuts << Cut{where, text, QStringLiteral("cell narrower than its text (%1 > %2 px) without the text in its tooltip")
                                                       .arg(need).arg(rect.width())};
            }
            const QModelIndex first = model->index(row, 0, parent);
            if (tree && model->hasChildren(first) && tree->isExpanded(first))
                checkRows(view, first);
        }
    }

    QWidget *m_root;
    QList<Cut> m_cuts;
};

// Every finding on a line of its own.
QString report(const QList<Cut> &cuts)
{
    QStringList lines;
    for (const Cut &c : cuts) {
        lines << QStringLiteral("%1: \"%2\": %3").arg(c.where, c.text.left(80), c.problem);
    }
    return lines.join(QLatin1Char('\n'));
}

bool mentions(const QList<Cut> &cuts, const QString &name)
{
    return std::any_of(cuts.cbegin(), cuts.cend(), [&](const Cut &c) { return c.where.contains(name); });
}

// Faceplates side by side that differ in height (the rows of a row: a power unit's and a
// programmer's), as "name: height, name: height"; empty when every row is even.
QString unevenRows(const QList<DeviceTile *> &tiles)
{
    QMap<int, QList<DeviceTile *>> rows;
    for (DeviceTile *tile : tiles)
        rows[tile->mapToGlobal(QPoint(0, 0)).y()] << tile;
    QStringList uneven;
    for (const QList<DeviceTile *> &row : std::as_const(rows)) {
        for (DeviceTile *tile : row) {
            if (tile->height() != row.first()->height())
                uneven << QStringLiteral("%1: %2, %3: %4").arg(row.first()->objectName()).arg(row.first()->height())
                                  .arg(tile->objectName()).arg(tile->height());
        }
    }
    return uneven.join(QStringLiteral("; "));
}

// Lets posted layout requests and resizes settle.
void settle()
{
    for (int i = 0; i < 3; ++i) {
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents();
    }
}

} // namespace

class tst_LayoutFit : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void checkerFindsCutTexts();
    void everyPageFits_data();
    void everyPageFits();
    void thirtyOneFaceplatesFitAFullHdScreen();
    void faceplatesGrowOnALargeScreen();

private:
    // A window of a full line (31 devices of the four families, none connected) at this
    // size, on its overview, laid out.
    std::unique_ptr<MainWindow> fullLine(const QString &name, QSize size);
    static QStringList fullLineOrder() { return {"ipc300", "tya200", "quantrol", "dtron300"}; }

    QTemporaryDir m_dir;
    TestLine m_line;
    SimulatorPeer m_sim;
};

void tst_LayoutFit::initTestCase()
{
    QVERIFY(m_line.start());
    QVERIFY(m_sim.startOneOfEachFamily(m_line.deviceEnd()));
}

void tst_LayoutFit::cleanupTestCase()
{
    useLanguage(*qApp, QLocale(QLocale::English, QLocale::UnitedStates));
}

// The checker itself: each way of cutting a text is found, and what fits is not.
void tst_LayoutFit::checkerFindsCutTexts()
{
    const QString longText = QStringLiteral("Load voltage not connected to the supply at all");
    QWidget window;
    window.resize(500, 900);
    auto *layout = new QVBoxLayout(&window);

    auto *narrow = new QWidget(&window);
    narrow->setFixedSize(80, 30);
    auto *clipped = new QLabel(longText, narrow);   // no layout: keeps its own width, cut by its parent
    clipped->setObjectName("clippedLabel");
    clipped->resize(clipped->sizeHint());
    layout->addWidget(narrow);

    auto *squeezed = new QLabel(longText, &window);
    squeezed->setObjectName("squeezedLabel");
    squeezed->setMinimumWidth(0);
    squeezed->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    squeezed->setFixedWidth(60);
    layout->addWidget(squeezed);

    auto *wrappedShort = new QLabel(longText, &window);
    wrappedShort->setObjectName("wrappedTooShort");
    wrappedShort->setWordWrap(true);
    wrappedShort->setFixedSize(90, wrappedShort->fontMetrics().height());
    layout->addWidget(wrappedShort);

    auto *wrappedFits = new QLabel(longText, &window);
    wrappedFits->setObjectName("wrappedFits");
    wrappedFits->setWordWrap(true);
    layout->addWidget(wrappedFits);

    auto *elided = new ElidedLabel(&window);
    elided->setObjectName("elidedWithTooltip");
    elided->setFullText(longText);
    elided->setFixedWidth(90);
    layout->addWidget(elided);

    auto *elidedBare = new QLabel(longText.left(10) + ellipsis, &window);
    elidedBare->setObjectName("elidedWithoutTooltip");
    elidedBare->setFixedWidth(elidedBare->fontMetrics().horizontalAdvance(longText.left(4)));
    layout->addWidget(elidedBare);

    auto *scroll = new QScrollArea(&window);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto *content = new QWidget;
    content->setMinimumWidth(900);
    auto *button = new QPushButton(QStringLiteral("Start autotuning"), content);
    button->setObjectName("buttonOffTheEdge");
    button->move(700, 0);
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    layout->addWidget(scroll);

    auto *model = new QStandardItemModel(1, 2, &window);
    model->setItem(0, 0, new QStandardItem(longText));
    auto *withTip = new QStandardItem(longText);
    withTip->setToolTip(longText);
    model->setItem(0, 1, withTip);
    auto *table = new QTableView(&window);
    table->setObjectName("narrowTable");
    table->setModel(model);
    table->setColumnWidth(0, 60);
    table->setColumnWidth(1, 60);
    table->setMinimumHeight(100);
    layout->addWidget(table);

    auto *list = new QListWidget(&window);
    list->setObjectName("clippedList");
    list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    list->addItem(longText);
    list->setFixedWidth(100);
    layout->addWidget(list);

    // A tree: the rows under an expanded group are checked too.
    auto *treeModel = new QStandardItemModel(0, 1, &window);
    auto *group = new QStandardItem(QStringLiteral("Group"));
    group->appendRow(new QStandardItem(longText));
    treeModel->appendRow(group);
    auto *tree = new QTreeView(&window);
    tree->setObjectName("clippedTree");
    tree->setModel(treeModel);
    tree->header()->setStretchLastSection(false);
    tree->setColumnWidth(0, 90);
    tree->setMinimumHeight(80);
    tree->expandAll();
    layout->addWidget(tree);

    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    settle();

    const QList<Cut> cuts = FitChecker(&window).check();
    const QString found = report(cuts);
    for (const char *name : {"clippedLabel", "squeezedLabel", "wrappedTooShort", "elidedWithoutTooltip",
                             "buttonOffTheEdge", "clippedList"})
        QVERIFY2(mentions(cuts, name), qPrintable(QStringLiteral("%1 not found in:\n%2").arg(name, found)));
    QVERIFY2(!mentions(cuts, "wrappedFits"), qPrintable(found));
    QVERIFY2(!mentions(cuts, "elidedWithTooltip"), qPrintable(found));
    // In the table: the cell without its text in the tooltip, not the one with it.
    QVERIFY2(mentions(cuts, "narrowTable) cell 0,0"), qPrintable(found));
    QVERIFY2(!mentions(cuts, "narrowTable) cell 0,1"), qPrintable(found));
    QVERIFY2(mentions(cuts, "clippedTree) cell 0,0 under 0"), qPrintable(found));
    QVERIFY2(!mentions(cuts, "clippedTree) cell 0,0:"), qPrintable(found));

    // A page that scrolls sideways is found as well.
    QWidget holder;
    auto *holderLayout = new QVBoxLayout(&holder);
    auto *sideways = new QScrollArea(&holder);
    sideways->setObjectName("sideways");
    auto *wide = new QWidget;
    wide->setMinimumWidth(900);
    sideways->setWidget(wide);
    sideways->setWidgetResizable(true);
    holderLayout->addWidget(sideways);
    holder.resize(320, 220);
    holder.show();
    QVERIFY(QTest::qWaitForWindowExposed(&holder));
    settle();
    QVERIFY(mentions(FitChecker(&holder).horizontalScrollBars(), "sideways"));
}

void tst_LayoutFit::everyPageFits_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("English") << "en";
    QTest::newRow("German") << "de";
}

void tst_LayoutFit::everyPageFits()
{
    QFETCH(QString, language);
    const QLocale locale = language == QLatin1String("de") ? QLocale(QLocale::German, QLocale::Germany)
                                                           : QLocale(QLocale::English, QLocale::UnitedStates);
    // English needs no translation; German must have one, or the row tests nothing.
    QCOMPARE(useLanguage(*qApp, locale), language == QLatin1String("de"));

    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(QStringLiteral("fit-%1.ini").arg(language));
    options.logFolder = m_dir.filePath(QStringLiteral("logs-%1").arg(language));
    MainWindow window(families(), options);
    window.connectionBar()->setSettings(m_line.masterEnd(), 19200, "8N1");
    QVERIFY(window.connectLine());
    const QList<QPair<QString, quint8>> devices{{"ipc300", 1}, {"tya200", 2}, {"quantrol", 3}, {"dtron300", 4}};
    for (const auto &[family, address] : devices)
        QVERIFY(window.addDevice(families().family(family), address));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QCOMPARE(window.size(), QSize(1280, 800));

    // The overview and the device list, once every device answers.
    window.showOverview();
    for (const auto &[family, address] : devices) {
        DeviceTile *tile = window.deviceTile(family, address);
        QTRY_VERIFY_WITH_TIMEOUT(tile->stateText() == DeviceTile::conditionText({DeviceCondition::State::Online, {}, {}}),
                                 30000);
        QTRY_VERIFY_WITH_TIMEOUT(!tile->valuesText().contains(QChar(0x2014)), 30000);
    }
    settle();
    QList<Cut> cuts = FitChecker(&window).check();

    for (const auto &[family, address] : devices) {
        DevicePage *page = window.devicePage(family, address);
        window.showDevice(page);
        // Live values first: the pages show what the device reports, not empty fields.
        const RegisterMap &map = *families().family(family);
        for (const QString &id : map.overview) {
            const QModelIndex value = page->values()->index(page->values()->rowOf(id), LiveValuesModel::ValueColumn);
            QTRY_VERIFY_WITH_TIMEOUT(Validity(value.data(LiveValuesModel::ValidityRole).toInt()) == Validity::Current,
                                     30000);
        }
        // The parameter editor with a change waiting: the mark, the bold value, the counts.
        ParameterEditModel *parameters = page->parameters()->model();
        const QString first = parameters->entryIds().value(0);
        QVERIFY(parameters->setNewValue(first, QStringLiteral("1")) && parameters->isChanged(first));
        for (int tab = 0; tab < page->tabs()->count(); ++tab) {
            page->tabs()->setCurrentIndex(tab);
            settle();
            FitChecker checker(page);
            for (Cut &c : checker.check() + checker.horizontalScrollBars()) {
                c.where = QStringLiteral("%1@%2 tab \"%3\": %4").arg(family).arg(address).arg(page->tabs()->tabText(tab), c.where);
                cuts << c;
            }
        }
        settle();
        cuts << FitChecker(window.findChild<QListWidget *>(QStringLiteral("navigation"))).check();
    }
    const QString found = report(cuts);
    if (!cuts.isEmpty())
        qInfo().noquote() << found;
    QVERIFY2(cuts.isEmpty(), qPrintable(QStringLiteral("%1 text(s) cut off, listed above").arg(cuts.size())));
}

// 26.16: on a 3840x2160 screen a full line does not sit in a corner of it (85 % of it
// was empty): the faceplates grow, within reason, and still all fit without scrolling.
void tst_LayoutFit::faceplatesGrowOnALargeScreen()
{
    const auto full = fullLine(QStringLiteral("4k"), QSize(3840, 2160 - 40));
    QVERIFY(full);
    MainWindow &window = *full;
    auto *overview = window.findChild<OverviewPage *>(QStringLiteral("overview"));
    QVERIFY(overview);
    QWidget *viewport = overview->scrollArea()->viewport();
    QVERIFY(!overview->scrollArea()->verticalScrollBar()->isVisible());
    qint64 covered = 0;
    const QList<DeviceTile *> tiles = overview->findChildren<DeviceTile *>();
    QCOMPARE(tiles.size(), 31);
    for (DeviceTile *tile : tiles) {
        const QRect onScreen(tile->mapTo(viewport, QPoint(0, 0)), tile->size());
        QVERIFY2(viewport->rect().contains(onScreen), qPrintable(tile->objectName()));
        QVERIFY(tile->height() >= tile->sizeHint().height());
        covered += qint64(onScreen.width()) * onScreen.height();
    }
    const double share = double(covered) / (qint64(viewport->width()) * viewport->height());
    qInfo("31 faceplates on 3840x2120: %d columns, scale %.2f, %.0f %% of the overview covered", overview->columns(),
          overview->scale(), share * 100);
    QVERIFY2(share >= 0.5, qPrintable(QStringLiteral("%1 % covered").arg(share * 100, 0, 'f', 0)));
    QVERIFY(overview->scale() > 1 && overview->scale() <= 2);
    QCOMPARE(overview->density(), DeviceTile::Density::Comfortable);
    const QString uneven = unevenRows(tiles);
    QVERIFY2(uneven.isEmpty(), qPrintable(uneven));
    // Faceplates are read as before at their own size: a small window keeps them so.
    window.resize(1280, 800);
    settle();
    QTRY_COMPARE(overview->scale(), 1.0);
    // Four devices on a desk's screen keep their own size; on the large one they grow.
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(QStringLiteral("fit-4-4k.ini"));
    options.logFolder = m_dir.filePath(QStringLiteral("logs-4k"));
    MainWindow few(families(), options);
    for (int address = 1; address <= 4; ++address)
        QVERIFY(few.addDevice(families().family(fullLineOrder().at(address % 4)), quint8(address)));
    few.resize(1280, 800);
    few.show();
    QVERIFY(QTest::qWaitForWindowExposed(&few));
    few.showOverview();
    settle();
    auto *fewOverview = few.findChild<OverviewPage *>(QStringLiteral("overview"));
    QCOMPARE(fewOverview->density(), DeviceTile::Density::Comfortable);
    QCOMPARE(fewOverview->scale(), 1.0);
    few.resize(3840, 2160 - 40);
    settle();
    QTRY_COMPARE(fewOverview->scale(), 2.0);
}

QTEST_MAIN(tst_LayoutFit)
#include "tst_layoutfit.moc"

std::unique_ptr<MainWindow> tst_LayoutFit::fullLine(const QString &name, QSize size)
{
    MainWindow::Options options;
    options.settingsFile = m_dir.filePath(QStringLiteral("fit-%1.ini").arg(name));
    options.logFolder = m_dir.filePath(QStringLiteral("logs-%1").arg(name));
    auto window = std::make_unique<MainWindow>(families(), options);
    const QStringList order = fullLineOrder();
    for (int address = 1; address <= 31; ++address) {
        if (!window->addDevice(families().family(order.at(address % 4)), quint8(address)))
            return nullptr;
    }
    window->resize(size);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get()))
        return nullptr;
    window->showOverview();
    QTest::qWait(50);
    settle();
    return window;
}

// A full line (31 devices) on the overview of a 1920x1080 screen, less a title bar: every
// faceplate whole on screen, no scroll bar, each at least as wide as it needs.
void tst_LayoutFit::thirtyOneFaceplatesFitAFullHdScreen()
{
    const auto full = fullLine(QStringLiteral("31"), QSize(1920, 1080 - 40));
    QVERIFY(full);
    MainWindow &window = *full;
    const QStringList order = fullLineOrder();
    auto *overview = window.findChild<OverviewPage *>(QStringLiteral("overview"));
    QVERIFY(overview);
    QWidget *viewport = overview->scrollArea()->viewport();
    qInfo("31 faceplates: %d columns, %s, viewport %dx%d", overview->columns(),
          overview->density() == DeviceTile::Density::Compact ? "compact" : "comfortable", viewport->width(),
          viewport->height());
    QVERIFY(!overview->scrollArea()->verticalScrollBar()->isVisible());
    for (int address = 1; address <= 31; ++address) {
        DeviceTile *tile = window.deviceTile(order.at(address % 4), quint8(address));
        QVERIFY(tile && tile->isVisible());
        const QRect onScreen(tile->mapTo(viewport, QPoint(0, 0)), tile->size());
        QVERIFY2(viewport->rect().contains(onScreen),
                 qPrintable(QStringLiteral("%1 at %2,%3 %4x%5").arg(tile->objectName()).arg(onScreen.x()).arg(onScreen.y())
                                    .arg(onScreen.width()).arg(onScreen.height())));
        QVERIFY(tile->width() >= tile->minimumSizeHint().width());
        QVERIFY(tile->height() >= tile->sizeHint().height());
    }
    QCOMPARE(overview->density(), DeviceTile::Density::Compact);
    // 26.16: a row reads as one line of boxes, whatever kinds of device it holds.
    const QString uneven = unevenRows(overview->findChildren<DeviceTile *>());
    QVERIFY2(uneven.isEmpty(), qPrintable(uneven));
    // Four devices keep the comfortable faceplates.
    MainWindow::Options options;
    options.logFolder = m_dir.filePath(QStringLiteral("logs-31"));
    options.settingsFile = m_dir.filePath(QStringLiteral("fit-4.ini"));
    MainWindow few(families(), options);
    for (int address = 1; address <= 4; ++address)
        QVERIFY(few.addDevice(families().family(order.at(address % 4)), quint8(address)));
    few.show();
    QVERIFY(QTest::qWaitForWindowExposed(&few));
    few.showOverview();
    auto *fewOverview = few.findChild<OverviewPage *>(QStringLiteral("overview"));
    QTRY_COMPARE(fewOverview->density(), DeviceTile::Density::Comfortable);
}
