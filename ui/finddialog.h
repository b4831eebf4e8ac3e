// Devices > Find on an unknown line: searches the port of a disconnected serial line at
// every baud rate and format the families support (LineFinder), with the plan, progress,
// time left and cancel, and offers the settings where devices answered for the line, with
// the devices found there for adding.
#pragma once

#include "bus/bussettings.h"
#include "bus/linefinder.h"

#include <QDialog>

#include <memory>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTreeWidget;

namespace jumo {

class Bus;
class FamilyRegistry;

class FindDialog : public QDialog
{
    Q_OBJECT

public:
    FindDialog(const BusSettings &line, const FamilyRegistry &registry, QWidget *parent = nullptr);
    ~FindDialog() override;

    void start();
    bool isSearching() const;
    // The setting chosen for the line (the best where devices answered); null if none.
    std::optional<LineFormat> chosenFormat() const;
    // The checked devices found at the chosen setting.
    QList<QPair<std::shared_ptr<const RegisterMap>, quint8>> chosen() const;

private:
    void updatePlan();
    void onFound(const LineFinder::Finding &finding);
    void onFinished();
    QString settingName(const LineFormat &format) const;
    void showChosenSetting();

    std::unique_ptr<Bus> m_bus;
    std::unique_ptr<LineFinder> m_finder;
    QSpinBox *m_from;
    QSpinBox *m_to;
    QLabel *m_plan;
    QProgressBar *m_progress;
    QTreeWidget *m_found;
    QComboBox *m_setting;
    QLabel *m_note;   // one device at several formats of one baud rate
    QPushButton *m_startButton;
    QPushButton *m_cancelButton;
    QPushButton *m_useButton;
    QString m_trying;
    QList<LineFormat> m_answered;   // the settings in m_setting, in order
};

} // namespace jumo
