#pragma once
// Keeps a wizard's finished calibration run in the calibration history
// (calib::CalibrationHistory): kind, UTC time, the device's serial, product and firmware
// (from the link's identity), the result JSON (metrics, "verdict", "reason") and the raw
// samples. Each wizard owns one; the root defaults to CalibrationHistory::defaultRoot()
// and tests point it at a temporary folder. statusText() is the line the result page shows:
// where the run was saved, or why it could not be (the run is still shown).
#include "calib/calibration_history.h"
#include "model/device_identity.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QString>

namespace imudesk::ui {

class CalibrationRunSaver {
    Q_DECLARE_TR_FUNCTIONS(CalibrationRunSaver)

public:
    static constexpr size_t kMaxRows = 400000; // samples kept per run

    CalibrationRunSaver();

    void setRoot(const QString &root) { m_root = root; }
    const QString &root() const { return m_root; }
    void setIdentity(const model::DeviceIdentity &identity);
    // The serial a run is kept under: the device's serial, or "<product>-addr<n>" for a bus
    // device without one (HEC495).
    static QString serialOf(const model::DeviceIdentity &identity);
    const QString &serial() const { return m_serial; }

    // Saves one run; false with lastError(). Every call is a new run in the history.
    bool save(const QString &kind, const QJsonObject &result, const calib::SampleTable &samples);
    const QString &lastFolder() const { return m_folder; }
    const QString &lastError() const { return m_error; }
    bool saved() const { return !m_folder.isEmpty(); }
    // "Saved in the calibration history: <folder>", the error, or empty before any save.
    QString statusText() const;

private:
    QString m_root;
    QString m_serial, m_product, m_firmware;
    QString m_folder, m_error;
};

} // namespace imudesk::ui
