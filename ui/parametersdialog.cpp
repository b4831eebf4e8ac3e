#include "parametersdialog.h"

#include "protocol/filesaver.h"
#include "protocol/regularfile.h"

#include <QCoreApplication>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace jumo {

ParametersDialog::ParametersDialog(Bus *bus, DeviceId device, QWidget *parent)
    : QDialog(parent), m_bus(bus), m_device(device), m_transfer(new ParameterTransfer(bus, device, this)),
      m_table(new QTableWidget(this)), m_progress(new QProgressBar(this)), m_status(new QLabel(this)),
      m_cancel(new QPushButton(tr("Cancel"), this))
{
    const auto map = bus->deviceMap(device);
    setWindowTitle(tr("Parameters of %1 at address %2").arg(map->displayName()).arg(bus->deviceAddress(device)));
    m_table->setObjectName(QStringLiteral("differences"));
    m_table->setColumnCount(5);
    m_table->setHorizontalHeaderLabels({tr("Parameter"), tr("Device"), tr("File"), tr("Unit"), tr("Result")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_status->setObjectName(QStringLiteral("parameterStatus"));
    m_status->setWordWrap(true);
    const QString filter = tr("Parameter files (*.json)");
    auto *backupButton = new QPushButton(tr("Back up to file..."), this);
    auto *compareButton = new QPushButton(tr("Compare with file..."), this);
    auto *restoreButton = new QPushButton(tr("Restore from file..."), this);
    m_actions = {backupButton, compareButton, restoreButton};
    restoreButton->setEnabled(!bus->isReadOnly());
    connect(backupButton, &QPushButton::clicked, this, [this, filter] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Back up parameters"), QString(), filter);
        if (!path.isEmpty())
            backup(path);
    });
    connect(compareButton, &QPushButton::clicked, this, [this, filter] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Compare with"), QString(), filter);
        if (!path.isEmpty())
            compare(path);
    });
    connect(restoreButton, &QPushButton::clicked, this, [this, filter] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Restore from"), QString(), filter);
        if (path.isEmpty())
            return;
        restore(path, [this](int count) {
            return QMessageBox::question(this, tr("Restore parameters"),
                                         tr("Write %n parameter(s) that differ to the device? Each is verified by "
                                            "reading it back; EEPROM parameters wear with every write.",
                                            nullptr, count))
                    == QMessageBox::Yes;
        });
    });
    connect(m_cancel, &QPushButton::clicked, m_transfer, &ParameterTransfer::cancel);
    connect(m_transfer, &ParameterTransfer::progress, this, [this](int done, int total) {
        m_progress->setRange(0, std::max(1, total));
        m_progress->setValue(done);
    });
    auto *actions = new QHBoxLayout;
    for (QPushButton *b : std::as_const(m_actions))
        actions->addWidget(b);
    actions->addStretch();
    actions->addWidget(m_cancel);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(actions);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(m_table);
    setBusy(false);
    resize(760, 480);
}

QString ParametersDialog::status() const
{
    return m_status->text();
}

int ParametersDialog::differenceCount() const
{
    return int(m_differences.size());
}

void ParametersDialog::setStatus(const QString &text)
{
    m_status->setText(text);
}

void ParametersDialog::setBusy(bool busy)
{
    for (QPushButton *b : std::as_const(m_actions))
        b->setEnabled(!busy && (b != m_actions.last() || !m_bus->isReadOnly()));
    m_cancel->setEnabled(busy);
}

std::optional<ParameterSet> ParametersDialog::load(const QString &path)
{
    QString error;
    const std::optional<QByteArray> json = RegularFile::read(path, RegularFile::defaultLimit, &error);
    if (!json) {
        setStatus(tr("Cannot read %1").arg(error));
        return std::nullopt;
    }
    std::optional<ParameterSet> set = ParameterSet::fromJson(*json, &error);
    if (!set)
        setStatus(error);
    return set;
}

void ParametersDialog::showDifferences(const QList<ParameterDifference> &differences)
{
    m_differences = differences;
    const auto map = m_bus->deviceMap(m_device);
    m_table->setRowCount(int(differences.size()));
    for (int row = 0; row < differences.size(); ++row) {
        const ParameterDifference &d = differences[row];
        const QStringList cells{QCoreApplication::translate("jumo::maps", d.label.toUtf8().constData()), d.oldDisplay,
                                d.newDisplay, d.unit, QString()};
        for (int c = 0; c < cells.size(); ++c)
            m_table->setItem(row, c, new QTableWidgetItem(cells[c]));
    }
}

