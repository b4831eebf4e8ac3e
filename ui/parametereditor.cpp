#include "parametereditor.h"

#include "commissioning/parameterset.h"
#include "commissioning/parametertransfer.h"
#include "devicetile.h"
#include "models/devicetitle.h"
#include "models/parametereditmodel.h"
#include "models/viewinterest.h"
#include "parametervaluedelegate.h"
#include "parameterwritepreview.h"
#include "protocol/regularfile.h"
#include "protocol/valueformat.h"

#include <QAction>
#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QStyle>
#include <QTreeView>
#include <QVBoxLayout>

namespace jumo {

namespace {

QString translatedLabel(const QString &label)
{
    return QCoreApplication::translate("jumo::maps", label.toUtf8().constData());
}

// Down or Enter in the search field goes on to the first parameter found; Escape empties it.
class SearchKeys : public QObject
{
public:
    SearchKeys(QLineEdit *field, QTreeView *tree) : QObject(field), m_field(field), m_tree(tree) { }

    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (watched != m_field || event->type() != QEvent::KeyPress)
            return false;
        const auto *key = static_cast<QKeyEvent *>(event);
        if (key->key() == Qt::Key_Escape && !m_field->text().isEmpty()) {
            m_field->clear();
            return true;
        }
        if (key->key() == Qt::Key_Down || key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) {
            QAbstractItemModel *model = m_tree->model();
            const QModelIndex group = model->index(0, 0);
            const QModelIndex first = model->rowCount(group) > 0
                    ? model->index(0, ParameterEditModel::NewValueColumn, group)
                    : group;
            if (first.isValid())
                m_tree->setCurrentIndex(first);
            m_tree->setFocus(Qt::ShortcutFocusReason);
            return true;
        }
        return false;
    }

private:
    QLineEdit *m_field;
    QTreeView *m_tree;
};

} // namespace

