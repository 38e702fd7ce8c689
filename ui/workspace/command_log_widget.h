#pragma once
// The commands the GUI sent (models::CommandLogModel) in a table: status in colour
// (OK green, ERR / timeout red), newest at the bottom (followed while the view is at
// the bottom). Copy copies the selected rows, Copy all every row, tab-separated with a
// header line; Ctrl+C copies the selection too. The workspace calls record() when it
// sends a command and complete() when the session reports the outcome.
#include "device/text_reply.h"

#include <QWidget>

class QTableView;
class QToolButton;

namespace imudesk::models {
class CommandLogModel;
}

namespace imudesk::ui {

class CommandLogWidget : public QWidget {
    Q_OBJECT
public:
    explicit CommandLogWidget(QWidget *parent = nullptr);

    void record(quint64 id, const QString &text);
    // False when `id` was not recorded here (a command someone else sent).
    bool complete(quint64 id, const device::TextReply &reply);

    models::CommandLogModel *model() const { return m_model; }
    QTableView *view() const { return m_view; }

    // The selected rows (whole rows, however they were selected), and every row, as the
    // clipboard gets them.
    QString selectedText() const;
    QString allText() const;
    void copySelected() const;
    void copyAll() const;
    void clear();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void updateActions();

    models::CommandLogModel *m_model = nullptr;
    QTableView *m_view = nullptr;
    QToolButton *m_copyButton = nullptr;
    QToolButton *m_copyAllButton = nullptr;
    QToolButton *m_clearButton = nullptr;
};

} // namespace imudesk::ui
