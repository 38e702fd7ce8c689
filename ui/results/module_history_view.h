#pragma once
// The Modules tab's lower half (issue 38): every attempt of the serial number selected above,
// oldest first, as a tree (attempt, its steps, each step's measurements with value, unit,
// limits, marginal band and outcome), and the attempts' files (the PDF report, the evidence
// recording) with their SHA-256; Open (or a double click) asks the window to open the file
// chosen, the report of the selected attempt to begin with. The tree's columns show a line of
// each text; the Details pane beside it holds the current row's whole text, wrapped (a step's
// detail, a measurement's value and limits, an attempt's plan and station), in a splitter that
// gives it more room when dragged.
#include "core/results/result_record.h"

#include <QWidget>

#include <vector>

QT_BEGIN_NAMESPACE
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSplitter;
class QTreeWidget;
class QTreeWidgetItem;
QT_END_NAMESPACE

namespace imudesk::ui {

class ElidedLabel;

class ModuleHistoryView : public QWidget {
    Q_OBJECT

public:
    enum Column { NameColumn, ValueColumn, UnitColumn, LimitsColumn, MarginalColumn, OutcomeColumn, ColumnCount };

    explicit ModuleHistoryView(QWidget *parent = nullptr);

    // The attempts of serial (history()); the attempt with selectedUuid is made current.
    void showHistory(const QString &serial, std::vector<results::ModuleRecord> attempts, const QString &selectedUuid);
    // No history, and why (nothing selected, being read, an error).
    void showMessage(const QString &text);
    QString serial() const { return m_serial; }
    const std::vector<results::ModuleRecord> &attempts() const { return m_attempts; }
    QTreeWidget *tree() const { return m_tree; }
    QTreeWidget *files() const { return m_files; }
    QSplitter *splitter() const { return m_split; }
    QPlainTextEdit *details() const { return m_details; }
    // What the Open button does: asks for the chosen file (openRequested); false without one.
    bool openSelected();

Q_SIGNALS:
    void openRequested(const QString &location);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void updateTitle();
    void fillTree(const QString &selectedUuid);
    void fillFiles(const QString &selectedUuid);
    static void setOutcome(QTreeWidgetItem *item, results::Outcome o, bool marginal);
    void showDetails(const QTreeWidgetItem *item);

    QString m_serial;
    std::vector<results::ModuleRecord> m_attempts;
    QString m_message;
    ElidedLabel *m_title = nullptr;
    QSplitter *m_split = nullptr;
    QTreeWidget *m_tree = nullptr;
    QLabel *m_detailsTitle = nullptr;
    QPlainTextEdit *m_details = nullptr;
    QSplitter *m_side = nullptr;
    QLabel *m_filesTitle = nullptr;
    QTreeWidget *m_files = nullptr;
    QPushButton *m_open = nullptr;
};

} // namespace imudesk::ui
