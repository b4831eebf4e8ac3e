#include "finddialog.h"

#include "bus/bus.h"
#include "protocol/familyregistry.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace jumo {

namespace {

enum Column { SettingColumn, AddressColumn, DeviceColumn };
constexpr int findingRole = Qt::UserRole;        // index into the finder's findings, for devices
constexpr int formatRole = Qt::UserRole + 1;     // "19200 8E1"

} // namespace

FindDialog::FindDialog(const BusSettings &line, const FamilyRegistry &registry, QWidget *parent)
    : QDialog(parent), m_bus(std::make_unique<Bus>()), m_from(new QSpinBox(this)), m_to(new QSpinBox(this)),
      m_plan(new QLabel(this)), m_progress(new QProgressBar(this)), m_found(new QTreeWidget(this)),
      m_setting(new QComboBox(this)), m_note(new QLabel(this)), m_startButton(new QPushButton(tr("&Search"), this)),
      m_cancelButton(new QPushButton(tr("Cancel search"), this)), m_useButton(nullptr)
{
    setWindowTitle(tr("Find devices on an unknown line"));
    BusSettings settings = line;
    settings.readOnly = true;   // probes are reads; nothing else goes out
    settings.retries = 0;
    m_bus->setSettings(settings);
    m_finder = std::make_unique<LineFinder>(*m_bus, registry.families());

    m_from->setObjectName(QStringLiteral("findFrom"));
    m_to->setObjectName(QStringLiteral("findTo"));
    m_plan->setObjectName(QStringLiteral("findPlan"));
    m_progress->setObjectName(QStringLiteral("findProgress"));
    m_found->setObjectName(QStringLiteral("findResults"));
    m_setting->setObjectName(QStringLiteral("findSetting"));
    m_note->setObjectName(QStringLiteral("findNote"));
    m_note->setWordWrap(true);
    m_note->hide();
    m_startButton->setObjectName(QStringLiteral("startFind"));
    m_cancelButton->setObjectName(QStringLiteral("cancelFind"));
    m_plan->setWordWrap(true);
    m_from->setRange(1, 255);
    m_to->setRange(1, 255);
    m_from->setValue(1);
    m_to->setValue(31);
    m_to->setToolTip(tr("An RS-485 line carries at most 31 devices; they are most often given the first addresses."));
    m_cancelButton->setEnabled(false);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setFormat(tr("not started"));
    m_found->setColumnCount(3);
    m_found->setHeaderLabels({tr("Answers at"), tr("Address"), tr("Device")});
    m_found->setRootIsDecorated(false);
    m_found->header()->setSectionResizeMode(DeviceColumn, QHeaderView::Stretch);
    m_setting->setEnabled(false);
    m_setting->setPlaceholderText(tr("(nothing answered yet)"));

    auto *range = new QHBoxLayout;
    range->addWidget(new QLabel(tr("Addresses"), this));
    range->addWidget(m_from);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_to);
    range->addStretch();
    range->addWidget(m_startButton);
    range->addWidget(m_cancelButton);
    auto *port = new QLabel(tr("Port: %1. Every baud rate and data format the device families support is tried, "
                               "address 255 first (every IPC 300 and TYA 200 answers there), then a quick scan of "
                               "the addresses.")
                                    .arg(line.portName.toHtmlEscaped()),
                            this);
    port->setWordWrap(true);
    auto *use = new QFormLayout;
    use->addRow(tr("Line settings to use:"), m_setting);
    auto *buttons = new QDialogButtonBox(this);
    m_useButton = buttons->addButton(tr("&Use these settings and add the checked devices"), QDialogButtonBox::AcceptRole);
    m_useButton->setObjectName(QStringLiteral("useFound"));
    m_useButton->setEnabled(false);
    buttons->addButton(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, [this] {
        m_finder->cancel();
        reject();
    });

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(port);
    layout->addLayout(range);
    layout->addWidget(m_plan);
    layout->addWidget(m_progress);
    layout->addWidget(m_found);
    layout->addWidget(m_note);
    layout->addLayout(use);
    layout->addWidget(buttons);
    resize(640, 440);

    connect(m_startButton, &QPushButton::clicked, this, &FindDialog::start);
    connect(m_cancelButton, &QPushButton::clicked, m_finder.get(), &LineFinder::cancel);
    connect(m_from, &QSpinBox::valueChanged, this, &FindDialog::updatePlan);
    connect(m_to, &QSpinBox::valueChanged, this, &FindDialog::updatePlan);
    connect(m_setting, &QComboBox::currentIndexChanged, this, &FindDialog::showChosenSetting);
    connect(m_finder.get(), &LineFinder::trying, this, [this](const LineFormat &format, int step, int count, bool hint) {
        // The hint pass is short (one probe per setting): the bar's first tenth.
        m_trying = hint ? tr("address 255 at %1").arg(settingName(format)) : settingName(format);
        m_progress->setRange(0, 1000);
        m_progress->setValue(hint ? 100 * step / std::max(1, count) : 100 + 900 * step / std::max(1, count));
    });
    connect(m_finder.get(), &LineFinder::probing, this, [this](int address, int, int) {
        const int left = int((m_finder->remainingMs() + 999) / 1000);
        m_progress->setFormat(tr("%1, address %2: about %n s left", nullptr, left).arg(m_trying).arg(address));
    });
    connect(m_finder.get(), &LineFinder::found, this, &FindDialog::onFound);
    connect(m_finder.get(), &Job::finished, this, &FindDialog::onFinished);
    updatePlan();
}

