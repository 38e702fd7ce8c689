#include "workspace/raw_bytes_view.h"

#include <QApplication>
#include <QClipboard>
#include <QEvent>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextCursor>
#include <QToolButton>
#include <QVBoxLayout>

#include <cstdio>

namespace imudesk::ui {

using device::RawByteLog;

namespace {

// "    1.234 RX 000001A0  5A A5 4C 00 ...                    |Z.L.|"
void formatLine(QByteArray &out, double seconds, RawByteLog::Direction direction, uint64_t offset,
                const char *bytes, int count)
{
    char head[48];
    const int n = std::snprintf(head, sizeof head, "%9.3f %s %08llX  ", seconds,
                                direction == RawByteLog::Direction::Rx ? "RX" : "TX",
                                static_cast<unsigned long long>(offset));
    out.append(head, n);
    static const char digits[] = "0123456789ABCDEF";
    for (int i = 0; i < RawBytesView::kBytesPerLine; ++i) {
        if (i < count) {
            const auto b = static_cast<unsigned char>(bytes[i]);
            out.append(digits[b >> 4]);
            out.append(digits[b & 0xF]);
            out.append(' ');
        } else {
            out.append("   ", 3);
        }
    }
    out.append(" |", 2);
    for (int i = 0; i < count; ++i) {
        const auto b = static_cast<unsigned char>(bytes[i]);
        out.append(b >= 0x20 && b < 0x7F ? char(b) : '.');
    }
    out.append('|');
}

} // namespace

QColor RawBytesView::rxColor()
{
    return QColor(0x15, 0x65, 0xC0); // blue: from the device
}

QColor RawBytesView::txColor()
{
    return QColor(0xC6, 0x28, 0x28); // red: to the device
}

RawBytesView::RawBytesView(QWidget *parent) : QWidget(parent)
{
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_text = new QPlainTextEdit(this);
    m_text->setObjectName(QStringLiteral("rawBytesText"));
    m_text->setReadOnly(true);
    m_text->setUndoRedoEnabled(false);
    m_text->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_text->setFont(mono);
    m_text->setMaximumBlockCount(int(m_maxBytes / kBytesPerLine) + 64);
    m_text->document()->setDocumentMargin(2);

    m_rxFormat.setForeground(rxColor());
    m_txFormat.setForeground(txColor());
    m_noteFormat.setForeground(QColor(0x75, 0x75, 0x75));
    m_noteFormat.setFontItalic(true);

    m_pauseButton = new QToolButton(this);
    m_pauseButton->setObjectName(QStringLiteral("rawBytesPause"));
    m_pauseButton->setCheckable(true);
    m_clearButton = new QToolButton(this);
    m_clearButton->setObjectName(QStringLiteral("rawBytesClear"));
    m_copyButton = new QToolButton(this);
    m_copyButton->setObjectName(QStringLiteral("rawBytesCopy"));
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("rawBytesStatus"));

    auto *bar = new QHBoxLayout;
    bar->addWidget(m_pauseButton);
    bar->addWidget(m_clearButton);
    bar->addWidget(m_copyButton);
    bar->addStretch(1);
    bar->addWidget(m_status);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(bar);
    layout->addWidget(m_text, 1);

    connect(m_pauseButton, &QToolButton::toggled, this, &RawBytesView::setPaused);
    connect(m_clearButton, &QToolButton::clicked, this, &RawBytesView::clear);
    connect(m_copyButton, &QToolButton::clicked, this, &RawBytesView::copyToClipboard);
    retranslateUi();
}

void RawBytesView::setLog(const RawByteLog *log)
{
    m_log = log;
    m_nextSeq = 0; // what the log still holds is shown at the next refresh
    m_originNs = -1;
    m_offset[0] = m_offset[1] = 0;
    m_skippedBytes = 0;
    m_text->clear();
    m_empty = true;
    updateStatus();
}

void RawBytesView::setPaused(bool paused)
{
    m_paused = paused;
    if (m_pauseButton->isChecked() != paused)
        m_pauseButton->setChecked(paused);
    updateStatus();
}

void RawBytesView::setMaxBytes(size_t bytes)
{
    m_maxBytes = std::max<size_t>(bytes, kBytesPerLine);
    m_text->setMaximumBlockCount(int(m_maxBytes / kBytesPerLine) + 64);
}

void RawBytesView::clear()
{
    // Skip what is logged so far; the offsets still count it.
    if (m_log) {
        for (const auto &c : m_log->since(m_nextSeq))
            m_offset[c.direction == RawByteLog::Direction::Rx ? 0 : 1] += uint64_t(c.bytes.size());
        m_nextSeq = m_log->nextSeq();
    }
    m_text->clear();
    m_empty = true;
    updateStatus();
}

void RawBytesView::refresh()
{
    if (!m_log || m_paused)
        return;
    const std::vector<RawByteLog::Chunk> chunks = m_log->since(m_nextSeq);
    if (chunks.empty())
        return;
    // Chunks the log dropped before this view read them.
    const uint64_t evicted = chunks.front().seq > m_nextSeq ? chunks.front().seq - m_nextSeq : 0;
    m_nextSeq = chunks.back().seq + 1;
    appendChunks(chunks, evicted);
}

