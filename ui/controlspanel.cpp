#include "controlspanel.h"

#include "controlrow.h"
#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QFrame>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace jumo {

ControlsPanel::ControlsPanel(Bus *bus, int device, const RegisterMap &map, const QStringList &controls,
                             LiveValuesModel *values, QWidget *parent)
    : QWidget(parent)
{
    auto *inner = new QWidget;
    auto *list = new QVBoxLayout(inner);
    QString group;
    for (const RegisterEntry &e : map.entries()) {
        if (!controls.contains(e.control) || !e.isWritable() || e.reserved)
            continue;
        if (e.group != group) {
            group = e.group;
            const QString title = QCoreApplication::translate("jumo::maps", group.toUtf8().constData());
            auto *heading = new QLabel(QStringLiteral("<h3>%1</h3>").arg(title.toHtmlEscaped()), inner);
            heading->setWordWrap(true);
            list->addWidget(heading);
        }
        auto *row = new ControlRow(bus, device, map, e, values, inner);
        list->addWidget(row);
        auto *line = new QFrame(inner);
        line->setFrameShape(QFrame::HLine);
        line->setFrameShadow(QFrame::Sunken);
        list->addWidget(line);
        m_rows << row;
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

ControlRow *ControlsPanel::row(const QString &entryId) const
{
    for (ControlRow *r : m_rows) {
        if (r->objectName() == QStringLiteral("control_") + entryId)
            return r;
    }
    return nullptr;
}

} // namespace jumo
