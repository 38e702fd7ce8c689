#pragma once
// Export of a capture: the capture (given, e.g. the recording just made; Choose… picks
// another), format (vendor CSV, tidy CSV, JSON Lines), output file, time range, a progress
// bar and cancel. The export runs as a jobs::BackgroundJob (CaptureExporter streams, so
// memory stays flat); the dialog stays responsive and Cancel stops it and removes the
// partial files.
#include "jobs/background_job.h"
#include "record/capture_exporter.h"

#include <QDialog>
#include <QTimer>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace imudesk::ui {

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    explicit ExportDialog(const QString &capturePath, QWidget *parent = nullptr);
    ~ExportDialog() override;

    // The capture to export (or a recorded session: its folder or its session.json, exported
    // whole, every device aligned); the output file is suggested beside it.
    void setCapture(const QString &path);
    QString capture() const { return m_capture; }
    bool isSession() const { return m_session; }
    void setFormat(record::CaptureExporter::Format format);
    void setOutput(const QString &path);
    // to < 0: until the end.
    void setRange(double fromS, double toS);
    bool isRunning() const { return m_job.isRunning(); }
    const record::CaptureExporter::Result &lastResult() const { return m_result; }

public Q_SLOTS:
    void startExport();
    void cancelExport();

Q_SIGNALS:
    void exportFinished(bool ok, const QString &message);

private:
    void onFinished();
    void suggestOutput();
    void pollProgress();
    void chooseCapture();

    QString m_capture;
    QLineEdit *m_captureEdit = nullptr;
    QPushButton *m_chooseCapture = nullptr;
    QComboBox *m_format = nullptr;
    QLineEdit *m_output = nullptr;
    QDoubleSpinBox *m_from = nullptr;
    QDoubleSpinBox *m_to = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_export = nullptr;
    QPushButton *m_cancel = nullptr;
    QPushButton *m_showFolder = nullptr; // after a success: the folder of what was written
    bool m_session = false;              // m_capture is a recorded session's folder
    QTimer m_poll;
    record::CaptureExporter::Result m_result;
    jobs::BackgroundJob m_job; // last: cancelled and joined before the rest goes
};

} // namespace imudesk::ui
