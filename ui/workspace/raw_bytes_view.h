#pragma once
// Hex + ASCII dump of the bytes a link carried (Session::rawLog()): one line per
// up to 16 bytes of one read or write, with the time since the view started, the
// direction and the byte offset in that direction; received bytes in one colour, sent
// bytes in another. refresh() (called on the workspace's clock) renders only what is new
// and keeps the last maxBytes() of traffic, so the view stays responsive at 921600 baud:
// when more arrived since the last refresh than the view holds, the older part is
// skipped with a note. Pause stops rendering (the log keeps recording); Clear empties
// the view; Copy copies the selection, or everything shown.
#include "device/raw_byte_log.h"

#include <QElapsedTimer>
#include <QTextCharFormat>
#include <QWidget>

#include <cstdint>

class QLabel;
class QPlainTextEdit;
class QToolButton;

namespace imudesk::ui {

class RawBytesView : public QWidget {
    Q_OBJECT
public:
    static constexpr int kBytesPerLine = 16;
    static constexpr size_t kDefaultMaxBytes = 64 * 1024;

    explicit RawBytesView(QWidget *parent = nullptr);

    // The log to show (not owned; nullptr detaches). The view starts at what the log
    // holds now, so a session already running shows its recent history.
    void setLog(const device::RawByteLog *log);
    // Renders the chunks added to the log since the last refresh.
    void refresh();

    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // Empties the view; the bytes already logged are not shown again.
    void clear();
    // How much traffic the view holds (rounded to whole lines).
    void setMaxBytes(size_t bytes);
    size_t maxBytes() const { return m_maxBytes; }

    // The text shown, and the selection (or all of it) as copied to the clipboard.
    QString text() const;
    QString copyText() const;
    void copyToClipboard() const;

    QPlainTextEdit *textView() const { return m_text; }
    // Colours of received and sent bytes.
    static QColor rxColor();
    static QColor txColor();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void appendChunks(const std::vector<device::RawByteLog::Chunk> &chunks, uint64_t skippedChunks);
    void updateStatus();

    const device::RawByteLog *m_log = nullptr;
    uint64_t m_nextSeq = 0;
    bool m_paused = false;
    size_t m_maxBytes = kDefaultMaxBytes;
    int64_t m_originNs = -1;         // host time of the first chunk shown
    uint64_t m_offset[2] = {0, 0};   // bytes seen per direction (Rx, Tx)
    uint64_t m_skippedBytes = 0;     // never rendered (the view was behind)
    bool m_empty = true;

    QPlainTextEdit *m_text = nullptr;
    QToolButton *m_pauseButton = nullptr;
    QToolButton *m_clearButton = nullptr;
    QToolButton *m_copyButton = nullptr;
    QLabel *m_status = nullptr;
    QTextCharFormat m_rxFormat, m_txFormat, m_noteFormat;
};

} // namespace imudesk::ui