void RawBytesView::appendChunks(const std::vector<RawByteLog::Chunk> &chunks, uint64_t evictedChunks)
{
    // Only the newest maxBytes can stay in the view: skip the rest before formatting it.
    size_t first = chunks.size();
    size_t kept = 0;
    while (first > 0 && kept + size_t(chunks[first - 1].bytes.size()) <= m_maxBytes) {
        kept += size_t(chunks[first - 1].bytes.size());
        --first;
    }
    if (first == chunks.size())
        first = chunks.size() - 1; // the newest chunk alone is larger than the view: its tail
    uint64_t skipped = 0;
    for (size_t i = 0; i < first; ++i) {
        const auto &c = chunks[i];
        m_offset[c.direction == RawByteLog::Direction::Rx ? 0 : 1] += uint64_t(c.bytes.size());
        skipped += uint64_t(c.bytes.size());
    }
    const qsizetype tailDrop = std::max<qsizetype>(0, chunks[first].bytes.size() - qsizetype(m_maxBytes));
    skipped += uint64_t(tailDrop);
    if (m_originNs < 0)
        m_originNs = chunks.front().hostTimeNs;

    QScrollBar *scroll = m_text->verticalScrollBar();
    const bool atEnd = scroll->value() >= scroll->maximum() - 1;
    QTextCursor cursor(m_text->document());
    cursor.movePosition(QTextCursor::End);
    cursor.beginEditBlock();
    auto newLine = [&] {
        if (!m_empty)
            cursor.insertBlock();
        m_empty = false;
    };
    if (evictedChunks > 0 || skipped > 0) {
        m_skippedBytes += skipped;
        newLine();
        const QString note = evictedChunks > 0 && skipped == 0
                                 ? tr("… %n read(s) or write(s) not shown (the log dropped them before this view "
                                      "caught up) …",
                                      nullptr, int(evictedChunks))
                                 : tr("… %n byte(s) not shown (more arrived than the view holds) …", nullptr,
                                      int(std::min<uint64_t>(skipped, INT32_MAX)));
        cursor.insertText(note, m_noteFormat);
    }
    QByteArray lines;
    for (size_t i = first; i < chunks.size(); ++i) {
        const auto &c = chunks[i];
        const int dir = c.direction == RawByteLog::Direction::Rx ? 0 : 1;
        const char *data = c.bytes.constData();
        qsizetype size = c.bytes.size();
        if (i == first && tailDrop > 0) { // the tail of an oversized chunk
            m_offset[dir] += uint64_t(tailDrop);
            data += tailDrop;
            size -= tailDrop;
        }
        const double seconds = double(c.hostTimeNs - m_originNs) * 1e-9;
        lines.clear();
        lines.reserve(size / kBytesPerLine * 80 + 80);
        for (qsizetype at = 0; at < size; at += kBytesPerLine) {
            if (at > 0)
                lines.append('\n');
            const int count = int(std::min<qsizetype>(kBytesPerLine, size - at));
            formatLine(lines, seconds, c.direction, m_offset[dir], data + at, count);
            m_offset[dir] += uint64_t(count);
        }
        newLine();
        cursor.insertText(QString::fromLatin1(lines), dir == 0 ? m_rxFormat : m_txFormat);
    }
    cursor.endEditBlock();
    if (atEnd)
        scroll->setValue(scroll->maximum());
    updateStatus();
}

QString RawBytesView::text() const
{
    return m_text->toPlainText();
}

QString RawBytesView::copyText() const
{
    const QTextCursor selection = m_text->textCursor();
    if (!selection.hasSelection())
        return text();
    QString selected = selection.selectedText();
    selected.replace(QChar::ParagraphSeparator, QLatin1Char('\n'));
    return selected;
}

void RawBytesView::copyToClipboard() const
{
    if (QClipboard *clipboard = QGuiApplication::clipboard())
        clipboard->setText(copyText());
}

void RawBytesView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void RawBytesView::retranslateUi()
{
    m_pauseButton->setText(tr("Pause"));
    m_pauseButton->setToolTip(tr("Stop updating the view; the bytes are still recorded"));
    m_clearButton->setText(tr("Clear"));
    m_clearButton->setToolTip(tr("Empty the view"));
    m_copyButton->setText(tr("Copy"));
    m_copyButton->setToolTip(tr("Copy the selected lines, or everything shown, to the clipboard"));
    m_text->setToolTip(tr("Link traffic: time (s), direction (RX from the device, TX to it), byte offset, "
                          "hex and ASCII"));
    updateStatus();
}

void RawBytesView::updateStatus()
{
    QString text = tr("RX %1 bytes, TX %2 bytes").arg(m_offset[0]).arg(m_offset[1]);
    if (m_paused)
        text = tr("Paused — %1").arg(text);
    m_status->setText(text);
}

} // namespace imudesk::ui
