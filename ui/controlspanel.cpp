#include "controlspanel.h"

#include "controlrow.h"
#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QFrame>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>

namespace jumo {

ControlsPanel::ControlsPanel(Bus *bus, int device, const RegisterMap &map, const QStringList &controls,
                             LiveValuesModel *values, QWidget *parent)
    : QWidget(parent)
{
    auto *inner = new QWidget;
    auto *list = new QVBoxLayout(inner);
    // The setpoint fields first, the one kept in RAM before those that wear the EEPROM
    // (about 10,000 writes): the field an operator uses most is the one that wears
    // nothing. A setpoint override is one when the map names it so (its simulation's
    // "setpointOverride"). Then every other control, by the manual's sections.
    const QString setpointOverride = map.simulation ? map.simulation->binding(QStringLiteral("setpointOverride")) : QString();
    auto isSetpoint = [&](const RegisterEntry &e) {
        return e.control == QLatin1String("setpoint") || (!setpointOverride.isEmpty() && e.id == setpointOverride);
    };
    auto wear = [](const RegisterEntry *e) { return e->storage == Storage::Ram ? 0 : e->storage == Storage::None ? 1 : 2; };
    QList<const RegisterEntry *> setpoints;
    QList<const RegisterEntry *> others;
    for (const RegisterEntry &e : map.entries()) {
        if (!controls.contains(e.control) || !e.isWritable() || e.reserved)
            continue;
        (controls.contains(QStringLiteral("setpoint")) && isSetpoint(e) ? setpoints : others) << &e;
    }
    std::stable_sort(setpoints.begin(), setpoints.end(),
                     [&wear](const RegisterEntry *a, const RegisterEntry *b) { return wear(a) < wear(b); });
    std::stable_sort(others.begin(), others.end(),
                     [](const RegisterEntry *a, const RegisterEntry *b) { return sectionBefore(a->group, b->group); });
    auto addHeading = [inner, list](const QString &title) {
        auto *heading = new QLabel(QStringLiteral("<h3>%1</h3>").arg(title.toHtmlEscaped()), inner);
        heading->setWordWrap(true);
        list->addWidget(heading);
    };
    auto addRow = [&](const RegisterEntry &e) {
        auto *row = new ControlRow(bus, device, map, e, values, inner);
        list->addWidget(row);
        auto *line = new QFrame(inner);
        line->setFrameShape(QFrame::HLine);
        line->setFrameShadow(QFrame::Sunken);
        list->addWidget(line);
        m_rows << row;
    };
    if (!setpoints.isEmpty())
        addHeading(tr("Setpoints"));
    for (const RegisterEntry *e : std::as_const(setpoints))
        addRow(*e);
    QString group;
    for (const RegisterEntry *e : std::as_const(others)) {
        if (e->group != group) {
            group = e->group;
            addHeading(QCoreApplication::translate("jumo::maps", group.toUtf8().constData()));
        }
        addRow(*e);
    }
    list->addStretch();
    auto *scroll = new QScrollArea(this);
    scroll->setWidget(inner);
    scroll->setWidgetResizable(true);
    // Every row wraps or flows, so the page never needs a horizontal scroll bar.
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);
}

void ControlsPanel::setReadOnly(bool readOnly)
{
    for (ControlRow *row : std::as_const(m_rows))
        row->setReadOnly(readOnly);
}

void ControlsPanel::setDeviceTitle(const QString &title)
{
    for (ControlRow *row : std::as_const(m_rows))
        row->setDeviceTitle(title);
}

ControlRow *ControlsPanel::row(const QString &entryId) const
{
    for (ControlRow *r : m_rows) {
        if (r->objectName() == QStringLiteral("control_") + entryId)
            return r;
    }
    return nullptr;
}

} // namespace jumo
