#pragma once
// Record / stop for one HiPNUC serial session: a file name pattern ({date}, {time},
// {serial}, {product} are filled in when recording starts) in a folder, and while
// recording the elapsed time, the file size and the frames recorded. A recording that
// stops by itself (full disk, write error) shows its reason and emits recordingFailed.
//
// Folder ui/recording/: recording, replay and export of captures. These RecordingControls, the
// ReplayControls and the ExportDialog. It mirrors core/record: recording goes through the
// link's session (device::Session: its engine writes the capture with capture::CaptureWriter, a
// HiPNUC module or an HEC495), replay drives a record::ReplaySession and export runs
// record::CaptureExporter in a worker thread. No item models.
#include <QString>
#include <QWidget>

#include <QElapsedTimer>
#include <QTimer>

class QDateTime;
class QLabel;
class QLineEdit;
class QPushButton;

class QSpinBox;

namespace imudesk::device {
class Session;
}

namespace imudesk::ui {

class RecordingControls : public QWidget {
    Q_OBJECT
public:
    static constexpr const char *kDefaultPattern = "{product}-{date}-{time}.imucap";

    explicit RecordingControls(QWidget *parent = nullptr);

    // The session to record from (not owned); nullptr disables the controls. Its
    // identityChanged fills {product} and {serial}; for a session that is already
    // identified, pass the identity with setIdentity().
    void setSession(device::Session *session);
    void setIdentity(const QString &product, const QString &serial);
    void setFolder(const QString &folder);
    QString folder() const;
    void setPattern(const QString &pattern);
    QString pattern() const;
    // Seconds after which a recording stops by itself; 0: until Stop. Remembered (QSettings).
    void setDurationS(int seconds);
    int durationS() const;
    bool isRecording() const { return m_recording; }
    QString currentPath() const { return m_path; }

    // The file name a pattern gives now (identity fields from the last identityChanged).
    QString expandPattern(const QString &pattern) const;
    // The file name a pattern gives for this product, serial and time: {product}, {serial},
    // {date} (yyyyMMdd), {time} (HHmmss); characters that leave the folder or upset a file
    // system become "_"; ".imucap" is added unless it ends in .imucap or .mcap (an MCAP recording).
    // (Also the preferences' example.)
    static QString expandPattern(const QString &pattern, const QString &product, const QString &serial,
                                 const QDateTime &when);

public Q_SLOTS:
    void startRecording();
    void stopRecording();

Q_SIGNALS:
    void recordingStarted(const QString &path);
    void recordingStopped(const QString &path);
    void recordingFailed(const QString &reason);

private:
    void onStarted(const QString &path);
    void onStopped(const QString &reason);
    void onProgress(quint64 bytes, quint64 frames);
    void refresh();
    void updateButtons();

    device::Session *m_session = nullptr;
    QPushButton *m_record = nullptr;
    QPushButton *m_stop = nullptr;
    QLineEdit *m_folder = nullptr;
    QLineEdit *m_pattern = nullptr;
    QSpinBox *m_duration = nullptr;
    QTimer m_stopTimer; // the duration's end
    bool m_stoppedByDuration = false;
    QLabel *m_elapsed = nullptr;
    QLabel *m_size = nullptr;
    QLabel *m_frames = nullptr;
    QLabel *m_message = nullptr;
    QTimer m_clock;
    QElapsedTimer m_since;
    bool m_recording = false;
    bool m_pending = false;
    bool m_interrupted = false;      // stopped by a drop-out; the same file may go on
    bool m_showingRecording = false; // the fields show the recording's folder and file
    QString m_userFolder, m_userPattern;
    QString m_path;
    QString m_product, m_serial;
    quint64 m_bytes = 0, m_frameCount = 0;
};

} // namespace imudesk::ui
