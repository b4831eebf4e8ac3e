#include "adddevicedialog.h"

#include "protocol/familyregistry.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>

namespace jumo {

AddDeviceDialog::AddDeviceDialog(const FamilyRegistry &registry, QWidget *parent)
    : QDialog(parent), m_registry(registry), m_family(new QComboBox(this)), m_address(new QSpinBox(this))
{
    setWindowTitle(tr("Add device"));
    m_family->setObjectName(QStringLiteral("familyBox"));
    m_address->setObjectName(QStringLiteral("addressBox"));
    for (const auto &map : registry.families())
        m_family->addItem(map->name, map->family);
    auto updateRange = [this] {
        if (const auto map = family())
            m_address->setRange(map->protocol.addressMin, map->protocol.addressMax);
    };
    connect(m_family, &QComboBox::currentIndexChanged, this, updateRange);
    updateRange();
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *form = new QFormLayout(this);
    form->addRow(tr("&Family:"), m_family);
    form->addRow(tr("&Address:"), m_address);
    form->addRow(buttons);
}

std::shared_ptr<const RegisterMap> AddDeviceDialog::family() const
{
    return m_registry.family(m_family->currentData().toString());
}

quint8 AddDeviceDialog::address() const
{
    return quint8(m_address->value());
}

} // namespace jumo
