#include "eventlogview.h"

#include "logs/eventlog.h"
#include "models/eventlogmodel.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPersistentModelIndex>
#include <QPushButton>
#include <QScrollBar>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

namespace jumo {

namespace {

constexpr int typingPauseMs = 300;

} // namespace

EventLogView::EventLogView(EventLog *log, const QStringList &columns, const QStringList &titles, QWidget *parent)
    : QWidget(parent), m_model(new EventLogModel(log, columns, titles, this)), m_table(new QTableView(this)),
      m_filterEdit(new QLineEdit(this)), m_typing(new QTimer(this)), m_state(new QLabel(this)),
      m_exportButton(new QPushButton(tr("Export CSV..."), this))
{
    m_table->setModel(m_model);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setVerticalScrollMode(QAbstractItemView::ScrollPerItem);
    m_table->setObjectName(QStringLiteral("logTable"));
    m_filterEdit->setObjectName(QStringLiteral("logFilter"));
    m_filterEdit->setPlaceholderText(tr("Filter: device, entry, kind, text..."));
    m_filterEdit->setClearButtonEnabled(true);
    m_state->setObjectName(QStringLiteral("logState"));
    m_exportButton->setObjectName(QStringLiteral("logExport"));
    // A search goes through the whole log: it starts when the typing pauses.
    m_typing->setSingleShot(true);
    m_typing->setInterval(typingPauseMs);
    connect(m_filterEdit, &QLineEdit::textChanged, m_typing, qOverload<>(&QTimer::start));
    connect(m_typing, &QTimer::timeout, this, [this] { m_model->setFilter(m_filterEdit->text()); });
    connect(m_exportButton, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export"), QString(), tr("CSV files (*.csv)"));
        if (path.isEmpty())
            return;
        m_exportButton->setEnabled(false);
        m_state->setText(tr("Exporting to %1...").arg(path));
        m_model->exportCsv(path);
    });
    connect(m_model, &EventLogModel::exportFinished, this, [this](bool ok, const QString &message) {
        m_exportButton->setEnabled(true);
        updateState();
        if (ok)
            m_state->setText(message);
        else
            QMessageBox::warning(this, tr("Export"), message);
    });
    connect(m_model, &EventLogModel::stateChanged, this, &EventLogView::updateState);
    connect(m_model, &QAbstractItemModel::rowsInserted, this, &EventLogView::updateState);
    connect(m_model, &QAbstractItemModel::modelReset, this, &EventLogView::updateState);

    // New records come on top; a user looking at older ones keeps them in view.
    auto anchor = std::make_shared<QPersistentModelIndex>();
    connect(m_model, &QAbstractItemModel::rowsAboutToBeInserted, this, [this, anchor](const QModelIndex &, int first) {
        *anchor = first == 0 && m_table->verticalScrollBar()->value() > 0 ? QPersistentModelIndex(m_table->indexAt(QPoint(0, 0)))
                                                                          : QPersistentModelIndex();
    });
    connect(m_model, &QAbstractItemModel::rowsInserted, this, [this, anchor] {
        if (!anchor->isValid())
            return;
        m_table->doItemsLayout();
        m_table->scrollTo(*anchor, QAbstractItemView::PositionAtTop);
        *anchor = QPersistentModelIndex();
    });

    auto *bar = new QHBoxLayout;
    bar->addWidget(m_filterEdit, 1);
    bar->addWidget(m_exportButton);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_table);
    auto *footer = new QHBoxLayout;
    footer->addWidget(m_state, 1);
    if (!log->path().isEmpty())
        footer->addWidget(new QLabel(tr("Kept in %1").arg(log->path()), this));
    layout->addLayout(footer);
    updateState();
}

int EventLogView::visibleRows() const
{
    return m_model->rowCount();
}

void EventLogView::setFilter(const QString &text)
{
    m_typing->stop();
    const QSignalBlocker quiet(m_filterEdit);
    m_filterEdit->setText(text);
    m_model->setFilter(text);
}

void EventLogView::updateState()
{
    const int rows = m_model->rowCount();
    QString text;
    if (!m_model->readError().isEmpty())
        text = m_model->readError();
    else if (m_model->filter().isEmpty())
        text = m_model->isComplete() ? tr("%n record(s)", nullptr, rows)
             : m_model->isLoading()  ? tr("%n record(s) shown, reading older ones...", nullptr, rows)
                                     : tr("the newest %n record(s); scroll down for older ones", nullptr, rows);
    else
        text = m_model->isComplete() ? tr("%n matching record(s)", nullptr, rows)
             : m_model->isLoading()  ? tr("%n matching record(s) so far, searching...", nullptr, rows)
                                     : tr("the newest %n matching record(s); scroll down for older ones", nullptr, rows);
    m_state->setText(text);
}

} // namespace jumo
