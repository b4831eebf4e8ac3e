#include "adddevicedialog.h"

#include "protocol/familyregistry.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>

namespace jumo {

AddDeviceDialog::AddDeviceDialog(const FamilyRegistry &registry, QWidget *parent)
    : QDialog(parent), m_registry(registry), m_line(new QComboBox(this)), m_family(new QComboBox(this)), m_address(new QSpinBox(this))
{
    setWindowTitle(tr("Add device"));
    m_line->setObjectName(QStringLiteral("addToLineBox"));
    m_family->setObjectName(QStringLiteral("familyBox"));
    m_address->setObjectName(QStringLiteral("addressBox"));
    for (const auto &map : registry.families())
        m_family->addItem(map->displayName(), map->family);
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
    form->addRow(tr("&Line:"), m_line);
    form->addRow(tr("&Family:"), m_family);
    form->addRow(tr("&Address:"), m_address);
    form->addRow(buttons);
}

std::shared_ptr<const RegisterMap> AddDeviceDialog::family() const
{
    return m_registry.family(m_family->currentData().toString());
}

void AddDeviceDialog::setLines(const QStringList &names, int current)
{
    m_line->clear();
    m_line->addItems(names);
    m_line->setCurrentIndex(current);
    auto *form = static_cast<QFormLayout *>(layout());
    form->setRowVisible(m_line, names.size() > 1);
}

int AddDeviceDialog::line() const
{
    return m_line->currentIndex();
}

quint8 AddDeviceDialog::address() const
{
    return quint8(m_address->value());
}

} // namespace jumo