ParameterEditor::ParameterEditor(Bus *bus, DeviceId device, QWidget *parent)
    : QWidget(parent), m_bus(bus), m_device(device), m_model(new ParameterEditModel(bus, device, this)),
      m_interest(new ViewInterest(bus, device, this)),
      m_filter(new QSortFilterProxyModel(this)), m_delegate(new ParameterValueDelegate(m_model, this)),
      m_transfer(new ParameterTransfer(bus, device, this)), m_tree(new QTreeView(this)), m_search(new QLineEdit(this)),
      m_noMatch(new QLabel(this)), m_eepromNote(new QLabel(this)), m_pendingLabel(new QLabel(this)),
      m_status(new QLabel(this)), m_load(new QPushButton(tr("Lo&ad backup..."), this)),
      m_discard(new QPushButton(tr("Dis&card changes"), this)), m_write(new QPushButton(this)),
      m_stop(new QPushButton(tr("S&top after this write"), this))
{
    setObjectName(QStringLiteral("parameterEditor"));
    m_tree->setObjectName(QStringLiteral("parameterTree"));
    m_search->setObjectName(QStringLiteral("parameterSearch"));
    m_noMatch->setObjectName(QStringLiteral("noMatch"));
    m_eepromNote->setObjectName(QStringLiteral("eepromNote"));
    m_pendingLabel->setObjectName(QStringLiteral("pendingChanges"));
    m_status->setObjectName(QStringLiteral("editorStatus"));
    m_load->setObjectName(QStringLiteral("loadBackup"));
    m_discard->setObjectName(QStringLiteral("discardChanges"));
    m_write->setObjectName(QStringLiteral("writeChanges"));
    m_stop->setObjectName(QStringLiteral("stopWriting"));

    // EEPROM wear said once for the page, not on every row.
    const int listed = int(m_model->entryIds().size());
    const int eeprom = m_model->eepromCount();
    if (eeprom > 0 && eeprom == listed)
        m_eepromNote->setText(tr("All %n parameter(s) listed here are stored in EEPROM: every write wears it (about 10,000 "
                                 "write cycles). Write only what needs changing.",
                                 nullptr, listed));
    else if (eeprom > 0)
        m_eepromNote->setText(tr("%1 of the %n parameter(s) listed here are stored in EEPROM: every write wears it (about "
                                 "10,000 write cycles). Write only what needs changing.",
                                 nullptr, listed)
                                      .arg(eeprom));
    else if (listed > 0)
        m_eepromNote->setText(tr("The parameters listed here are kept in RAM: the device loses them when it is switched off."));
    else
        m_eepromNote->setText(tr("This device has no parameters to edit."));
    m_eepromNote->setWordWrap(true);
    Theme::colourText(m_eepromNote, Theme::Role::Hint);

    auto *searchLabel = new QLabel(tr("&Search:"), this);
    searchLabel->setBuddy(m_search);
    m_search->setPlaceholderText(tr("Name, id or address"));
    m_search->setClearButtonEnabled(true);
    m_search->setToolTip(tr("Shows the parameters whose name, id or register address contains this text (Ctrl+F)."));
    m_search->installEventFilter(new SearchKeys(m_search, m_tree));
    m_search->setMaximumWidth(fontMetrics().horizontalAdvance(QLatin1Char('x')) * 40);
    connect(m_search, &QLineEdit::textChanged, this, &ParameterEditor::applyFilter);
    m_noMatch->setWordWrap(true);
    m_noMatch->hide();

    m_filter->setSourceModel(m_model);
    m_filter->setFilterRole(ParameterEditModel::SearchTextRole);
    m_filter->setFilterCaseSensitivity(Qt::CaseInsensitive);
    // A group stays while one of its parameters matches, and goes when none does.
    m_filter->setRecursiveFilteringEnabled(true);
    m_tree->setModel(m_filter);
    m_tree->setItemDelegate(m_delegate);
    m_tree->setAlternatingRowColors(true);
    m_tree->setUniformRowHeights(true);
    m_tree->setAllColumnsShowFocus(true);
    m_tree->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tree->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                            | QAbstractItemView::AnyKeyPressed | QAbstractItemView::SelectedClicked);
    m_tree->setTextElideMode(Qt::ElideRight);
    // As wide as the page, never wider: long names end in "…" and are whole in the tooltip.
    m_tree->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_tree->expandAll();

    QHeaderView *header = m_tree->header();
    header->setStretchLastSection(false);
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setSectionResizeMode(ParameterEditModel::NameColumn, QHeaderView::Stretch);
    const QFontMetrics fm = fontMetrics();
    QFont bold = font();
    bold.setBold(true);
    const QFontMetrics boldMetrics(bold);
    const int pad = 2 * (style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, this) + 1) + 12;
    auto fit = [&](int column, const QStringList &samples, const QFontMetrics &metrics) {
        const int headerMargin = style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
        int width = header->fontMetrics().horizontalAdvance(m_model->headerData(column, Qt::Horizontal).toString())
                + 2 * headerMargin + 8;
        for (const QString &sample : samples)
            width = std::max(width, metrics.horizontalAdvance(sample) + pad);
        m_tree->setColumnWidth(column, width);
    };
    QStringList units;
    for (const QString &id : m_model->entryIds())
        units << m_model->indexOf(id, ParameterEditModel::UnitColumn).data().toString();
    fit(ParameterEditModel::DeviceColumn, {tr("%1 (stale)").arg(QStringLiteral("-8888.88")), QStringLiteral("Overrange")}, fm);
    fit(ParameterEditModel::NewValueColumn, {QStringLiteral("-88888.888")}, boldMetrics);
    fit(ParameterEditModel::UnitColumn, units, fm);
    fit(ParameterEditModel::StorageColumn, {tr("EEPROM"), tr("RAM")}, fm);
    // Outcomes are long; the column shows their start and the tooltip the whole.
    fit(ParameterEditModel::ResultColumn, {ParameterEditModel::tr("Confirmed by read-back: %1").arg(QStringLiteral("8888.8 s"))}, fm);

    auto *revert = new QAction(tr("Take back this change"), m_tree);
    revert->setObjectName(QStringLiteral("revertChange"));
    revert->setShortcut(QKeySequence::Delete);
    revert->setShortcutContext(Qt::WidgetShortcut);
    connect(revert, &QAction::triggered, this, [this] {
        const QString id = m_tree->currentIndex().data(ParameterEditModel::EntryIdRole).toString();
        if (!id.isEmpty() && !m_model->isLocked() && !m_readOnly)
            m_model->revert(id);
    });
    m_tree->addAction(revert);
    m_tree->setContextMenuPolicy(Qt::ActionsContextMenu);
    // Keyboard users land on the new value, the one cell there is to edit.
    connect(m_tree->selectionModel(), &QItemSelectionModel::currentChanged, this, [this](const QModelIndex &current) {
        if (current.isValid() && current.parent().isValid() && current.column() != ParameterEditModel::NewValueColumn)
            m_tree->selectionModel()->setCurrentIndex(current.siblingAtColumn(ParameterEditModel::NewValueColumn),
                                                      QItemSelectionModel::NoUpdate);
    });
    connect(m_tree, &QTreeView::activated, this, [this](const QModelIndex &index) {
        if (index.parent().isValid())
            m_tree->edit(index.siblingAtColumn(ParameterEditModel::NewValueColumn));
    });

    connect(m_delegate, &ParameterValueDelegate::inputRefused, this, [this](const QString &id, const QString &reason) {
        const RegisterEntry *e = m_model->entry(id);
        showStatus(tr("Not taken for %1: %2").arg(e ? translatedLabel(e->label) : id, reason), Theme::Role::Refused);
    });
    connect(m_delegate, &ParameterValueDelegate::inputNote, this,
            [this](const QString &, const QString &note) { showStatus(note); });
    connect(m_delegate, &ParameterValueDelegate::inputTaken, this, [this] { showStatus(QString()); });

    m_write->setDefault(false);
    m_write->setToolTip(tr("Shows the changes with the device's values first; nothing is written before you confirm."));
    m_load->setToolTip(tr("Fills in the values of a parameter backup file that differ from the device, to check "
                          "before writing them."));
    m_discard->setToolTip(tr("Drops every change that has not been written."));
    m_stop->setToolTip(tr("The write under way ends as usual; the changes after it are not written and stay."));
    m_stop->hide();
    connect(m_write, &QPushButton::clicked, this, &ParameterEditor::requestWrite);
    connect(m_discard, &QPushButton::clicked, this, &ParameterEditor::discardChanges);
    connect(m_stop, &QPushButton::clicked, this, [this] {
        m_stopReason = tr("stopped before its turn");
        m_transfer->cancel();
        updateActions();
    });
    connect(m_load, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load parameter backup"), QString(),
                                                          tr("Parameter files (*.json)"));
        if (!path.isEmpty())
            loadBackup(path);
    });

    connect(m_model, &ParameterEditModel::changeCountChanged, this, &ParameterEditor::updateActions);
    connect(m_transfer, &ParameterTransfer::entryWritten, this, &ParameterEditor::onEntryWritten);
    connect(m_transfer, &ParameterTransfer::writeFinished, this, &ParameterEditor::onWriteFinished);
    connect(m_transfer, &ParameterTransfer::progress, this, [this](int done, int total) {
        if (!m_written.isEmpty() && done < total)
            m_pendingLabel->setText(tr("Writing %1 of %2...").arg(std::min(done + 1, total)).arg(total));
    });
    connect(m_bus, &Bus::conditionChanged, this, &ParameterEditor::onConditionChanged);
    connect(m_bus, &Bus::stateChanged, this, &ParameterEditor::updateActions);

    m_status->setWordWrap(true);
    m_status->hide();
    m_pendingLabel->setAlignment(Qt::AlignRight | Qt::AlignVCenter);

    auto *tools = new QHBoxLayout;
    tools->addWidget(searchLabel);
    tools->addWidget(m_search, 1);
    tools->addWidget(m_load);
    tools->addStretch();
    tools->addWidget(m_pendingLabel);
    tools->addWidget(m_discard);
    tools->addWidget(m_stop);
    tools->addWidget(m_write);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_eepromNote);
    layout->addLayout(tools);
    layout->addWidget(m_noMatch);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_status);
    setTabOrder(m_search, m_tree);
    setTabOrder(m_tree, m_write);
    setTabOrder(m_write, m_stop);
    setTabOrder(m_stop, m_discard);
    setTabOrder(m_discard, m_load);
    updateActions();
}

