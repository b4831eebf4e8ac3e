#include "linedialog.h"

#include "bus/lineaddress.h"
#include "bus/serialportlist.h"
#include "bus/stationconfig.h"
#include "theme.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>

namespace jumo {

LineDialog::LineDialog(const QString &name, const BusSettings &settings, const QStringList &takenNames, QWidget *parent)
    : QDialog(parent), m_settings(settings), m_taken(takenNames), m_name(new QLineEdit(name, this)),
      m_address(new QComboBox(this)), m_baud(new QComboBox(this)), m_format(new QComboBox(this)),
      m_problem(new QLabel(this))
{
    setObjectName(QStringLiteral("lineDialog"));
    m_name->setObjectName(QStringLiteral("lineNameEdit"));
    m_address->setObjectName(QStringLiteral("lineAddressBox"));
    m_baud->setObjectName(QStringLiteral("lineBaudBox"));
    m_format->setObjectName(QStringLiteral("lineFormatBox"));
    m_problem->setObjectName(QStringLiteral("lineProblem"));
    m_name->setMaxLength(32);
    m_address->setEditable(true);
    m_address->setMinimumWidth(320);
    m_address->lineEdit()->setPlaceholderText(tr("/dev/ttyUSB0, tcp://10.0.0.20:502 or rtu+tcp://10.0.0.21:4001"));
    for (const SerialPort &port : SerialPortList::available())
        m_address->addItem(SerialPortList::label(port), port.location);
    const int listed = m_address->findData(settings.portName);
    if (listed >= 0)
        m_address->setCurrentIndex(listed);
    else
        m_address->setEditText(settings.portName);
    for (int baud : {4800, 9600, 19200, 38400})
        m_baud->addItem(QString::number(baud), baud);
    m_baud->setCurrentIndex(std::max(0, m_baud->findData(settings.format.baudRate)));
    for (const char *f : {"8N1", "8E1", "8O1", "8N2"})
        m_format->addItem(QLatin1String(f), QLatin1String(f));
    m_format->setCurrentIndex(std::max(0, m_format->findData(settings.format.formatName())));
    Theme::colourText(m_problem, Theme::Role::Refused);
    m_problem->setWordWrap(true);
    m_problem->hide();

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *form = new QFormLayout(this);
    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("&Address:"), m_address);
    form->addRow(tr("&Baud:"), m_baud);
    form->addRow(tr("&Format:"), m_format);
    form->addRow(m_problem);
    form->addRow(buttons);
}

QString LineDialog::name() const
{
    return m_name->text().trimmed();
}

BusSettings LineDialog::settings() const
{
    BusSettings s = m_settings;
    const int row = m_address->currentIndex();
    // A listed port shows its label; what it stands for is its location.
    s.portName = row >= 0 && m_address->itemText(row) == m_address->currentText() ? m_address->itemData(row).toString()
                                                                                   : m_address->currentText().trimmed();
    if (const auto format = LineFormat::parse(m_baud->currentData().toInt(), m_format->currentData().toString()))
        s.format = *format;
    return s;
}

QString LineDialog::nameProblem(const QString &name, const QStringList &takenNames)
{
    if (name.isEmpty())
        return tr("A line needs a name.");
    if (!StationConfig::isLineName(name))
        return tr("A line's name has 1 to 32 letters (A-Z, a-z), digits, '_', '.' or '-'.");
    if (takenNames.contains(name))
        return tr("There is a line named %1 already.").arg(name);
    return {};
}

void LineDialog::accept()
{
    QString problem = nameProblem(name(), m_taken);
    if (problem.isEmpty() && settings().portName.isEmpty())
        problem = tr("Choose or type the line's address.");
    if (problem.isEmpty())
        LineAddress::parse(settings().portName, &problem);   // a bad URL says what is wrong
    if (!problem.isEmpty()) {
        m_problem->setText(problem);
        m_problem->show();
        return;
    }
    QDialog::accept();
}

} // namespace jumo
