#include "parameterwritepreview.h"

#include "theme.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScreen>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace jumo {

ParameterWritePreview::ParameterWritePreview(const QString &deviceName, const QList<Change> &changes, QWidget *parent)
    : QDialog(parent), m_changes(changes), m_table(new QTableWidget(this))
{
    setObjectName(QStringLiteral("writePreview"));
    setWindowTitle(tr("Write parameters"));
    const int count = int(changes.size());
    const int eeprom = int(std::count_if(changes.cbegin(), changes.cend(), [](const Change &c) { return c.eeprom; }));
    const bool anyUnknown = std::any_of(changes.cbegin(), changes.cend(), [](const Change &c) { return !c.lastWrite.isEmpty(); });

    auto *question = new QLabel(tr("Write these %n change(s) to %1? Each is written once and verified by reading it back.",
                                   nullptr, count)
                                        .arg(deviceName),
                                this);
    question->setObjectName(QStringLiteral("previewQuestion"));
    question->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(question);
    if (eeprom > 0) {
        auto *wear = new QLabel(tr("%n of them are stored in EEPROM, which wears with every write.", nullptr, eeprom), this);
        wear->setObjectName(QStringLiteral("previewEeprom"));
        wear->setWordWrap(true);
        Theme::colourText(wear, Theme::Role::Hint);
        layout->addWidget(wear);
    }

    QStringList headers{tr("Parameter"), tr("Device value"), tr("New value"), tr("Unit")};
    if (anyUnknown)
        headers << tr("Last write");
    m_table->setObjectName(QStringLiteral("previewTable"));
    m_table->setColumnCount(int(headers.size()));
    m_table->setHorizontalHeaderLabels(headers);
    m_table->setRowCount(count);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setWordWrap(false);
    m_table->setTextElideMode(Qt::ElideRight);
    for (int row = 0; row < count; ++row) {
        const Change &c = changes[row];
        QStringList cells{c.label, c.deviceValue, c.newValue, c.unit};
        if (anyUnknown)
            cells << c.lastWrite;
        for (int column = 0; column < cells.size(); ++column) {
            auto *item = new QTableWidgetItem(cells[column]);
            item->setToolTip(cells[column]);
            if (column == 1 || column == 2)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            if (column == 2) {
                QFont bold = item->font();
                bold.setBold(true);
                item->setFont(bold);
            }
            if (column == 0)
                item->setData(Qt::UserRole, c.id);
            m_table->setItem(row, column, item);
        }
    }
    m_table->resizeColumnsToContents();
    QHeaderView *header = m_table->horizontalHeader();
    header->setSectionResizeMode(0, QHeaderView::Stretch);
    header->setStretchLastSection(false);
    layout->addWidget(m_table, 1);
    if (anyUnknown) {
        auto *unknown = new QLabel(tr("A change whose last write is unknown may already be on the device: writing it "
                                      "again sends the same value once more."),
                                   this);
        unknown->setObjectName(QStringLiteral("previewUnknown"));
        unknown->setWordWrap(true);
        layout->addWidget(unknown);
    }

    auto *buttons = new QDialogButtonBox(this);
    QPushButton *write = buttons->addButton(tr("&Write %n change(s)", nullptr, count), QDialogButtonBox::AcceptRole);
    write->setObjectName(QStringLiteral("confirmWrite"));
    write->setDefault(true);
    QPushButton *cancel = buttons->addButton(tr("Cancel"), QDialogButtonBox::RejectRole);
    cancel->setObjectName(QStringLiteral("cancelWrite"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);

    // As large as the table wants (every row, every column), within the screen.
    m_table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    m_table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    write->setFocus();
    const QRect screen = parent && parent->screen() ? parent->screen()->availableGeometry() : QRect(0, 0, 1280, 800);
    const QSize wanted = sizeHint();
    resize(std::clamp(wanted.width() + 24, 560, screen.width() * 9 / 10), std::min(wanted.height(), screen.height() * 9 / 10));
}

} // namespace jumo
