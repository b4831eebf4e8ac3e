// Asks for a device to add by hand: its line (when there are several), its family and its
// address on the line.
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
    // The lines to choose from, the current one chosen; shown with two or more.
    void setLines(const QStringList &names, int current);
    int line() const;

private:
    const FamilyRegistry &m_registry;
    QComboBox *m_line;
    QComboBox *m_family;
    QSpinBox *m_address;
};

} // namespace jumo