ParameterEditor::~ParameterEditor()
{
    // Closed mid-write: the write under way ends on the bus (and in the audit log), no
    // further one is sent.
    m_transfer->cancel();
}

bool ParameterEditor::isEmpty() const
{
    return m_model->entryIds().isEmpty();
}

bool ParameterEditor::isBusy() const
{
    return m_transfer->isBusy();
}

QString ParameterEditor::status() const
{
    return m_status->text();
}

void ParameterEditor::focusSearch()
{
    m_search->setFocus(Qt::ShortcutFocusReason);
    m_search->selectAll();
}

void ParameterEditor::setReadOnly(bool readOnly)
{
    m_readOnly = readOnly;
    m_model->setReadOnly(readOnly);
    m_tree->setEditTriggers(readOnly ? QAbstractItemView::NoEditTriggers
                                     : QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                                               | QAbstractItemView::AnyKeyPressed | QAbstractItemView::SelectedClicked);
    updateActions();
}

void ParameterEditor::showStatus(const QString &text, Theme::Role role)
{
    m_status->setText(text);
    m_status->setVisible(!text.isEmpty());
    if (role == Theme::Role::Hint)
        Theme::plain(m_status);
    else
        Theme::colourText(m_status, role);
}

void ParameterEditor::applyFilter(const QString &text)
{
    m_filter->setFilterFixedString(text.trimmed());
    m_tree->expandAll();
    const bool none = m_filter->rowCount() == 0 && !text.trimmed().isEmpty();
    m_noMatch->setText(none ? tr("No parameter matches \"%1\".").arg(text.trimmed()) : QString());
    m_noMatch->setVisible(none);
}

