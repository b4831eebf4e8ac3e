// A window that shows the register maps of all known families: a family chooser and
// the selected family's registers, with the manual's corrections as tooltips.
#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QTableView;

namespace jumo {

class FamilyRegistry;
class RegisterMapModel;

class RegisterMapBrowser : public QWidget
{
    Q_OBJECT

public:
    explicit RegisterMapBrowser(const FamilyRegistry &registry, QWidget *parent = nullptr);

private:
    void showFamily(int index);

    const FamilyRegistry &m_registry;
    QComboBox *m_familyBox;
    QLabel *m_summary;
    QTableView *m_table;
    RegisterMapModel *m_model;
};

} // namespace jumo
