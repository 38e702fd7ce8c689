#include "workspace/console_widget.h"


#include <QAbstractItemView>
#include <QCompleter>
#include <QEvent>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QStringListModel>
#include <QVBoxLayout>

#include <algorithm>

namespace imudesk::ui {


namespace {
const QString kOkColor = QStringLiteral("#2e7d32");
const QString kErrorColor = QStringLiteral("#c62828");
const QString kQuietColor = QStringLiteral("#757575");
} // namespace

ConsoleWidget::ConsoleWidget(QWidget *parent) : QWidget(parent)
{
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_log = new QPlainTextEdit(this);
    m_log->setObjectName(QStringLiteral("consoleLog"));
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(kMaxLogLines);
    m_log->setFont(mono);
    m_log->setUndoRedoEnabled(false);

    m_input = new QLineEdit(this);
    m_input->setObjectName(QStringLiteral("consoleInput"));
    m_input->setFont(mono);
    m_input->setClearButtonEnabled(true);
    m_input->installEventFilter(this);

    m_completions = new QStringListModel(this);
    m_completer = new QCompleter(m_completions, this);
    m_completer->setCaseSensitivity(Qt::CaseInsensitive);
    m_completer->setCompletionMode(QCompleter::PopupCompletion);
    m_completer->setFilterMode(Qt::MatchStartsWith);
    m_completer->setMaxVisibleItems(12);
    m_completer->popup()->setFont(mono);
    m_input->setCompleter(m_completer);

    m_sendButton = new QPushButton(this);
    m_clearButton = new QPushButton(this);

    auto *inputRow = new QHBoxLayout;
    inputRow->addWidget(m_input, 1);
    inputRow->addWidget(m_sendButton);
    inputRow->addWidget(m_clearButton);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_log, 1);
    layout->addLayout(inputRow);

    connect(m_input, &QLineEdit::returnPressed, this, &ConsoleWidget::onReturnPressed);
    connect(m_sendButton, &QPushButton::clicked, this, &ConsoleWidget::onReturnPressed);
    connect(m_clearButton, &QPushButton::clicked, m_log, &QPlainTextEdit::clear);
    retranslateUi();
}

void ConsoleWidget::showCommand(quint64 id, const QString &text)
{
    m_pending.insert(id, text);
    m_lastShownId = id;
    appendLine(QStringLiteral("> ") + text, QString(), true);
}

void ConsoleWidget::setCompletions(const QStringList &commands)
{
    m_completions->setStringList(commands);
}

void ConsoleWidget::showReply(quint64 id, const device::TextReply &reply)
{
    const QString command = m_pending.take(id);
    // Another command was logged since this one: say which command this reply answers.
    if (id != m_lastShownId) {
        const QString what = command.isEmpty() ? reply.command : command;
        appendLine(tr("(reply to: %1)").arg(what), kQuietColor);
    }
    m_lastShownId = id;
    for (const auto &line : reply.lines)
        appendLine(QStringLiteral("  ") + line);
    const QString &why = reply.why;
    switch (reply.status) {
    case device::TextReply::Status::Ok: appendLine(tr("OK"), kOkColor, true); break;
    case device::TextReply::Status::Refused: appendLine(tr("ERR: %1").arg(why), kErrorColor, true); break;
    case device::TextReply::Status::Invalid: appendLine(tr("Invalid reply: %1").arg(why), kErrorColor, true); break;
    case device::TextReply::Status::Timeout: appendLine(tr("Timeout: %1").arg(why), kErrorColor, true); break;
    case device::TextReply::Status::Cancelled: appendLine(tr("Cancelled: %1").arg(why), kErrorColor, true); break;
    case device::TextReply::Status::NotSent: appendLine(tr("Not sent: %1").arg(why), kErrorColor, true); break;
    case device::TextReply::Status::Pending: break;
    }
}

void ConsoleWidget::showText(const QString &line)
{
    appendLine(line, kQuietColor);
}

void ConsoleWidget::showError(const QString &message)
{
    appendLine(message, kErrorColor);
}

void ConsoleWidget::setInputEnabled(bool enabled)
{
    m_input->setEnabled(enabled);
    m_sendButton->setEnabled(enabled);
}

void ConsoleWidget::submit(const QString &text)
{
    m_input->setText(text);
    onReturnPressed();
}

QString ConsoleWidget::logText() const
{
    return m_log->toPlainText();
}

bool ConsoleWidget::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_input && event->type() == QEvent::KeyPress) {
        const auto *key = static_cast<QKeyEvent *>(event);
        if (key->modifiers() == Qt::NoModifier || key->modifiers() == Qt::KeypadModifier) {
            if (key->key() == Qt::Key_Up) {
                stepHistory(-1);
                return true;
            }
            if (key->key() == Qt::Key_Down) {
                stepHistory(+1);
                return true;
            }
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ConsoleWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ConsoleWidget::retranslateUi()
{
    m_input->setPlaceholderText(tr("Type an ASCII command, e.g. LOG VERSION, and press Enter"));
    m_input->setToolTip(tr("Enter sends the command; Up and Down recall earlier commands"));
    m_sendButton->setText(tr("Send"));
    m_clearButton->setText(tr("Clear log"));
}

void ConsoleWidget::onReturnPressed()
{
    const QString text = m_input->text().trimmed();
    if (text.isEmpty() || !m_input->isEnabled())
        return;
    if (m_history.isEmpty() || m_history.constLast() != text) {
        m_history.append(text);
        while (m_history.size() > kMaxHistory)
            m_history.removeFirst();
    }
    m_historyPos = int(m_history.size());
    m_draft.clear();
    m_input->clear();
    Q_EMIT commandSubmitted(text);
}

void ConsoleWidget::stepHistory(int delta)
{
    if (m_history.isEmpty())
        return;
    if (m_historyPos == m_history.size())
        m_draft = m_input->text();
    const int pos = std::clamp(m_historyPos + delta, 0, int(m_history.size()));
    if (pos == m_historyPos)
        return;
    m_historyPos = pos;
    m_input->setText(pos == m_history.size() ? m_draft : m_history.at(pos));
}

void ConsoleWidget::appendLine(const QString &text, const QString &color, bool bold)
{
    // Every line states its colour and weight so that nothing carries over from the line before.
    const QString html = QStringLiteral("<span style=\"white-space:pre-wrap; color:%1; font-weight:%2\">%3</span>")
                             .arg(color.isEmpty() ? palette().color(QPalette::Text).name() : color,
                                  bold ? QStringLiteral("bold") : QStringLiteral("normal"), text.toHtmlEscaped());
    m_log->appendHtml(html);
}

} // namespace imudesk::ui