bool ParameterEditor::deviceAnswers() const
{
    return m_bus->state() == LineState::Connected && m_bus->condition(m_device).isOnline();
}

QString ParameterEditor::notAnsweringText() const
{
    return DeviceTile::conditionText(m_bus->condition(m_device));
}

void ParameterEditor::updateActions()
{
    const int count = m_model->changeCount();
    const bool busy = m_transfer->isBusy();
    const bool writing = busy && !m_written.isEmpty();
    m_write->setText(count ? tr("&Write %n change(s)", nullptr, count) : tr("&Write changes"));
    m_write->setEnabled(!m_readOnly && !busy && count > 0 && deviceAnswers());
    if (m_readOnly)
        m_write->setToolTip(tr("Read-only mode: nothing is written to the devices."));
    else if (count > 0 && !deviceAnswers())
        m_write->setToolTip(tr("Not now: %1. The changes can be written once the device answers.").arg(notAnsweringText()));
    else
        m_write->setToolTip(tr("Shows the changes with the device's values first; nothing is written before you confirm."));
    m_discard->setEnabled(!m_readOnly && !busy && count > 0);
    m_load->setEnabled(!m_readOnly && !busy);
    m_stop->setVisible(writing);
    m_stop->setEnabled(writing && m_stopReason.isEmpty());
    if (!writing)
        m_pendingLabel->setText(count ? tr("%n change(s) not written yet", nullptr, count) : tr("No changes"));
    m_load->setToolTip(m_readOnly ? tr("Read-only mode: nothing is changed or written.")
                                  : tr("Fills in the values of a parameter backup file that differ from the device, to "
                                       "check before writing them."));
}

