// Starts and stops CSV data logging of chosen values of a device: which values, how
// often, where, how large a file may grow before the next one starts, and how many of
// the files written are kept.
#pragma once

#include "logs/datalogger.h"

#include <QDialog>

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace jumo {

class DataLoggingDialog : public QDialog
{
    Q_OBJECT

public:
    DataLoggingDialog(const DeviceSource *devices, DeviceId device, DataLogger *logger, QWidget *parent = nullptr);

private:
    void toggle();
    void refresh();

    const DeviceSource *m_devices;
    DeviceId m_device;
    DataLogger *m_logger;
    QListWidget *m_entries;
    QSpinBox *m_interval;
    QSpinBox *m_maxSize;
    QSpinBox *m_keepFiles;
    QLineEdit *m_folder;
    QPushButton *m_startStop;
    QLabel *m_state;
};

} // namespace jumo
