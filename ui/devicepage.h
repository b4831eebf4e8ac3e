// The page of one device, built entirely from its family's map: identity and live
// values, LED grid, controls, parameters, program (where the family has one), trend.
#pragma once

#include "bus/bus.h"

#include <QWidget>

class QLabel;
class QTabWidget;

namespace jumo {

class AlarmBitsModel;
class Bus;
class ControlsPanel;
class LedGrid;
class LiveValuesModel;
class LiveValuesView;
class ParameterEditor;
class TrendView;

class DevicePage : public QWidget
{
    Q_OBJECT

public:
    // The models belong to the caller: they outlive the page, which is made when first shown.
    DevicePage(Bus *bus, int device, LiveValuesModel *values, AlarmBitsModel *alarms, QWidget *parent = nullptr);
    // A page that only shows (a remote viewer's): live values, LEDs and trend, with no
    // controls, parameters or program, since there is nothing to write with.
    DevicePage(const DeviceSource *devices, int device, LiveValuesModel *values, AlarmBitsModel *alarms,
               QWidget *parent = nullptr);

    void setReadOnly(bool readOnly);
    // How the questions before a write name the device ("IPC 300 at address 1 on line
    // cabinet-a", see DeviceTitle).
    void setDeviceTitle(const QString &title);
    // A banner says why nothing is shown or written while another device answers or the
    // identity check is under way.
    void setCondition(const DeviceCondition &condition);
    int device() const { return m_device; }
    LiveValuesModel *values() const { return m_values; }
    AlarmBitsModel *alarms() const { return m_alarms; }
    LiveValuesView *valuesView() const { return m_valuesView; }
    LedGrid *ledGrid() const { return m_leds; }
    ControlsPanel *controls() const { return m_controls; }
    ParameterEditor *parameters() const { return m_parameters; }
    QTabWidget *tabs() const { return m_tabs; }
    TrendView *trend() const { return m_trend; }
    // Takes the colours of the theme now in use (banners).
    void restyle(const DeviceCondition &condition);

private:
    DevicePage(const DeviceSource *devices, Bus *writer, int device, LiveValuesModel *values, AlarmBitsModel *alarms,
               QWidget *parent);
    // Controls, parameters and program: the tabs that write.
    void addWriteTabs(Bus *bus, int device, const RegisterMap &map);

    int m_device;
    LiveValuesModel *m_values;
    AlarmBitsModel *m_alarms;
    QTabWidget *m_tabs;
    LiveValuesView *m_valuesView;
    LedGrid *m_leds;
    // Null on a page that only shows.
    ControlsPanel *m_controls = nullptr;
    ParameterEditor *m_parameters = nullptr;
    ControlsPanel *m_program = nullptr;
    TrendView *m_trend;
    QLabel *m_readOnlyBanner;
    QLabel *m_identityBanner;
};

} // namespace jumo
