#pragma once
// Calibrate > Calibration history: the devices that have runs (the history's folders), the
// selected device's runs newest first (CalibrationHistoryModel in a QTableView), and the
// details of the selected run: every metric with its unit, and for magnetometer runs the
// sphere of its samples before (raw) and after (corrected by the run's hard/soft iron).
// Buttons: Export report (PDF), Export samples (CSV), Open folder, Delete (confirmed).
// Opens at the connected device when selectDevice() names it. Remembers its geometry.
// The steps behind the buttons take a path (exportReport, exportSamples, removeSelected)
// so tests and scripts run them without a file dialog.
#include "calib/calibration_history.h"
#include "calib/sample_csv.h"

#include <QDialog>

QT_BEGIN_NAMESPACE
class QLabel;
class QListWidget;
class QPushButton;
class QTableView;
QT_END_NAMESPACE

namespace imudesk::models {
class CalibrationHistoryModel;
}

namespace imudesk::ui {

class MagSphereView;

class CalibrationHistoryDialog : public QDialog {
    Q_OBJECT
public:
    static constexpr const char *kGeometryKey = "ui/v1/calibrationHistory/geometry";

    explicit CalibrationHistoryDialog(const QString &root = calib::CalibrationHistory::defaultRoot(),
                                      QWidget *parent = nullptr);
    ~CalibrationHistoryDialog() override;

    // Re-reads the device folders (keeps the selected device when it is still there).
    void reload();
    // Selects a device by its serial number (as the wizards saved it); false when it has no runs.
    bool selectDevice(const QString &serial);
    QString currentDevice() const;
    bool selectRun(int row);
    // The selected run; nullptr when none.
    const calib::CalibrationRecord *currentRecord() const;

    bool exportReport(const QString &path, QString *error = nullptr);
    bool exportSamples(const QString &path, QString *error = nullptr);
    bool removeSelected(QString *error = nullptr);

    QListWidget *deviceList() const { return m_devices; }
    QTableView *runTable() const { return m_runs; }
    models::CalibrationHistoryModel *model() const { return m_model; }
    QString detailsText() const;
    MagSphereView *beforeView() const { return m_before; }
    MagSphereView *afterView() const { return m_after; }

protected:
    void done(int result) override;

private:
    void deviceChanged();
    void runChanged();
    void chooseReportPath();
    void chooseSamplesPath();
    void openFolder();
    void confirmDelete();
    void showError(const QString &message);

    calib::CalibrationHistory m_history;
    calib::SampleTable m_samples;
    QListWidget *m_devices = nullptr;
    QTableView *m_runs = nullptr;
    models::CalibrationHistoryModel *m_model = nullptr;
    QLabel *m_details = nullptr;
    QLabel *m_sphereCaption = nullptr;
    MagSphereView *m_before = nullptr;
    MagSphereView *m_after = nullptr;
    QPushButton *m_exportReport = nullptr;
    QPushButton *m_exportSamples = nullptr;
    QPushButton *m_openFolder = nullptr;
    QPushButton *m_delete = nullptr;
};

} // namespace imudesk::ui