void ParameterEditor::onConditionChanged(DeviceId device)
{
    if (device != m_device)
        return;
    // A device that stops answering mid-write is not sent the rest: each would only end
    // unknown after its timeouts. They stay, to be written when it answers again.
    if (!m_written.isEmpty() && m_transfer->isBusy() && !deviceAnswers() && m_stopReason.isEmpty()) {
        m_stopReason = tr("the device stopped answering (%1)").arg(notAnsweringText());
        m_transfer->cancel();
    }
    updateActions();
}

void ParameterEditor::discardChanges()
{
    if (m_readOnly || m_transfer->isBusy())
        return;
    const int count = m_model->changeCount();
    m_model->discardAll();
    if (count)
        showStatus(tr("%n change(s) discarded.", nullptr, count));
}

void ParameterEditor::loadBackup(const QString &path)
{
    if (m_readOnly) {
        showStatus(tr("Read-only mode: nothing is changed or written."), Theme::Role::Refused);
        return;
    }
    if (m_transfer->isBusy()) {
        showStatus(tr("Wait until the read or write under way has ended."), Theme::Role::Refused);
        return;
    }
    const QString name = QFileInfo(path).fileName();
    QString error;
    const std::optional<QByteArray> json = RegularFile::read(path, RegularFile::defaultLimit, &error);
    if (!json) {
        showStatus(tr("Not loaded: %1").arg(error), Theme::Role::Refused);
        emit backupLoaded();
        return;
    }
    const std::optional<ParameterSet> file = ParameterSet::fromJson(*json, &error);
    if (!file) {
        showStatus(tr("Not loaded: %1: %2").arg(name, error), Theme::Role::Refused);
        emit backupLoaded();
        return;
    }
    const RegisterMap &map = m_model->map();
    if (file->family != map.family) {
        showStatus(tr("Not loaded: %1").arg(file->incompatibility(map, QString())), Theme::Role::Refused);
        emit backupLoaded();
        return;
    }
    // Compared with the device as it is now, not with values that may be old.
    if (!deviceAnswers()) {
        showStatus(tr("Not loaded: %1. A backup is compared with the device, which must answer.").arg(notAnsweringText()),
                   Theme::Role::Refused);
        emit backupLoaded();
        return;
    }
    showStatus(tr("Reading the device's parameters to compare with %1...").arg(name));
    connect(m_transfer, &ParameterTransfer::readFinished, this,
            [this, file = *file, name](const ParameterSet &device, const QStringList &failed) {
                updateActions();
                const RegisterMap &map = m_model->map();
                if (!failed.isEmpty()) {
                    QStringList named = failed.mid(0, 5);
                    if (failed.size() > named.size())
                        named << tr("and %n more", nullptr, int(failed.size() - named.size()));
                    showStatus(tr("Not loaded: these could not be read from the device to compare: %1")
                                       .arg(named.join(QStringLiteral(", "))),
                               Theme::Role::Refused);
                } else if (const QString refused = file.incompatibility(map, device.softwareVersion); !refused.isEmpty()) {
                    showStatus(tr("Not loaded: %1").arg(refused), Theme::Role::Refused);
                } else if (m_readOnly || m_model->isLocked()) {
                    showStatus(tr("Not loaded: a write started meanwhile."), Theme::Role::Refused);
                } else {
                    int filled = 0;
                    int elsewhere = 0;
                    QStringList refusedValues;
                    for (const ParameterDifference &d : ParameterSet::toRestore(device.differences(file, map))) {
                        if (!m_model->entry(d.id)) {
                            ++elsewhere;
                            continue;
                        }
                        QString message;
                        if (m_model->setExactValue(d.id, d.newValue, &message) && m_model->isChanged(d.id))
                            ++filled;
                        else if (!message.isEmpty())
                            refusedValues << message;
                    }
                    int missing = 0;
                    for (const QString &id : m_model->entryIds()) {
                        if (m_model->entry(id)->isReadable() && !file.values.contains(id))
                            ++missing;
                    }
                    QStringList parts;
                    parts << (filled ? tr("%1: %n value(s) that differ from the device filled in as changes; check them "
                                          "and write them.",
                                          nullptr, filled)
                                               .arg(name)
                                     : tr("%1: every parameter listed here matches the device, nothing to fill in.").arg(name));
                    if (missing)
                        parts << tr("%n parameter(s) the file does not hold are left as they are.", nullptr, missing);
                    if (elsewhere)
                        parts << tr("%n differing value(s) of the file are not on this page (setpoints and the like); "
                                    "the Parameters dialog restores them.",
                                    nullptr, elsewhere);
                    if (!refusedValues.isEmpty())
                        parts << tr("Not taken: %1").arg(refusedValues.join(QStringLiteral("; ")));
                    showStatus(parts.join(QLatin1Char(' ')),
                               refusedValues.isEmpty() ? Theme::Role::Hint : Theme::Role::Refused);
                    if (filled && !m_search->text().isEmpty())
                        m_search->clear();   // every filled-in change in sight
                }
                emit backupLoaded();
            },
            Qt::SingleShotConnection);
    m_transfer->read();
    updateActions();
}