void ParametersDialog::backup(const QString &path)
{
    setBusy(true);
    setStatus(tr("Reading all parameters..."));
    disconnect(m_transfer, &ParameterTransfer::readFinished, this, nullptr);
    connect(m_transfer, &ParameterTransfer::readFinished, this, [this, path](const ParameterSet &set, const QStringList &failed) {
        setBusy(false);
        if (!failed.isEmpty()) {
            setStatus(tr("Not saved: these could not be read: %1").arg(failed.join(QStringLiteral(", "))));
            return;
        }
        QString error;
        if (!FileSaver::save(path, set.toJson(), &error)) {
            setStatus(error);
            return;
        }
        setStatus(tr("%n parameter(s) saved to %1", nullptr, int(set.values.size())).arg(path));
    }, Qt::SingleShotConnection);
    m_transfer->read();
}

std::optional<ParameterSet> ParametersDialog::startReadFor(const QString &path)
{
    std::optional<ParameterSet> file = load(path);
    if (!file)
        return std::nullopt;
    const auto map = m_bus->deviceMap(m_device);
    if (file->family != map->family) {
        setStatus(tr("Refused: %1").arg(file->incompatibility(*map, QString())));
        return std::nullopt;
    }
    setBusy(true);
    setStatus(tr("Reading all parameters..."));
    disconnect(m_transfer, &ParameterTransfer::readFinished, this, nullptr);
    return file;
}

void ParametersDialog::compare(const QString &path)
{
    const std::optional<ParameterSet> file = startReadFor(path);
    if (!file)
        return;
    connect(m_transfer, &ParameterTransfer::readFinished, this, [this, file](const ParameterSet &device, const QStringList &failed) {
        setBusy(false);
        if (!failed.isEmpty()) {
            setStatus(tr("Could not read: %1").arg(failed.join(QStringLiteral(", "))));
            return;
        }
        const QList<ParameterDifference> d = device.differences(*file, *m_bus->deviceMap(m_device));
        showDifferences(d);
        setStatus(d.isEmpty() ? tr("The device matches the file.")
                              : tr("%n parameter(s) differ from the file.", nullptr, int(d.size())));
    }, Qt::SingleShotConnection);
    m_transfer->read();
}

void ParametersDialog::restore(const QString &path, const std::function<bool(int)> &confirm)
{
    const std::optional<ParameterSet> file = startReadFor(path);
    if (!file)
        return;
    connect(m_transfer, &ParameterTransfer::readFinished, this,
            [this, file, confirm](const ParameterSet &device, const QStringList &failed) {
                const RegisterMap &map = *m_bus->deviceMap(m_device);
                if (!failed.isEmpty()) {
                    setBusy(false);
                    setStatus(tr("Could not read: %1").arg(failed.join(QStringLiteral(", "))));
                    return;
                }
                if (const QString refused = file->incompatibility(map, device.softwareVersion); !refused.isEmpty()) {
                    setBusy(false);
                    setStatus(tr("Refused: %1").arg(refused));
                    return;
                }
                const QList<ParameterDifference> shown = device.differences(*file, map);
                const QList<ParameterDifference> d = ParameterSet::toRestore(shown);
                const int missing = int(shown.size() - d.size());
                showDifferences(d);
                if (d.isEmpty()) {
                    setBusy(false);
                    setStatus(missing > 0 ? tr("Nothing to write: the %n parameter(s) that differ are missing from the "
                                               "file and are left as they are.",
                                               nullptr, missing)
                                          : tr("The device already matches the file: nothing to write."));
                    return;
                }
                // Only what differs is written: EEPROM is not worn by unchanged values.
                if (!confirm(int(d.size()))) {
                    setBusy(false);
                    setStatus(tr("Nothing written."));
                    return;
                }
                setStatus(tr("Writing..."));
                m_transfer->write(d);
            },
            Qt::SingleShotConnection);
    disconnect(m_transfer, &ParameterTransfer::entryWritten, this, nullptr);
    connect(m_transfer, &ParameterTransfer::entryWritten, this, [this](const QString &id, const WriteOutcome &outcome) {
        for (int row = 0; row < m_differences.size(); ++row) {
            if (m_differences[row].id == id)
                m_table->setItem(row, 4, new QTableWidgetItem(outcome.message));
        }
    });
    disconnect(m_transfer, &ParameterTransfer::writeFinished, this, nullptr);
    connect(m_transfer, &ParameterTransfer::writeFinished, this, [this](int succeeded, int failed, bool cancelled) {
        setBusy(false);
        setStatus(cancelled ? tr("Cancelled after %n verified write(s).", nullptr, succeeded)
                  : failed ? tr("%1 written and verified, %2 failed: see the table.").arg(succeeded).arg(failed)
                           : tr("%n parameter(s) restored and verified.", nullptr, succeeded));
    }, Qt::SingleShotConnection);
    m_transfer->read();
}

} // namespace jumo