FindDialog::~FindDialog()
{
    // The finder's bus goes with the dialog: its port is closed before the line takes it back.
    m_finder->cancel();
}

QString FindDialog::settingName(const LineFormat &format) const
{
    return tr("%1 baud %2").arg(format.baudRate).arg(format.formatName());
}

void FindDialog::updatePlan()
{
    if (m_finder->isRunning())
        return;
    const int from = m_from->value();
    const int to = std::max(from, m_to->value());
    const int seconds = int((m_finder->plannedMs(from, to) + 999) / 1000);
    m_plan->setText(tr("%n setting(s) to try: about %1 s where nothing answers late.", nullptr,
                       int(m_finder->settings().size()))
                            .arg(seconds));
}

void FindDialog::start()
{
    if (m_finder->isRunning())
        return;
    m_found->clear();
    m_note->hide();
    m_setting->clear();
    m_answered.clear();
    m_setting->setEnabled(false);
    m_useButton->setEnabled(false);
    updatePlan();
    for (QWidget *w : std::initializer_list<QWidget *>{m_from, m_to, m_startButton})
        w->setEnabled(false);
    m_cancelButton->setEnabled(true);
    m_finder->start(m_from->value(), std::max(m_from->value(), m_to->value()));
}

bool FindDialog::isSearching() const
{
    return m_finder->isRunning();
}

void FindDialog::onFound(const LineFinder::Finding &finding)
{
    if (!std::any_of(m_answered.cbegin(), m_answered.cend(), [&](const LineFormat &f) { return f == finding.format; })) {
        // A setting where only address 255 answered is one to offer all the same: a
        // device is on the line at it.
        m_answered << finding.format;
        m_setting->addItem(settingName(finding.format));
    }
    if (finding.alwaysAnswered)
        return;   // shown at the end where its own address was not found
    auto *item = new QTreeWidgetItem(m_found);
    item->setText(SettingColumn, settingName(finding.format));
    item->setText(AddressColumn, QString::number(finding.address));
    item->setData(SettingColumn, formatRole, settingName(finding.format));
    if (finding.family) {
        item->setText(DeviceColumn, finding.family->displayName());
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(SettingColumn, Qt::Checked);
        item->setData(SettingColumn, findingRole, int(m_finder->findings().size() - 1));
    } else {
        item->setText(DeviceColumn, tr("answers, but matches no known family"));
        item->setFlags(Qt::ItemIsEnabled);
    }
    for (int c = 0; c < m_found->columnCount() - 1; ++c)
        m_found->resizeColumnToContents(c);
}

