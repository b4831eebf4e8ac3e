#include "dataloggingdialog.h"

#include "logs/eventlog.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace jumo {

DataLoggingDialog::DataLoggingDialog(const DeviceSource *devices, DeviceId device, DataLogger *logger, QWidget *parent)
    : QDialog(parent), m_devices(devices), m_device(device), m_logger(logger), m_entries(new QListWidget(this)),
      m_interval(new QSpinBox(this)), m_maxSize(new QSpinBox(this)), m_keepFiles(new QSpinBox(this)),
      m_folder(new QLineEdit(this)),
      m_startStop(new QPushButton(this)), m_state(new QLabel(this))
{
    setWindowTitle(tr("Data logging"));
    const auto map = devices->deviceMap(device);
    for (const RegisterEntry &e : map->entries()) {
        if (!e.isReadable() || e.reserved || e.type == ValueType::Text || !e.alias.isEmpty())
            continue;
        auto *item = new QListWidgetItem(QStringLiteral("%1 (%2)").arg(
                                                 QCoreApplication::translate("jumo::maps", e.label.toUtf8().constData()), e.id),
                                         m_entries);
        item->setData(Qt::UserRole, e.id);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(map->overview.contains(e.id) ? Qt::Checked : Qt::Unchecked);
    }
    m_interval->setRange(100, 3600000);
    m_interval->setSingleStep(100);
    m_interval->setValue(1000);
    m_interval->setSuffix(tr(" ms"));
    m_maxSize->setRange(1, 2048);
    m_maxSize->setValue(10);
    m_maxSize->setSuffix(tr(" MiB"));
    m_keepFiles->setObjectName(QStringLiteral("keepFiles"));
    m_keepFiles->setRange(0, 100000);
    m_keepFiles->setSpecialValueText(tr("all"));
    m_keepFiles->setSuffix(tr(" newest files"));
    m_keepFiles->setValue(0);
    m_folder->setText(EventLog::defaultFolder() + QStringLiteral("/data"));
    connect(m_startStop, &QPushButton::clicked, this, &DataLoggingDialog::toggle);
    connect(m_logger, &DataLogger::failed, this, [this](const QString &reason) {
        m_state->setText(tr("Stopped: %1").arg(reason));
        refresh();
    });
    auto *form = new QFormLayout;
    form->addRow(tr("Interval:"), m_interval);
    form->addRow(tr("New file after:"), m_maxSize);
    form->addRow(tr("Keep:"), m_keepFiles);
    form->addRow(tr("Folder:"), m_folder);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_startStop, QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Values to log (a new file also starts each day):"), this));
    layout->addWidget(m_entries);
    layout->addLayout(form);
    layout->addWidget(m_state);
    layout->addWidget(buttons);
    refresh();
    resize(520, 520);
}

void DataLoggingDialog::toggle()
{
    if (m_logger->isRunning()) {
        m_logger->stop();
        m_state->setText(tr("Stopped; %n row(s) written.", nullptr, m_logger->rowsWritten()));
        refresh();
        return;
    }
    DataLogger::Settings settings;
    settings.folder = m_folder->text().trimmed();
    settings.intervalMs = m_interval->value();
    settings.maxFileBytes = qint64(m_maxSize->value()) * 1024 * 1024;
    settings.keepFiles = m_keepFiles->value();
    for (int i = 0; i < m_entries->count(); ++i) {
        if (m_entries->item(i)->checkState() == Qt::Checked)
            settings.entries << qMakePair(m_device, m_entries->item(i)->data(Qt::UserRole).toString());
    }
    QString error;
    if (!m_logger->start(settings, &error))
        m_state->setText(tr("Not started: %1").arg(error));
    else
        m_state->setText(tr("Logging to %1").arg(m_logger->currentFile()));
    refresh();
}

void DataLoggingDialog::refresh()
{
    const bool running = m_logger->isRunning();
    m_startStop->setText(running ? tr("Stop logging") : tr("Start logging"));
    m_entries->setEnabled(!running);
    m_interval->setEnabled(!running);
    m_maxSize->setEnabled(!running);
    m_keepFiles->setEnabled(!running);
    m_folder->setEnabled(!running);
}

} // namespace jumo
