#include "reportdetailsdialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace jumo {

namespace {

// A title field holds a line of a printed table: long enough for any real name.
constexpr int maxFieldLength = 200;

} // namespace

ReportDetailsDialog::ReportDetailsDialog(const QString &device, const ReportTitle &title, QWidget *parent)
    : QDialog(parent), m_site(new QLineEdit(title.site, this)), m_cabinet(new QLineEdit(title.cabinet, this)),
      m_tag(new QLineEdit(title.tag, this)), m_engineer(new QLineEdit(title.engineer, this))
{
    setWindowTitle(tr("Commissioning report"));
    const QList<QPair<QLineEdit *, QString>> fields{{m_site, QStringLiteral("siteEdit")},
                                                    {m_cabinet, QStringLiteral("cabinetEdit")},
                                                    {m_tag, QStringLiteral("tagEdit")},
                                                    {m_engineer, QStringLiteral("engineerEdit")}};
    for (const auto &[edit, name] : fields) {
        edit->setObjectName(name);
        edit->setMaxLength(maxFieldLength);
        edit->setMinimumWidth(320);
    }
    m_site->setPlaceholderText(tr("Plant, hall or building"));
    m_cabinet->setPlaceholderText(tr("Cabinet or panel"));
    m_tag->setPlaceholderText(tr("e.g. TIC-101"));
    m_engineer->setPlaceholderText(tr("Who commissions the device"));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Choose a &file..."));
    buttons->button(QDialogButtonBox::Ok)->setObjectName(QStringLiteral("chooseFileButton"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *form = new QFormLayout(this);
    auto *intro = new QLabel(tr("The title block of the report of %1. What you enter here is offered again next time.")
                                     .arg(device),
                             this);
    intro->setWordWrap(true);
    form->addRow(intro);
    form->addRow(tr("&Site:"), m_site);
    form->addRow(tr("&Cabinet:"), m_cabinet);
    form->addRow(tr("Device &tag:"), m_tag);
    form->addRow(tr("&Engineer:"), m_engineer);
    form->addRow(buttons);
}

ReportTitle ReportDetailsDialog::title() const
{
    return {m_site->text().trimmed(), m_cabinet->text().trimmed(), m_tag->text().trimmed(), m_engineer->text().trimmed()};
}

} // namespace jumo