void FindDialog::onFinished()
{
    for (QWidget *w : std::initializer_list<QWidget *>{m_from, m_to, m_startButton})
        w->setEnabled(true);
    m_cancelButton->setEnabled(false);
    const bool complete = m_finder->result() == Job::Result::Succeeded;
    for (const LineFinder::Finding &f : complete ? m_finder->ownAddressNotFound() : QList<LineFinder::Finding>()) {
        auto *item = new QTreeWidgetItem(m_found);
        item->setText(SettingColumn, settingName(f.format));
        item->setText(AddressColumn, QString::number(f.address));
        item->setText(DeviceColumn, m_finder->scannedEveryAddressOf(*f.family)
                                            ? tr("%1 answers here and at no other address: its own address is %2, "
                                                 "or its answer there was lost (search again)")
                                                      .arg(f.family->displayName())
                                                      .arg(f.address)
                                            : tr("%1 answers here, as every one does; its own address is outside %2..%3")
                                                      .arg(f.family->displayName())
                                                      .arg(m_from->value())
                                                      .arg(m_to->value()));
        item->setFlags(Qt::ItemIsEnabled);
    }
    const double seconds = double(m_finder->elapsedMs()) / 1000.0;
    m_progress->setValue(m_progress->maximum());
    switch (m_finder->result()) {
    case Job::Result::Cancelled:
        m_progress->setFormat(tr("cancelled after %1 s").arg(seconds, 0, 'f', 1));
        break;
    case Job::Result::Failed:
        m_progress->setFormat(tr("stopped: %1").arg(m_finder->errorText()));
        break;
    default:
        m_progress->setFormat(m_found->topLevelItemCount() == 0
                                      ? tr("nothing answered (in %1 s): check the wiring, the termination and the adapter")
                                                .arg(seconds, 0, 'f', 1)
                                      : tr("done in %1 s").arg(seconds, 0, 'f', 1));
        break;
    }
    if (const std::optional<LineFormat> best = m_finder->bestSetting()) {
        for (int i = 0; i < m_answered.size(); ++i) {
            if (m_answered.at(i) == *best)
                m_setting->setCurrentIndex(i);
        }
    }
    m_setting->setEnabled(!m_answered.isEmpty());
    m_useButton->setEnabled(!m_answered.isEmpty());
    // A device found at two formats of one baud rate: the device or the adapter takes one
    // for the other.
    QStringList twice;
    for (const LineFinder::SeveralFormats &several : m_finder->answeredAtSeveralFormats())
        twice << tr("%1 at address %2").arg(several.family->displayName()).arg(several.address);
    m_note->setText(tr("%1 answered at more than one data format of a baud rate: the device or the adapter takes one "
                       "for the other (a pseudo-terminal does not carry even parity; many UARTs take 8N2 for 8N1). "
                       "The device's own setting is in its interface menu.")
                            .arg(twice.join(QStringLiteral(", "))));
    m_note->setVisible(!twice.isEmpty());
    showChosenSetting();
}

void FindDialog::showChosenSetting()
{
    // Devices found at another setting cannot be added with this one: shown, not offered.
    const QString chosen = m_setting->currentText();
    for (int i = 0; i < m_found->topLevelItemCount(); ++i) {
        QTreeWidgetItem *item = m_found->topLevelItem(i);
        if (!item->data(SettingColumn, findingRole).isValid())
            continue;
        const bool here = item->data(SettingColumn, formatRole).toString() == chosen;
        item->setDisabled(!here && !m_finder->isRunning());
    }
}

std::optional<LineFormat> FindDialog::chosenFormat() const
{
    const int index = m_setting->currentIndex();
    if (index < 0 || index >= m_answered.size())
        return std::nullopt;
    return m_answered.at(index);
}

QList<QPair<std::shared_ptr<const RegisterMap>, quint8>> FindDialog::chosen() const
{
    QList<QPair<std::shared_ptr<const RegisterMap>, quint8>> out;
    const std::optional<LineFormat> format = chosenFormat();
    if (!format)
        return out;
    const QList<LineFinder::Finding> findings = m_finder->findings();
    for (int i = 0; i < m_found->topLevelItemCount(); ++i) {
        const QTreeWidgetItem *item = m_found->topLevelItem(i);
        const QVariant index = item->data(SettingColumn, findingRole);
        if (!index.isValid() || item->checkState(SettingColumn) != Qt::Checked)
            continue;
        const LineFinder::Finding &f = findings.at(index.toInt());
        if (f.format == *format)
            out << qMakePair(f.family, quint8(f.address));
    }
    return out;
}

} // namespace jumo
