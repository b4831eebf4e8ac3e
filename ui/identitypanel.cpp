#include "identitypanel.h"

#include "models/livevaluesmodel.h"
#include "protocol/registermap.h"

#include <QCoreApplication>
#include <QLabel>
#include <QVBoxLayout>

namespace jumo {

IdentityPanel::IdentityPanel(const RegisterMap &map, quint8 address, LiveValuesModel *values, QWidget *parent)
    : QWidget(parent), m_map(map), m_values(values), m_text(new QLabel(this)), m_address(address)
{
    m_text->setObjectName(QStringLiteral("identity"));
    m_text->setTextFormat(Qt::RichText);
    m_text->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_text);
    connect(m_values, &QAbstractItemModel::dataChanged, this, &IdentityPanel::refresh);
    refresh();
}

void IdentityPanel::refresh()
{
    if (!isVisible()) {
        m_dirty = true;   // caught up in showEvent()
        return;
    }
    m_dirty = false;
    QStringList parts;
    for (const QString &id : m_map.identity) {
        const int row = m_values->rowOf(id);
        if (row < 0)
            continue;
        const QString value = m_values->index(row, LiveValuesModel::ValueColumn).data().toString().trimmed();
        const RegisterEntry *e = m_map.entry(id);
        parts << QStringLiteral("%1: <b>%2</b>")
                         .arg(QCoreApplication::translate("jumo::maps", e->label.toUtf8().constData()).toHtmlEscaped(),
                              value.isEmpty() ? QStringLiteral("-") : value.toHtmlEscaped());
    }
    m_text->setText(QStringLiteral("<big><b>%1</b></big> &nbsp; %2<br>%3")
                            .arg(m_map.displayName().toHtmlEscaped(), tr("address %1").arg(m_address),
                                 parts.join(QStringLiteral(" &nbsp;·&nbsp; "))));
}

void IdentityPanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_dirty)
        refresh();
}

} // namespace jumo
