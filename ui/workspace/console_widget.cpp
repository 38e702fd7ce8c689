#include "workspace/console_widget.h"

#include "protocol/hipnuc/ascii_command.h"

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

namespace hp = protocol::hipnuc;

namespace {
const QString kOkColor = QStringLiteral("#2e7d32");
const QString kErrorColor = QStringLiteral("#c62828");
const QString kQuietColor = QStringLiteral("#757575");
} // namespace

QStringList ConsoleWidget::documentedCommands()
{
    namespace c = hp::commands;
    using hp::Message;
    using model::ManualEdition;
    std::vector<hp::Command> all = {
        // Queries
        c::logVersion(), c::logComConfig(), c::logMagConfig(), c::logMagCalStatus(),
        // Output
        c::logEnable(), c::logDisable(),
        c::logOnTime(Message::HI91, 0.01), c::logOnTime(Message::HI91, 0.005), c::logOnTime(Message::HI91, 0.001),
        c::logOnTime(Message::HI91, 0),
        c::logOnTime(Message::HI92, 0.01), c::logOnTime(Message::HI92, 0),
        c::logOnTime(Message::HI81, 0.01), c::logOnTime(Message::HI81, 0),
        c::logOnTime(Message::HI83, 0.01), c::logOnTime(Message::HI83, 0),
        c::logOnTime(Message::GGA, 1), c::logOnTime(Message::RMC, 1), c::logOnTime(Message::SXT, 1),
        c::logOnMark(Message::HI91, false), c::logOnMark(Message::HI91, true),
        c::logOnMark(Message::HI83, false), c::logOnMark(Message::HI83, true),
        c::logHi83Map(0x000000FF),
        // Configuration
        c::attMode(0), c::attMode(1), c::attMode(4),
        c::attReset(1), c::attReset(2), c::attReset(3), c::attReset(5),
        c::imuUrfrMatrix(model::Mounting::identity()),
        c::imuCoord(0), c::imuCoord(4),
        c::pmux(1, 1), c::pmux(2, 2), c::pmux(3, 5), c::pmux(5, 9, true), c::pmux2Div(1),
        c::magCalStart(), c::gyroCalStart(720), c::gyroCalStop(),
        c::setYaw(0, 0), c::setYaw(1, 0),
        c::enableBackgroundMagCal(true), c::enableBackgroundMagCal(false),
        // Port and system
        c::serialConfig(1, 115200),
        c::saveConfig(), c::reboot(), c::rebootBootloader(), c::factoryReset(),
    };
    for (int code : model::Mounting::validCodes())
        all.push_back(c::imuUrfr(code));
    for (int baud : {4800, 9600, 19200, 38400, 57600, 115200, 230400, 256000, 460800, 921600})
        all.push_back(c::serialConfig(baud, ManualEdition::V171));
    QStringList out;
    for (const hp::Command &command : all)
        if (command.ok() && !out.contains(QString::fromStdString(command.text)))
            out << QString::fromStdString(command.text);
    return out;
}

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

    m_completer = new QCompleter(new QStringListModel(documentedCommands(), this), this);
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

void ConsoleWidget::showReply(quint64 id, const hp::AsciiReply &reply)
{
    const QString command = m_pending.take(id);
    // Another command was logged since this one: say which command this reply answers.
    if (id != m_lastShownId) {
        const QString what = command.isEmpty() ? QString::fromStdString(reply.command) : command;
        appendLine(tr("(reply to: %1)").arg(what), kQuietColor);
    }
    m_lastShownId = id;
    for (const auto &line : reply.lines)
        appendLine(QStringLiteral("  ") + QString::fromStdString(line));
    const QString why = QString::fromStdString(reply.errorLine);
    switch (reply.status) {
    case hp::AsciiReply::Status::Ok: appendLine(tr("OK"), kOkColor, true); break;
    case hp::AsciiReply::Status::Error: appendLine(tr("ERR: %1").arg(why), kErrorColor, true); break;
    case hp::AsciiReply::Status::Timeout: appendLine(tr("Timeout: %1").arg(why), kErrorColor, true); break;
    case hp::AsciiReply::Status::Cancelled: appendLine(tr("Cancelled: %1").arg(why), kErrorColor, true); break;
    case hp::AsciiReply::Status::NotSent: appendLine(tr("Not sent: %1").arg(why), kErrorColor, true); break;
    case hp::AsciiReply::Status::Pending: break;
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
