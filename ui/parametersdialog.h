// Backup, compare and restore of a device's parameters in the HMI: files chosen by the
// user, a table of differences (old, new, unit, result), progress and cancel, and a
// confirmation before anything is written.
#pragma once

#include "commissioning/parametertransfer.h"

#include <QDialog>

#include <functional>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace jumo {

class ParametersDialog : public QDialog
{
    Q_OBJECT

public:
    ParametersDialog(Bus *bus, DeviceId device, QWidget *parent = nullptr);

    // The three actions; the file dialogs and the confirmation live in the buttons'
    // handlers, so tests drive these directly. confirm() decides about writing.
    void backup(const QString &path);
    void compare(const QString &path);
    void restore(const QString &path, const std::function<bool(int count)> &confirm);

    QString status() const;
    int differenceCount() const;
    bool isBusy() const { return m_transfer->isBusy(); }

private:
    std::optional<ParameterSet> load(const QString &path);
    // Loads a file for compare or restore, refuses another family, and starts reading
    // the device; the caller connects readFinished.
    std::optional<ParameterSet> startReadFor(const QString &path);
    void showDifferences(const QList<ParameterDifference> &differences);
    void setBusy(bool busy);
    void setStatus(const QString &text);

    Bus *m_bus;
    DeviceId m_device;
    ParameterTransfer *m_transfer;
    QTableWidget *m_table;
    QProgressBar *m_progress;
    QLabel *m_status;
    QList<QPushButton *> m_actions;
    QPushButton *m_cancel;
    QList<ParameterDifference> m_differences;
};

} // namespace jumo
