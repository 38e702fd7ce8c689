#include "ui/results/yield_view.h"

#include "ui/results/results_format.h"
#include "ui/common/elided_label.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace imudesk::ui {

using Counts = results::ResultsStore::Counts;

YieldView::YieldView(QWidget *parent) : QWidget(parent)
{
    m_title = new ElidedLabel(1, this);
    m_title->setObjectName(QStringLiteral("yieldTitle"));
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setObjectName(QStringLiteral("yieldTable"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->setWordWrap(false);
    m_table->setTextElideMode(Qt::ElideRight);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_table->horizontalHeader()->setSectionResizeMode(GroupColumn, QHeaderView::Stretch);
    m_note = new QLabel(this);
    m_note->setObjectName(QStringLiteral("yieldNote"));
    m_note->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_note);
    retranslateUi();
}

void YieldView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_table)
        retranslateUi();
    QWidget::changeEvent(event);
}

void YieldView::retranslateUi()
{
    m_table->setHorizontalHeaderLabels({tr("Modules"), tr("Pass"), tr("Fail"), tr("Marginal"), tr("Error"),
                                        tr("Aborted"), tr("Yield")});
    m_table->horizontalHeaderItem(MarginalColumn)
        ->setToolTip(tr("Passed, with a value beyond its marginal band (counted among the passes too)"));
    m_table->horizontalHeaderItem(YieldColumn)->setToolTip(tr("Pass / (pass + fail)"));
    m_note->setText(tr("ERROR (the equipment failed: a port went away, a module did not answer) and ABORTED (the "
                       "operator cancelled) are not counted in the yield: yield = pass / (pass + fail)."));
    fill();
}

void YieldView::showMessage(const QString &text)
{
    m_message = text;
    m_yield.reset();
    fill();
}

void YieldView::showYield(const QString &plan, const QDateTime &since, const results::ResultsStore::Yield &yield)
{
    m_plan = plan;
    m_since = since;
    m_yield = yield;
    m_message.clear();
    fill();
}

QString YieldView::yieldText(const Counts &c)
{
    const double y = c.yield();
    return std::isnan(y) ? QStringLiteral("–") : QStringLiteral("%1 %").arg(QLocale().toString(100.0 * y, 'f', 1));
}

void YieldView::fill()
{
    m_table->setRowCount(0);
    if (!m_yield) {
        m_title->setFullText(m_message);
        return;
    }
    m_title->setFullText(m_since.isValid() ? tr("Plan %1, since %2").arg(m_plan, QLocale().toString(m_since.toLocalTime().date(), QLocale::ShortFormat))
                                           : tr("Plan %1, every module").arg(m_plan));
    const auto addRow = [this](const QString &group, const Counts &c, bool total) {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        auto *name = new QTableWidgetItem(ResultsFormat::shortText(group));
        name->setToolTip(ResultsFormat::toolTip(group));
        m_table->setItem(row, GroupColumn, name);
        const int counts[] = {c.pass, c.fail, c.marginal, c.error, c.aborted};
        for (int i = 0; i < 5; ++i) {
            auto *item = new QTableWidgetItem(QString::number(counts[i]));
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(row, PassColumn + i, item);
        }
        auto *yield = new QTableWidgetItem(yieldText(c));
        yield->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_table->setItem(row, YieldColumn, yield);
        if (total)
            for (int col = 0; col < ColumnCount; ++col) {
                QFont bold = m_table->item(row, col)->font();
                bold.setBold(true);
                m_table->item(row, col)->setFont(bold);
            }
    };
    addRow(tr("All modules"), m_yield->total, true);
    for (const auto &[firmware, c] : m_yield->byFirmware)
        addRow(tr("Firmware %1").arg(firmware.isEmpty() ? tr("(unknown)") : firmware), c, false);
    for (const auto &[slot, c] : m_yield->bySlot)
        addRow(tr("Slot %1").arg(slot.isEmpty() ? tr("(unknown)") : slot), c, false);
    for (int col = PassColumn; col < ColumnCount; ++col)
        m_table->resizeColumnToContents(col);
}

} // namespace imudesk::ui
