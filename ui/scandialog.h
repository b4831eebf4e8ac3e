// Scans the connected line for devices, with progress and cancel, and offers what it
// finds for adding.
#pragma once

#include "protocol/registermap.h"

#include <QDialog>

#include <memory>

class QCheckBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace jumo {

class Bus;
class DeviceScanner;
class FamilyRegistry;

class ScanDialog : public QDialog
{
    Q_OBJECT

public:
    ScanDialog(Bus *bus, const FamilyRegistry &registry, QWidget *parent = nullptr);

    void start();
    bool isScanning() const;
    // The found devices the user left checked.
    QList<QPair<std::shared_ptr<const RegisterMap>, quint8>> chosen() const;

private:
    // What a scan of the chosen range costs, said before it starts.
    void updatePlan();

    Bus *m_bus;
    DeviceScanner *m_scanner;
    QSpinBox *m_from;
    QSpinBox *m_to;
    QProgressBar *m_progress;
    QListWidget *m_found;
    QPushButton *m_startButton;
    QPushButton *m_cancelButton;
    QCheckBox *m_thorough;
    QLabel *m_plan;
    qint64 m_startedMs = 0;
    QList<QPair<std::shared_ptr<const RegisterMap>, quint8>> m_results;
};

} // namespace jumo
