#pragma once
// "Twist to align" (issue 36 point 4), the wizard page of a recorded session: modules on one
// fixture, the fixture turned sharply a few times while every device recorded; the devices'
// gyro magnitudes on their common time are cross-correlated against a reference device's
// (clock::alignByTwist, sub-sample fine search) and each device's constant offset is stored in
// the session's session.json, where export and replay take it from. The same as
// `imudesk-cli align FOLDER` (app/cli/commands_session.cpp), with a table of the offsets found
// and a plot of the correlation curves.
//
// Reading the captures can take seconds: the search runs as a jobs::BackgroundJob with a
// progress bar and Cancel; the dialog stays responsive.
#include "clock/twist_align.h"
#include "jobs/background_job.h"
#include "record/session_manifest.h"

#include <QColor>
#include <QDialog>
#include <QString>
#include <QTimer>
#include <QWidget>

#include <utility>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSplitter;
class QTableWidget;

namespace imudesk::ui {

// The normalised cross-correlation of each device's gyro magnitude with the reference's
// against the lag (ms), -1..1, one curve per device, with a marker at the offset found and a
// legend. Painted with QPainter (renders offscreen).
class CorrelationPlot : public QWidget {
    Q_OBJECT
public:
    struct Curve {
        QString name;
        std::vector<std::pair<double, double>> points; // (lag ms, correlation)
        bool aligned = false;                         // the marker is drawn only for an aligned device
        double offsetMs = 0;                          // the offset found (the marker's lag)
        double correlation = 0;                       // at the offset
    };

    explicit CorrelationPlot(QWidget *parent = nullptr);

    void setCurves(std::vector<Curve> curves);
    void clear();
    const std::vector<Curve> &curves() const { return m_curves; }
    // The correlation a device needs (a dashed line), clock::TwistAlignOptions::minCorrelation.
    void setMinimumCorrelation(double c);
    // The colour of the i-th curve (tests look for it in a rendering).
    static QColor curveColour(int i);
    // What the plot says when it has no curve.
    QString emptyText() const;

    QSize sizeHint() const override { return {640, 260}; }
    QSize minimumSizeHint() const override { return {260, 140}; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    std::vector<Curve> m_curves;
    double m_minCorrelation = 0.8;
};

class TwistAlignDialog : public QDialog {
    Q_OBJECT
public:
    // One device of the session, after a search.
    struct DeviceResult {
        QString name;
        bool reference = false;
        QString error;          // its capture could not be read (the reader's words)
        size_t samples = 0;     // gyro samples with a common time inside the window
        int twists = 0;         // distinct twists in its series
        clock::TwistAlignResult result; // a device other than the reference, with samples: the alignment
        bool aligned() const { return !reference && result.ok; }
    };

    explicit TwistAlignDialog(const QString &sessionFolder = {}, QWidget *parent = nullptr);
    ~TwistAlignDialog() override;

    // Loads the folder's session.json (the device list for the reference); the status says
    // what is wrong with a folder that is not a session.
    void setSessionFolder(const QString &path);
    QString sessionFolder() const { return m_folder; }
    // The reference device by its name in session.json; an empty name: the first device with
    // gyroscope data (the CLI's default). False when the session has no such device.
    bool setReferenceDevice(const QString &name);
    // The part of the session the twists are in, s since the recording began; toS 0: the end.
    void setWindow(double fromS, double toS);

    bool isRunning() const { return m_job.isRunning(); }
    // The last search's devices, in the order of session.json (empty before one).
    std::vector<DeviceResult> results() const { return m_results; }
    bool anyAligned() const;
    QString statusText() const;
    CorrelationPlot *plot() const { return m_plot; }

public Q_SLOTS:
    void findOffsets();
    void cancelSearch();
    // Writes the offsets of the last search into session.json (the reference: 0, "twist
    // reference"; each aligned device: its offset, "twist"; the others as they were).
    bool storeOffsets();
    void reject() override;

Q_SIGNALS:
    void alignmentFinished(bool anyAligned);
    void offsetsStored(bool ok, const QString &message);

private:
    bool loadManifest();
    void chooseFolder();
    void onFinished(bool ok, const QString &message);
    void pollProgress();
    void setBusy(bool busy);
    void setStatus(const QString &text, bool error);
    void showDevices();  // the manifest's devices before a search
    void showResults();  // the last search's
    void clearResults();
    void updateButtons();

    QString m_folder;
    record::SessionManifest m_manifest;
    bool m_manifestOk = false;
    std::vector<DeviceResult> m_results;
    QString m_resultsFolder; // the folder the results are of
    bool m_cancelled = false;

    QLabel *m_instructions = nullptr;
    QLineEdit *m_folderEdit = nullptr;
    QPushButton *m_chooseFolder = nullptr;
    QComboBox *m_reference = nullptr;
    QDoubleSpinBox *m_from = nullptr;
    QDoubleSpinBox *m_to = nullptr;
    QTableWidget *m_table = nullptr;
    CorrelationPlot *m_plot = nullptr;
    QSplitter *m_splitter = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_find = nullptr;
    QPushButton *m_store = nullptr;
    QPushButton *m_cancel = nullptr;
    QTimer m_poll;
    jobs::BackgroundJob m_job; // last: cancelled and joined before the rest goes
};

} // namespace imudesk::ui
