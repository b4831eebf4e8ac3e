#include "registermapbrowser.h"

#include "protocol/familyregistry.h"
#include "models/registermapmodel.h"

#include <QComboBox>
#include <QHeaderView>
#include <QLabel>
#include <QTableView>
#include <QVBoxLayout>

namespace jumo {

RegisterMapBrowser::RegisterMapBrowser(const FamilyRegistry &registry, QWidget *parent)
    : QWidget(parent), m_registry(registry), m_familyBox(new QComboBox(this)), m_summary(new QLabel(this)),
      m_table(new QTableView(this)), m_model(new RegisterMapModel(this))
{
    setWindowTitle(tr("JUMO register maps"));
    m_familyBox->setObjectName(QStringLiteral("familyBox"));
    m_table->setObjectName(QStringLiteral("registerTable"));
    m_summary->setObjectName(QStringLiteral("familySummary"));
    m_summary->setWordWrap(true);
    m_table->setModel(m_model);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_familyBox);
    layout->addWidget(m_summary);
    layout->addWidget(m_table);

    for (const auto &map : m_registry.families())
        m_familyBox->addItem(map->displayName(), map->family);
    connect(m_familyBox, &QComboBox::currentIndexChanged, this, &RegisterMapBrowser::showFamily);
    showFamily(m_familyBox->currentIndex());
    resize(1000, 700);
}

void RegisterMapBrowser::showFamily(int index)
{
    const auto map = m_registry.family(m_familyBox->itemData(index).toString());
    m_model->setMap(map);
    if (!map) {
        m_summary->setText(tr("No register maps could be loaded."));
        return;
    }
    m_summary->setText(tr("%1 - %2 registers - models: %3 - manual: %4")
                               .arg(map->displayName())
                               .arg(map->entries().size())
                               .arg(map->models.join(QStringLiteral(", ")), map->manual));
    m_table->resizeColumnsToContents();
}

} // namespace jumo
