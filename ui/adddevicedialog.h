// Asks for a device to add by hand: its family and its address on the line.
#pragma once

#include "protocol/registermap.h"

#include <QDialog>

#include <memory>

class QComboBox;
class QSpinBox;

namespace jumo {

class FamilyRegistry;

class AddDeviceDialog : public QDialog
{
    Q_OBJECT

public:
    AddDeviceDialog(const FamilyRegistry &registry, QWidget *parent = nullptr);

    std::shared_ptr<const RegisterMap> family() const;
    quint8 address() const;

private:
    const FamilyRegistry &m_registry;
    QComboBox *m_family;
    QSpinBox *m_address;
};

} // namespace jumo
