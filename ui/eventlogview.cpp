#include "eventlogview.h"

#include "logs/eventlog.h"
#include "models/eventlogmodel.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

namespace jumo {

EventLogView::EventLogView(EventLog *log, const QStringList &columns, const QStringList &titles, QWidget *parent)
    : QWidget(parent), m_log(log), m_columns(columns), m_model(new EventLogModel(log, columns, titles, this)),
      m_filter(new QSortFilterProxyModel(this)), m_table(new QTableView(this)), m_filterEdit(new QLineEdit(this))
{
    m_filter->setSourceModel(m_model);
    m_filter->setFilterKeyColumn(-1);
    m_filter->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_table->setModel(m_filter);
    m_table->setSortingEnabled(true);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setObjectName(QStringLiteral("logTable"));
    m_filterEdit->setObjectName(QStringLiteral("logFilter"));
    m_filterEdit->setPlaceholderText(tr("Filter: device, entry, kind, text..."));
    m_filterEdit->setClearButtonEnabled(true);
    connect(m_filterEdit, &QLineEdit::textChanged, this, &EventLogView::setFilter);
    auto *exportButton = new QPushButton(tr("Export CSV..."), this);
    connect(exportButton, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export"), QString(), tr("CSV files (*.csv)"));
        QString error;
        if (!path.isEmpty() && !m_log->exportCsv(path, m_columns, &error))
            QMessageBox::warning(this, tr("Export"), error);
    });
    auto *bar = new QHBoxLayout;
    bar->addWidget(m_filterEdit, 1);
    bar->addWidget(exportButton);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_table);
    if (!log->path().isEmpty())
        layout->addWidget(new QLabel(tr("Kept in %1").arg(log->path()), this));
    // New records scroll into view unless the user looks at older ones.
    connect(m_model, &QAbstractItemModel::rowsInserted, m_table, [this] {
        if (!m_table->isSortingEnabled() || m_table->horizontalHeader()->sortIndicatorSection() < 0)
            m_table->scrollToBottom();
    });
}

int EventLogView::visibleRows() const
{
    return m_filter->rowCount();
}

void EventLogView::setFilter(const QString &text)
{
    m_filter->setFilterFixedString(text);
}

} // namespace jumo
