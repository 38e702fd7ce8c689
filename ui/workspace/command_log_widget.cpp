#include "workspace/command_log_widget.h"

#include "itemmodels/command_log_model.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QScrollBar>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

namespace imudesk::ui {

using models::CommandLogModel;
using Status = device::TextReply::Status;

namespace {

// Status in colour: the model has none (QtCore only).
class StatusDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;

protected:
    void initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const override
    {
        QStyledItemDelegate::initStyleOption(option, index);
        if (index.column() != CommandLogModel::StatusColumn)
            return;
        QColor color;
        switch (Status(index.data(CommandLogModel::StatusRole).toInt())) {
        case Status::Ok: color = QColor(0x2E, 0x7D, 0x32); break;
        case Status::Pending: color = QColor(0x75, 0x75, 0x75); break;
        case Status::Refused:
        case Status::Invalid:
        case Status::Timeout:
        case Status::Cancelled:
        case Status::NotSent: color = QColor(0xC6, 0x28, 0x28); break;
        }
        option->palette.setColor(QPalette::Text, color);
        option->palette.setColor(QPalette::HighlightedText, color.lighter(180));
        option->font.setBold(true);
    }
};

} // namespace

CommandLogWidget::CommandLogWidget(QWidget *parent) : QWidget(parent)
{
    m_model = new CommandLogModel(this);
    m_view = new QTableView(this);
    m_view->setObjectName(QStringLiteral("commandLogView"));
    m_view->setModel(m_model);
    m_view->setItemDelegate(new StatusDelegate(m_view));
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setWordWrap(false);
    m_view->setAlternatingRowColors(true);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 6);
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->horizontalHeader()->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_view->setColumnWidth(CommandLogModel::TimeColumn, m_view->fontMetrics().horizontalAdvance(QStringLiteral("00:00:00.000  ")));
    m_view->setColumnWidth(CommandLogModel::CommandColumn, m_view->fontMetrics().horizontalAdvance(QLatin1Char('M')) * 22);
    m_view->setColumnWidth(CommandLogModel::StatusColumn, m_view->fontMetrics().horizontalAdvance(QLatin1Char('M')) * 7);

    auto *copyShortcut = new QAction(m_view);
    copyShortcut->setShortcut(QKeySequence::Copy);
    copyShortcut->setShortcutContext(Qt::WidgetShortcut);
    m_view->addAction(copyShortcut);
    connect(copyShortcut, &QAction::triggered, this, &CommandLogWidget::copySelected);

    m_copyButton = new QToolButton(this);
    m_copyButton->setObjectName(QStringLiteral("commandLogCopy"));
    m_copyAllButton = new QToolButton(this);
    m_copyAllButton->setObjectName(QStringLiteral("commandLogCopyAll"));
    m_clearButton = new QToolButton(this);
    m_clearButton->setObjectName(QStringLiteral("commandLogClear"));
    auto *bar = new QHBoxLayout;
    bar->addWidget(m_copyButton);
    bar->addWidget(m_copyAllButton);
    bar->addWidget(m_clearButton);
    bar->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(bar);
    layout->addWidget(m_view, 1);

    connect(m_copyButton, &QToolButton::clicked, this, &CommandLogWidget::copySelected);
    connect(m_copyAllButton, &QToolButton::clicked, this, &CommandLogWidget::copyAll);
    connect(m_clearButton, &QToolButton::clicked, this, &CommandLogWidget::clear);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this, &CommandLogWidget::updateActions);
    connect(m_model, &QAbstractItemModel::rowsInserted, this, &CommandLogWidget::updateActions);
    connect(m_model, &QAbstractItemModel::modelReset, this, &CommandLogWidget::updateActions);
    retranslateUi();
    updateActions();
}

void CommandLogWidget::record(quint64 id, const QString &text)
{
    QScrollBar *scroll = m_view->verticalScrollBar();
    const bool atEnd = scroll->value() >= scroll->maximum();
    m_model->record(id, text);
    if (atEnd)
        m_view->scrollToBottom();
}

bool CommandLogWidget::complete(quint64 id, const device::TextReply &reply)
{
    return m_model->complete(id, reply);
}

QString CommandLogWidget::selectedText() const
{
    QList<int> rows;
    const auto selected = m_view->selectionModel()->selectedIndexes();
    for (const QModelIndex &index : selected)
        rows << index.row();
    return m_model->rowsAsText(rows, true);
}

QString CommandLogWidget::allText() const
{
    return m_model->allAsText(true);
}

void CommandLogWidget::copySelected() const
{
    const QString text = selectedText();
    if (!text.isEmpty())
        QGuiApplication::clipboard()->setText(text);
}

void CommandLogWidget::copyAll() const
{
    const QString text = allText();
    if (!text.isEmpty())
        QGuiApplication::clipboard()->setText(text);
}

void CommandLogWidget::clear()
{
    m_model->clear();
}

void CommandLogWidget::updateActions()
{
    m_copyButton->setEnabled(m_view->selectionModel()->hasSelection());
    m_copyAllButton->setEnabled(m_model->rowCount() > 0);
    m_clearButton->setEnabled(m_model->rowCount() > 0);
}

void CommandLogWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void CommandLogWidget::retranslateUi()
{
    m_copyButton->setText(tr("Copy"));
    m_copyButton->setToolTip(tr("Copy the selected commands as tab-separated text"));
    m_copyAllButton->setText(tr("Copy all"));
    m_copyAllButton->setToolTip(tr("Copy every command as tab-separated text"));
    m_clearButton->setText(tr("Clear"));
    m_clearButton->setToolTip(tr("Remove every command from the list"));
    m_model->retranslate();
}

} // namespace imudesk::ui