void ParameterEditor::requestWrite()
{
    if (m_readOnly) {
        showStatus(tr("Read-only mode: nothing is written to the devices."), Theme::Role::Refused);
        return;
    }
    if (m_transfer->isBusy() || m_preview) {
        showStatus(tr("Wait until the read or write under way has ended."), Theme::Role::Refused);
        return;
    }
    // A value still being typed is part of what the person asks to write.
    if (QWidget *field = m_tree->indexWidget(m_tree->currentIndex())) {
        emit m_delegate->commitData(field);
        emit m_delegate->closeEditor(field, QAbstractItemDelegate::NoHint);
    }
    const QStringList ids = m_model->changedIds();
    if (ids.isEmpty()) {
        showStatus(tr("Nothing to write: no parameter is changed."));
        return;
    }
    if (!deviceAnswers()) {
        showStatus(tr("Not written: %1. The changes stay and can be written once the device answers.").arg(notAnsweringText()),
                   Theme::Role::Refused);
        return;
    }
    QList<ParameterWritePreview::Change> changes;
    for (const QString &id : ids) {
        const RegisterEntry &e = *m_model->entry(id);
        ParameterWritePreview::Change c;
        c.id = id;
        c.label = translatedLabel(e.label);
        c.deviceValue = m_model->deviceValueText(id);
        c.newValue = m_model->newValueText(id);
        c.unit = m_model->indexOf(id, ParameterEditModel::UnitColumn).data().toString();
        c.eeprom = e.storage == Storage::Eeprom;
        if (m_model->writeState(id) == WriteCommand::State::Unknown)
            c.lastWrite = m_model->resultText(id);
        changes << c;
    }
    const QString device = m_deviceTitle.isEmpty()
            ? DeviceTitle::full(m_model->map(), m_bus->deviceAddress(m_device), QString())
            : m_deviceTitle;
    m_preview = new ParameterWritePreview(device, changes, this);
    m_preview->setAttribute(Qt::WA_DeleteOnClose);
    m_preview->setWindowModality(Qt::WindowModal);
    connect(m_preview, &QDialog::accepted, this, [this, preview = m_preview.data()] { writeChanges(preview); });
    // Closed is gone, whenever Qt deletes it.
    connect(m_preview, &QDialog::finished, this, [this] { m_preview.clear(); });
    m_preview->open();
}

