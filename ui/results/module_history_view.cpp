#include "ui/results/module_history_view.h"

#include "ui/results/module_table_model.h"
#include "ui/results/results_format.h"
#include "ui/common/elided_label.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSplitter>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace imudesk::ui {

using results::ModuleRecord;
using results::Outcome;

namespace {
constexpr int kUuidRole = Qt::UserRole + 1;     // an attempt's module UUID (every item of it)
constexpr int kLocationRole = Qt::UserRole + 2; // a file's path
constexpr int kDetailsRole = Qt::UserRole + 3;  // a row's whole text, for the Details pane
} // namespace

ModuleHistoryView::ModuleHistoryView(QWidget *parent) : QWidget(parent)
{
    m_title = new ElidedLabel(1, this);
    m_title->setObjectName(QStringLiteral("historyTitle"));
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);

    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("historyTree"));
    m_tree->setColumnCount(ColumnCount);
    m_tree->setUniformRowHeights(true);
    m_tree->setTextElideMode(Qt::ElideRight);
    m_tree->header()->setStretchLastSection(false);
    m_tree->header()->setSectionResizeMode(QHeaderView::Interactive);
    m_tree->header()->setSectionResizeMode(NameColumn, QHeaderView::Stretch);
    // The numbers' columns as wide as their header or a value like "-0.0123456 … 0.0123456".
    const int wide = fontMetrics().horizontalAdvance(QStringLiteral("-0.012345 … 0.012345")) + 16;
    m_tree->setColumnWidth(ValueColumn, wide * 2 / 3);
    m_tree->setColumnWidth(UnitColumn, wide / 3);
    m_tree->setColumnWidth(LimitsColumn, wide);
    m_tree->setColumnWidth(MarginalColumn, wide);
    m_tree->setColumnWidth(OutcomeColumn, fontMetrics().horizontalAdvance(ResultsFormat::outcome(Outcome::Pass, true)) + 24);

    m_filesTitle = new QLabel(this);
    m_files = new QTreeWidget(this);
    m_files->setObjectName(QStringLiteral("historyFiles"));
    m_files->setColumnCount(3);
    m_files->setRootIsDecorated(false);
    m_files->setUniformRowHeights(true);
    m_files->setTextElideMode(Qt::ElideMiddle); // a path's end (the file's name) stays in view
    m_files->header()->setStretchLastSection(true);
    m_filesTitle->setBuddy(m_files);
    m_open = new QPushButton(this);
    m_open->setObjectName(QStringLiteral("openArtifact"));
    m_open->setEnabled(false);
    connect(m_open, &QPushButton::clicked, this, [this] { openSelected(); });
    connect(m_files, &QTreeWidget::itemDoubleClicked, this, [this] { openSelected(); });
    connect(m_files, &QTreeWidget::currentItemChanged, this,
            [this](QTreeWidgetItem *current) { m_open->setEnabled(current != nullptr); });

    // The current row's whole text: wrapped, selectable, never cut (issue 53 point 17f).
    m_detailsTitle = new QLabel(this);
    m_details = new QPlainTextEdit(this);
    m_details->setObjectName(QStringLiteral("historyDetails"));
    m_details->setReadOnly(true);
    m_details->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    m_details->setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    m_details->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_detailsTitle->setBuddy(m_details);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem *current) { showDetails(current); });
    auto *detailsPanel = new QWidget(this);
    auto *detailsLayout = new QVBoxLayout(detailsPanel);
    detailsLayout->setContentsMargins(0, 0, 0, 0);
    detailsLayout->addWidget(m_detailsTitle);
    detailsLayout->addWidget(m_details, 1);

    auto *filesPanel = new QWidget(this);
    auto *filesLayout = new QVBoxLayout(filesPanel);
    filesLayout->setContentsMargins(0, 0, 0, 0);
    filesLayout->addWidget(m_filesTitle);
    filesLayout->addWidget(m_files, 1);
    auto *openRow = new QHBoxLayout;
    openRow->addStretch(1);
    openRow->addWidget(m_open);
    filesLayout->addLayout(openRow);

    m_split = new QSplitter(Qt::Horizontal, this);
    m_split->setObjectName(QStringLiteral("historySplitter"));
    m_split->setChildrenCollapsible(false);
    m_side = new QSplitter(Qt::Vertical, this);
    m_side->setObjectName(QStringLiteral("historySideSplitter"));
    m_side->setChildrenCollapsible(false);
    m_side->addWidget(detailsPanel);
    m_side->addWidget(filesPanel);
    m_side->setStretchFactor(0, 1);
    m_side->setStretchFactor(1, 1);
    m_split->addWidget(m_tree);
    m_split->addWidget(m_side);
    m_split->setStretchFactor(0, 2);
    m_split->setStretchFactor(1, 1);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_title);
    layout->addWidget(m_split, 1);
    retranslateUi();
}

