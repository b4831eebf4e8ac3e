#include "devicepage.h"

#include "models/alarmbitsmodel.h"
#include "bus/bus.h"
#include "controlspanel.h"
#include "identitypanel.h"
#include "ledgrid.h"
#include "models/livevaluesmodel.h"
#include "livevaluesview.h"
#include "parametereditor.h"
#include "theme.h"
#include "trendview.h"

#include <QLabel>
#include <QLineEdit>
#include <QShortcut>
#include <QTabWidget>
#include <QVBoxLayout>

namespace jumo {

DevicePage::DevicePage(Bus *bus, int device, LiveValuesModel *values, AlarmBitsModel *alarms, QWidget *parent)
    : DevicePage(bus, bus, device, values, alarms, parent)
{
}

DevicePage::DevicePage(const DeviceSource *devices, int device, LiveValuesModel *values, AlarmBitsModel *alarms,
                       QWidget *parent)
    : DevicePage(devices, nullptr, device, values, alarms, parent)
{
}

DevicePage::DevicePage(const DeviceSource *devices, Bus *bus, int device, LiveValuesModel *values,
                       AlarmBitsModel *alarms, QWidget *parent)
    : QWidget(parent), m_device(device), m_values(values), m_alarms(alarms), m_tabs(new QTabWidget(this)),
      m_readOnlyBanner(new QLabel(this)), m_identityBanner(new QLabel(this))
{
    const RegisterMap &map = *devices->deviceMap(device);
    setObjectName(QStringLiteral("device_%1_%2").arg(map.family).arg(devices->deviceAddress(device)));
    m_readOnlyBanner->setObjectName(QStringLiteral("readOnlyBanner"));
    m_readOnlyBanner->setText(tr("Read-only mode: values are shown, nothing is written to the device."));
    m_readOnlyBanner->setStyleSheet(Theme::bannerStyle(Theme::Role::InfoBanner, Theme::Role::InfoBannerText));
    m_readOnlyBanner->setWordWrap(true);
    m_readOnlyBanner->hide();
    m_identityBanner->setObjectName(QStringLiteral("identityBanner"));
    m_identityBanner->setWordWrap(true);
    m_identityBanner->hide();

    auto *valuesTab = new QWidget(this);
    auto *valuesLayout = new QVBoxLayout(valuesTab);
    valuesLayout->addWidget(new IdentityPanel(map, devices->deviceAddress(device), m_values, valuesTab));
    m_valuesView = new LiveValuesView(m_values, valuesTab);
    m_valuesView->setObjectName(QStringLiteral("liveValues"));
    valuesLayout->addWidget(m_valuesView);
    m_tabs->addTab(valuesTab, tr("Live values"));

    m_leds = new LedGrid(m_alarms, this);
    const int alarmsTab = m_tabs->addTab(m_leds, tr("Alarms and status"));
    auto showCount = [this, alarmsTab](int count) {
        m_tabs->setTabText(alarmsTab, count ? tr("Alarms and status (%1)").arg(count) : tr("Alarms and status"));
    };
    connect(m_alarms, &AlarmBitsModel::activeAlarmsChanged, this, showCount);
    showCount(m_alarms->activeAlarms());

    if (bus)
        addWriteTabs(bus, device, map);
    m_trend = new TrendView(m_values, map.overview, this);
    m_tabs->addTab(m_trend, tr("Trend"));

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_readOnlyBanner);
    layout->addWidget(m_identityBanner);
    layout->addWidget(m_tabs);
}

void DevicePage::addWriteTabs(Bus *bus, int device, const RegisterMap &map)
{
    m_controls = new ControlsPanel(bus, device, map,
                                   {"setpoint", "analog_output", "digital_output", "external_input", "alpha",
                                    "setpoint_select", "parameter_set_select", "binary_outputs", "switches", "command", "override"},
                                   m_values, this);
    m_tabs->addTab(m_controls, tr("Controls"));
    m_parameters = new ParameterEditor(bus, device, this);
    m_tabs->addTab(m_parameters, tr("Parameters"));
    // Ctrl+F while the page is shown (the focus may be in the device list): the parameter
    // search. Pages not shown hold no active shortcut.
    auto *find = new QShortcut(QKeySequence::Find, this);
    find->setContext(Qt::WindowShortcut);
    connect(find, &QShortcut::activated, this, [this] {
        m_tabs->setCurrentWidget(m_parameters);
        m_parameters->focusSearch();
    });
    auto *program = new ControlsPanel(bus, device, map, {"program"}, m_values, this);
    if (program->isEmpty()) {
        delete program;
    } else {
        m_program = program;
        m_tabs->addTab(m_program, tr("Program"));
    }
}

void DevicePage::setReadOnly(bool readOnly)
{
    m_readOnlyBanner->setVisible(readOnly);
    if (m_controls)
        m_controls->setReadOnly(readOnly);
    if (m_parameters)
        m_parameters->setReadOnly(readOnly);
    if (m_program)
        m_program->setReadOnly(readOnly);
}

void DevicePage::setDeviceTitle(const QString &title)
{
    if (m_controls)
        m_controls->setDeviceTitle(title);
    if (m_program)
        m_program->setDeviceTitle(title);
    if (m_parameters)
        m_parameters->setDeviceTitle(title);
}

void DevicePage::restyle(const DeviceCondition &condition)
{
    m_readOnlyBanner->setStyleSheet(Theme::bannerStyle(Theme::Role::InfoBanner, Theme::Role::InfoBannerText));
    m_trend->restyle();
    setCondition(condition);
}

void DevicePage::setCondition(const DeviceCondition &condition)
{
    switch (condition.state) {
    case DeviceCondition::State::WrongDevice:
        m_identityBanner->setText(tr("Wrong device: %1. Its values are not shown and nothing is written to it until "
                                     "the device at this address is of the family it was added as.")
                                          .arg(condition.detail));
        m_identityBanner->setStyleSheet(Theme::bannerStyle(Theme::Role::ErrorBanner, Theme::Role::ErrorBannerText));
        m_identityBanner->show();
        break;
    case DeviceCondition::State::Identifying:
        m_identityBanner->setText(condition.detail.isEmpty()
                                          ? tr("Checking that the device at this address is of this family.")
                                          : tr("Identity not confirmed: %1").arg(condition.detail));
        m_identityBanner->setStyleSheet(Theme::bannerStyle(Theme::Role::NeutralBanner, Theme::Role::NeutralBannerText));
        m_identityBanner->show();
        break;
    default:
        m_identityBanner->hide();
        break;
    }
}

} // namespace jumo