void ParameterEditor::writeChanges(ParameterWritePreview *preview)
{
    // Checked again: the line or the device may have gone while the preview was open.
    if (m_readOnly || m_transfer->isBusy())
        return;
    if (!deviceAnswers()) {
        showStatus(tr("Not written: %1. The changes stay and can be written once the device answers.").arg(notAnsweringText()),
                   Theme::Role::Refused);
        return;
    }
    QList<ParameterDifference> differences;
    QStringList ids;
    for (const ParameterWritePreview::Change &c : preview->changes()) {
        const RegisterEntry *e = m_model->entry(c.id);
        // Exactly the value previewed: the editor is locked while the preview is open.
        if (!e || !m_model->isChanged(c.id))
            continue;
        ParameterDifference d;
        d.id = c.id;
        d.label = e->label;
        d.unit = e->unit;
        d.newValue = m_model->newValue(c.id);
        d.newDisplay = c.newValue;
        d.oldDisplay = c.deviceValue;
        differences << d;
        ids << c.id;
    }
    if (differences.isEmpty())
        return;
    m_writing = ids;
    m_written = ids;
    m_stopReason.clear();
    m_model->setLocked(true);
    m_model->setWriting(ids);
    showStatus(tr("Writing %n change(s), each verified by reading it back...", nullptr, int(ids.size())),
               Theme::Role::Pending);
    m_transfer->write(differences);
    updateActions();
}

void ParameterEditor::onEntryWritten(const QString &id, const WriteOutcome &outcome)
{
    m_writing.removeOne(id);
    m_model->setOutcome(id, outcome);
    // After a write whose outcome is unknown the device's state is too: the rest wait
    // until someone has looked, rather than going after it into the same silence.
    if (m_model->writeState(id) == WriteCommand::State::Unknown && !m_writing.isEmpty() && m_stopReason.isEmpty()) {
        const RegisterEntry *e = m_model->entry(id);
        m_stopReason = tr("the write of %1 ended unknown; check the device first").arg(translatedLabel(e->label));
        m_transfer->cancel();
        updateActions();
    }
}

void ParameterEditor::onWriteFinished(int, int, bool)
{
    for (const QString &id : std::as_const(m_writing))
        m_model->setNotWritten(id, m_stopReason.isEmpty() ? tr("stopped before its turn") : m_stopReason);
    m_writing.clear();
    m_model->setLocked(false);
    int confirmed = 0;
    int refused = 0;
    int unknown = 0;
    int notWritten = 0;
    for (const QString &id : std::as_const(m_written)) {
        switch (m_model->writeState(id)) {
        case WriteCommand::State::Confirmed:
            ++confirmed;
            break;
        case WriteCommand::State::Refused:
            ++refused;
            break;
        case WriteCommand::State::Unknown:
            ++unknown;
            break;
        case WriteCommand::State::Idle:
        case WriteCommand::State::Pending:
            ++notWritten;
            break;
        }
    }
    const int total = int(m_written.size());
    QStringList parts;
    parts << tr("%1 of %n change(s) written and confirmed by read-back.", nullptr, total).arg(confirmed);
    if (refused)
        parts << tr("%n refused.", nullptr, refused);
    if (unknown)
        parts << tr("%n with an unknown outcome: check the device.", nullptr, unknown);
    if (notWritten)
        parts << tr("%n not written (%1).", nullptr, notWritten).arg(m_stopReason.isEmpty() ? tr("stopped") : m_stopReason);
    if (confirmed < total)
        parts << tr("What was not confirmed stays as a change; see \"Last write\".");
    showStatus(parts.join(QLatin1Char(' ')), confirmed == total ? Theme::Role::Confirmed
                                             : unknown          ? Theme::Role::Unknown
                                                                : Theme::Role::Refused);
    m_written.clear();
    m_stopReason.clear();
    updateActions();
    emit writeEnded();
}

void ParameterEditor::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    m_interest->setShown(this, true, m_model->entryIds());
}

void ParameterEditor::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_interest->setShown(this, false, {});
}

} // namespace jumo
