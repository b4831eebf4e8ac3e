#include "scandialog.h"

#include "bus/bus.h"
#include "bus/devicescanner.h"
#include "protocol/familyregistry.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace jumo {

ScanDialog::ScanDialog(Bus *bus, const FamilyRegistry &registry, QWidget *parent)
    : QDialog(parent), m_bus(bus), m_scanner(new DeviceScanner(*bus, registry.families(), this)), m_from(new QSpinBox(this)),
      m_to(new QSpinBox(this)), m_progress(new QProgressBar(this)), m_found(new QListWidget(this)),
      m_startButton(new QPushButton(tr("Scan"), this)), m_cancelButton(new QPushButton(tr("Cancel scan"), this)),
      m_thorough(new QCheckBox(tr("&Thorough: every address at the full timeout (slow)"), this)),
      m_plan(new QLabel(this))
{
    setWindowTitle(tr("Scan the line"));
    m_from->setObjectName(QStringLiteral("fromBox"));
    m_to->setObjectName(QStringLiteral("toBox"));
    m_found->setObjectName(QStringLiteral("foundList"));
    m_startButton->setObjectName(QStringLiteral("startScan"));
    m_progress->setObjectName(QStringLiteral("scanProgress"));
    m_thorough->setObjectName(QStringLiteral("thoroughScan"));
    m_thorough->setToolTip(tr("A quick scan gives each address a short timeout and probes again at the full timeout "
                              "wherever it heard anything, which finds devices that answer late too. A thorough scan "
                              "probes every address twice at the full timeout: minutes for the whole range."));
    m_plan->setObjectName(QStringLiteral("scanPlan"));
    m_plan->setWordWrap(true);
    m_from->setRange(1, 255);
    m_to->setRange(1, 255);
    m_from->setValue(1);
    m_to->setValue(247);
    m_cancelButton->setEnabled(false);
    connect(m_startButton, &QPushButton::clicked, this, &ScanDialog::start);
    connect(m_cancelButton, &QPushButton::clicked, m_scanner, &DeviceScanner::cancel);
    connect(m_scanner, &DeviceScanner::progress, this, [this](int address, int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
        const int left = int((m_scanner->remainingMs() + 999) / 1000);
        m_progress->setFormat(tr("address %1, about %n s left", nullptr, left).arg(address));
    });
    connect(m_from, &QSpinBox::valueChanged, this, &ScanDialog::updatePlan);
    connect(m_to, &QSpinBox::valueChanged, this, &ScanDialog::updatePlan);
    connect(m_thorough, &QCheckBox::toggled, this, &ScanDialog::updatePlan);
    connect(m_scanner, &DeviceScanner::found, this, [this](int address, std::shared_ptr<const RegisterMap> map) {
        if (address == map->protocol.alwaysAnswersAddress) {
            // Every device of the family answers there, whatever its own address: not a device.
            auto *item = new QListWidgetItem(tr("Address %1 answers as %2, as every %2 does whatever its own address: "
                                                "not a device of its own")
                                                     .arg(address)
                                                     .arg(map->displayName()),
                                             m_found);
            item->setFlags(Qt::ItemIsEnabled);
            return;
        }
        auto *item = new QListWidgetItem(tr("%1 at address %2").arg(map->displayName()).arg(address), m_found);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(Qt::Checked);
        item->setData(Qt::UserRole, int(m_results.size()));
        m_results << qMakePair(map, quint8(address));
    });
    connect(m_scanner, &DeviceScanner::unknownDevice, this, [this](int address) {
        auto *item = new QListWidgetItem(tr("Unknown device at address %1").arg(address), m_found);
        item->setFlags(Qt::ItemIsEnabled);
    });
    connect(m_scanner, &Job::finished, this, [this] {
        m_startButton->setEnabled(true);
        m_cancelButton->setEnabled(false);
        for (QWidget *w : std::initializer_list<QWidget *>{m_from, m_to, m_thorough})
            w->setEnabled(true);
        m_progress->setValue(m_progress->maximum());
        switch (m_scanner->result()) {
        case Job::Result::Cancelled:
            m_progress->setFormat(tr("cancelled"));
            break;
        case Job::Result::Failed:
            m_progress->setFormat(tr("stopped: %1").arg(m_scanner->errorText()));
            break;
        default:
            m_progress->setFormat(tr("%n device(s) found in %1 s", nullptr, int(m_results.size()))
                                          .arg(double(m_bus->clockMs() - m_startedMs) / 1000.0, 0, 'f', 1));
            break;
        }
    });

    auto *range = new QHBoxLayout;
    range->addWidget(new QLabel(tr("From address"), this));
    range->addWidget(m_from);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_to);
    range->addWidget(m_startButton);
    range->addWidget(m_cancelButton);
    auto *buttons = new QDialogButtonBox(this);
    buttons->addButton(tr("Add checked devices"), QDialogButtonBox::AcceptRole);
    buttons->addButton(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, [this] {
        m_scanner->cancel();
        reject();
    });
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(range);
    layout->addWidget(m_thorough);
    layout->addWidget(m_plan);
    layout->addWidget(m_progress);
    layout->addWidget(m_found);
    layout->addWidget(buttons);
    resize(520, 380);
    updatePlan();
}