void ModuleHistoryView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_tree)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ModuleHistoryView::retranslateUi()
{
    m_tree->setHeaderLabels({tr("Attempt, step, measurement"), tr("Value"), tr("Unit"), tr("Limits"),
                             tr("Marginal band"), tr("Outcome")});
    m_tree->headerItem()->setToolTip(MarginalColumn, tr("A pass whose value lies beyond this band, but inside its limits, "
                                                  "is marked marginal"));
    m_files->setHeaderLabels({tr("Attempt"), tr("Kind"), tr("File")});
    m_filesTitle->setText(tr("Files:"));
    m_detailsTitle->setText(tr("Details:"));
    m_details->setPlaceholderText(tr("Select an attempt, a step or a measurement to read all of it here."));
    m_open->setText(tr("Open"));
    m_open->setToolTip(tr("Open the chosen file (the PDF report, the evidence recording) in the desktop's "
                          "application for it"));
    // The tree's words (outcomes, "Attempt 2") are in the language of the moment.
    const QTreeWidgetItem *current = m_tree->currentItem();
    const QString selected = current ? current->data(0, kUuidRole).toString() : QString();
    fillTree(selected);
    fillFiles(selected);
    updateTitle();
}

void ModuleHistoryView::updateTitle()
{
    if (m_attempts.empty()) {
        m_title->setFullText(m_message.isEmpty() ? tr("Select a module above to see every attempt of its serial number.")
                                                 : m_message);
        return;
    }
    m_title->setFullText(tr("History of %1: %n attempt(s)", nullptr, int(m_attempts.size())).arg(m_serial));
}

void ModuleHistoryView::showMessage(const QString &text)
{
    m_serial.clear();
    m_attempts.clear();
    m_message = text;
    fillTree({});
    fillFiles({});
    updateTitle();
}

void ModuleHistoryView::showHistory(const QString &serial, std::vector<ModuleRecord> attempts, const QString &selectedUuid)
{
    m_serial = serial;
    m_attempts = std::move(attempts);
    m_message.clear();
    fillTree(selectedUuid);
    fillFiles(selectedUuid);
    updateTitle();
}

void ModuleHistoryView::setOutcome(QTreeWidgetItem *item, Outcome o, bool marginal)
{
    item->setText(OutcomeColumn, ResultsFormat::outcome(o, marginal));
    item->setForeground(OutcomeColumn, ResultsFormat::outcomeColour(o, marginal));
}

