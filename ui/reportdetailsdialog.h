// Asks for the title block of a commissioning report: site, cabinet, the device's tag
// and the engineer, filled with what was given last time, editable each time.
#pragma once

#include "commissioning/commissioningreport.h"

#include <QDialog>

class QLineEdit;

namespace jumo {

class ReportDetailsDialog : public QDialog
{
    Q_OBJECT

public:
    ReportDetailsDialog(const QString &device, const ReportTitle &title, QWidget *parent = nullptr);

    ReportTitle title() const;

private:
    QLineEdit *m_site;
    QLineEdit *m_cabinet;
    QLineEdit *m_tag;
    QLineEdit *m_engineer;
};

} // namespace jumo
