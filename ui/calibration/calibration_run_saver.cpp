#include "calibration/calibration_run_saver.h"

#include <QDir>

namespace imudesk::ui {

CalibrationRunSaver::CalibrationRunSaver()
    : m_root(calib::CalibrationHistory::defaultRoot())
{
}

QString CalibrationRunSaver::serialOf(const model::DeviceIdentity &identity)
{
    const QString serial = QString::fromStdString(identity.serial);
    if (serial.isEmpty() && identity.busAddress >= 0)
        return QStringLiteral("%1-addr%2").arg(QString::fromStdString(identity.productName)).arg(identity.busAddress);
    return serial;
}

void CalibrationRunSaver::setIdentity(const model::DeviceIdentity &identity)
{
    m_serial = serialOf(identity);
    m_product = QString::fromStdString(identity.productName);
    m_firmware = identity.firmware ? QString::fromStdString(identity.firmware->toString()) : QString();
}

bool CalibrationRunSaver::save(const QString &kind, const QJsonObject &result, const calib::SampleTable &samples)
{
    calib::CalibrationRecord record;
    record.kind = kind;
    record.time = QDateTime::currentDateTimeUtc();
    record.deviceSerial = m_serial;
    record.product = m_product;
    record.firmware = m_firmware;
    record.result = result;
    m_folder.clear();
    m_error.clear();
    const calib::CalibrationHistory history(m_root);
    if (!history.save(record, samples, &m_error))
        return false;
    m_folder = record.folder;
    return true;
}

QString CalibrationRunSaver::statusText() const
{
    if (!m_folder.isEmpty())
        return tr("Saved in the calibration history (Calibrate > Calibration history): %1")
            .arg(QDir::toNativeSeparators(m_folder));
    if (!m_error.isEmpty())
        return tr("This run could not be saved in the calibration history: %1 The result is still shown here; "
                  "free some disk space or check the folder's permissions to keep the next run.")
            .arg(m_error);
    return {};
}

} // namespace imudesk::ui