void ScanDialog::updatePlan()
{
    if (m_scanner->isRunning())
        return;
    m_scanner->setMode(m_thorough->isChecked() ? DeviceScanner::Mode::Thorough : DeviceScanner::Mode::Quick);
    const int from = m_from->value();
    const int to = std::max(from, m_to->value());
    const int full = m_scanner->fullTimeoutMs();
    if (m_scanner->effectiveMode(from, to) == DeviceScanner::Mode::Quick) {
        QString plan = tr("Each address is probed once at %1 ms, again at the full %2 ms where anything was heard.")
                               .arg(m_scanner->quickTimeoutMs())
                               .arg(full);
        const qsizetype listeners = m_scanner->listenersFor(from, to).size();
        if (listeners > 0)
            plan += QLatin1Char(' ')
                    + tr("The range is short: %n address(es) next to it are probed once first, to hear late "
                         "answers, and not reported.",
                         nullptr, int(listeners));
        m_plan->setText(plan);
        return;
    }
    const int worst = int((m_scanner->thoroughWorstMs(from, to) + 999) / 1000);
    m_plan->setText(tr("Every address is probed at the full timeout of %1 ms: up to %n s.", nullptr, worst).arg(full));
}

void ScanDialog::start()
{
    if (m_scanner->isRunning())
        return;
    m_found->clear();
    m_results.clear();
    m_startButton->setEnabled(false);
    m_cancelButton->setEnabled(true);
    updatePlan();
    for (QWidget *w : std::initializer_list<QWidget *>{m_from, m_to, m_thorough})
        w->setEnabled(false);   // what the scan does was said, and stays so
    m_startedMs = m_bus->clockMs();
    // The bar starts from nothing: the borrowed listeners, probed first, say no progress.
    const int from = m_from->value();
    const int to = std::max(from, m_to->value());
    const qsizetype listeners = m_scanner->listenersFor(from, to).size();
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setFormat(listeners > 0 ? tr("probing %n address(es) next to the range first", nullptr, int(listeners))
                                        : QString());
    m_scanner->start(from, to);
}

bool ScanDialog::isScanning() const
{
    return m_scanner->isRunning();
}

QList<QPair<std::shared_ptr<const RegisterMap>, quint8>> ScanDialog::chosen() const
{
    QList<QPair<std::shared_ptr<const RegisterMap>, quint8>> out;
    for (int i = 0; i < m_found->count(); ++i) {
        const QListWidgetItem *item = m_found->item(i);
        if (item->data(Qt::UserRole).isValid() && item->checkState() == Qt::Checked)
            out << m_results.at(item->data(Qt::UserRole).toInt());
    }
    return out;
}

} // namespace jumo
