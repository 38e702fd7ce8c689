#pragma once
// The Yield tab (issue 38): for the plan chosen in the filter row (from its From date on), the
// modules that passed, failed, passed marginally, ended in ERROR or were ABORTED, and the yield,
// pass / (pass + fail): over all, per firmware as found, per fixture slot. ERROR and ABORTED
// are counted apart and left out of the yield (the equipment or the operator ended them, not the
// product), which a line under the table says.
#include "core/results/results_store.h"

#include <QWidget>

#include <optional>

QT_BEGIN_NAMESPACE
class QLabel;
class QTableWidget;
QT_END_NAMESPACE

namespace imudesk::ui {

class ElidedLabel;

class YieldView : public QWidget {
    Q_OBJECT

public:
    enum Column { GroupColumn, PassColumn, FailColumn, MarginalColumn, ErrorColumn, AbortedColumn, YieldColumn, ColumnCount };

    explicit YieldView(QWidget *parent = nullptr);

    void showYield(const QString &plan, const QDateTime &since, const results::ResultsStore::Yield &yield);
    // No table, and why (no plan chosen, being read).
    void showMessage(const QString &text);
    QTableWidget *table() const { return m_table; }
    // "92.3 %", or "–" when neither passed nor failed.
    static QString yieldText(const results::ResultsStore::Counts &c);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void fill();

    QString m_plan;
    QDateTime m_since;
    std::optional<results::ResultsStore::Yield> m_yield;
    QString m_message;
    ElidedLabel *m_title = nullptr;
    QTableWidget *m_table = nullptr;
    QLabel *m_note = nullptr;
};

} // namespace imudesk::ui