void ModuleHistoryView::fillTree(const QString &selectedUuid)
{
    m_tree->clear();
    QTreeWidgetItem *current = nullptr;
    for (const ModuleRecord &m : m_attempts) {
        auto *attempt = new QTreeWidgetItem(m_tree);
        attempt->setData(0, kUuidRole, m.uuid);
        attempt->setText(NameColumn, tr("Attempt %1 · %2").arg(m.attempt).arg(ResultsFormat::time(m.started)));
        QFont bold = attempt->font(NameColumn);
        bold.setBold(true);
        attempt->setFont(NameColumn, bold);
        attempt->setFont(OutcomeColumn, bold);
        setOutcome(attempt, m.outcome, m.marginal);
        const QString about = tr("Plan: %1\nStation: %2 · slot %3 · operator %4\nProduct: %5 · firmware %6\n"
                                 "Finished: %7\nRecord: %8")
                                  .arg(m.run.planName, m.run.stationId, m.slot, m.run.operatorName, m.product,
                                       ModuleTableModel::firmwareText(m), ResultsFormat::time(m.finished), m.uuid);
        attempt->setToolTip(NameColumn, ResultsFormat::toolTip(about));
        attempt->setData(0, kDetailsRole, attempt->text(NameColumn) + QStringLiteral(" · ")
                                              + attempt->text(OutcomeColumn) + QLatin1Char('\n') + about);
        if (m.uuid == selectedUuid)
            current = attempt;
        for (const results::StepRecord &s : m.steps) {
            auto *step = new QTreeWidgetItem(attempt);
            step->setData(0, kUuidRole, m.uuid);
            step->setText(NameColumn, ResultsFormat::shortText(s.name));
            step->setToolTip(NameColumn, ResultsFormat::toolTip(s.detail.isEmpty() ? s.name : s.name + QLatin1Char('\n') + s.detail));
            if (s.skipped)
                step->setText(OutcomeColumn, tr("skipped"));
            else
                setOutcome(step, s.outcome, false);
            if (!s.detail.isEmpty()) {
                step->setText(ValueColumn, ResultsFormat::shortText(s.detail));
                step->setToolTip(ValueColumn, ResultsFormat::toolTip(s.detail));
            }
            step->setData(0, kDetailsRole, s.name + QStringLiteral(" · ") + step->text(OutcomeColumn)
                                               + (s.detail.isEmpty() ? QString() : QLatin1Char('\n') + s.detail));
            for (const results::MeasurementRecord &v : m.measurements) {
                if (v.step != s.index)
                    continue;
                auto *item = new QTreeWidgetItem(step);
                item->setData(0, kUuidRole, m.uuid);
                item->setText(NameColumn, ResultsFormat::shortText(v.name));
                item->setToolTip(NameColumn, ResultsFormat::toolTip(v.name));
                item->setText(ValueColumn, ResultsFormat::number(v.value));
                item->setTextAlignment(ValueColumn, Qt::AlignRight | Qt::AlignVCenter);
                item->setText(UnitColumn, v.unit);
                const bool info = v.comparator == QLatin1String("INFO");
                item->setText(LimitsColumn, info ? tr("for information") : ResultsFormat::range(v.low, v.high));
                if (v.comparator == QLatin1String("ABS_LE"))
                    item->setToolTip(LimitsColumn, tr("The value's magnitude is compared with the limit"));
                item->setText(MarginalColumn, ResultsFormat::range(v.marginalLow, v.marginalHigh));
                if (!info)
                    setOutcome(item, v.outcome, v.marginal);
                QString text = tr("%1 = %2 %3").arg(v.name, item->text(ValueColumn), v.unit).trimmed();
                text += QLatin1Char('\n') + tr("Limits: %1").arg(item->text(LimitsColumn));
                if (!item->text(MarginalColumn).isEmpty())
                    text += QLatin1Char('\n') + tr("Marginal band: %1").arg(item->text(MarginalColumn));
                if (!info)
                    text += QLatin1Char('\n') + item->text(OutcomeColumn);
                item->setData(0, kDetailsRole, text);
            }
        }
        attempt->setExpanded(true);
        for (int i = 0; i < attempt->childCount(); ++i)
            attempt->child(i)->setExpanded(attempt->child(i)->childCount() > 0);
    }
    if (!current && m_tree->topLevelItemCount() > 0)
        current = m_tree->topLevelItem(m_tree->topLevelItemCount() - 1); // the latest attempt
    if (current) {
        m_tree->setCurrentItem(current);
        m_tree->scrollToItem(current, QAbstractItemView::PositionAtTop);
    }
}

void ModuleHistoryView::showDetails(const QTreeWidgetItem *item)
{
    m_details->setPlainText(item ? item->data(0, kDetailsRole).toString() : QString());
}

void ModuleHistoryView::fillFiles(const QString &selectedUuid)
{
    m_files->clear();
    QTreeWidgetItem *preferred = nullptr;
    for (const ModuleRecord &m : m_attempts)
        for (const results::ArtifactRecord &a : m.artifacts) {
            auto *item = new QTreeWidgetItem(m_files);
            item->setText(0, QString::number(m.attempt));
            item->setText(1, a.kind == QLatin1String("report") ? tr("PDF report")
                              : a.kind == QLatin1String("recording") ? tr("Recording")
                                                                      : a.kind);
            item->setText(2, ResultsFormat::shortText(a.location));
            item->setToolTip(2, ResultsFormat::toolTip(tr("%1\nSHA-256: %2").arg(a.location, a.sha256)));
            item->setData(0, kLocationRole, a.location);
            item->setData(0, kUuidRole, m.uuid);
            // The selected attempt's report, else the latest attempt's.
            if (a.kind == QLatin1String("report") && (m.uuid == selectedUuid || !preferred
                                                      || preferred->data(0, kUuidRole).toString() != selectedUuid))
                preferred = item;
        }
    m_files->resizeColumnToContents(0);
    m_files->resizeColumnToContents(1);
    if (!preferred && m_files->topLevelItemCount() > 0)
        preferred = m_files->topLevelItem(0);
    m_files->setCurrentItem(preferred);
    m_open->setEnabled(preferred != nullptr);
}

bool ModuleHistoryView::openSelected()
{
    const QTreeWidgetItem *item = m_files->currentItem();
    if (!item)
        return false;
    Q_EMIT openRequested(item->data(0, kLocationRole).toString());
    return true;
}

} // namespace imudesk::ui
