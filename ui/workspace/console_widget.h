#pragma once
// ASCII command console: a line to type a command (Enter sends, Up/Down walk the
// history, the documented commands complete as you type) above a read-only log of
// "> command", the reply lines and the outcome (OK, or ERR / timeout in red with the
// reason). It does not talk to the device; the main window forwards commandSubmitted()
// and feeds the replies back.
#include "device/text_reply.h"

#include <QHash>
#include <QStringList>
#include <QWidget>

class QCompleter;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QStringListModel;

namespace imudesk::ui {

class ConsoleWidget : public QWidget {
    Q_OBJECT
public:
    static constexpr int kMaxLogLines = 5000;
    static constexpr int kMaxHistory = 200;

    explicit ConsoleWidget(QWidget *parent = nullptr);

    // The commands the input line completes (case-insensitive prefix): the link's documented
    // ones (DeviceLink::textCommands).
    void setCompletions(const QStringList &commands);
    QCompleter *completer() const { return m_completer; }

    // Logs "> text" for a command the session accepted under `id`.
    void showCommand(quint64 id, const QString &text);
    // Logs the reply lines and the outcome of command `id`.
    void showReply(quint64 id, const device::TextReply &reply);
    // Lines the device sent that answer no command.
    void showText(const QString &line);
    // A problem that is not a reply (e.g. the port failed).
    void showError(const QString &message);
    void setInputEnabled(bool enabled);

    // Types `text` and presses Enter, as the user would.
    void submit(const QString &text);
    QString logText() const;
    const QStringList &history() const { return m_history; }
    QLineEdit *input() const { return m_input; }

Q_SIGNALS:
    void commandSubmitted(const QString &text);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void onReturnPressed();
    void stepHistory(int delta);
    void appendLine(const QString &text, const QString &color = QString(), bool bold = false);

    QPlainTextEdit *m_log = nullptr;
    QLineEdit *m_input = nullptr;
    QPushButton *m_sendButton = nullptr;
    QPushButton *m_clearButton = nullptr;
    QCompleter *m_completer = nullptr;
    QStringListModel *m_completions = nullptr;
    QStringList m_history;
    int m_historyPos = 0;   // == m_history.size() when editing a new line
    QString m_draft;        // the unfinished line kept while browsing the history
    QHash<quint64, QString> m_pending; // id -> command text
    quint64 m_lastShownId = 0;
};

} // namespace imudesk::ui
