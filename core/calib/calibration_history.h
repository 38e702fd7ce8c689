#pragma once
// Every calibration run kept on disk, per device (issue 6, "Calibration history"):
//   <root>/<device>/<id>/record.json   kind, time (UTC), device serial/product/firmware,
//                                      the result with its metrics and verdict
//   <root>/<device>/<id>/samples.csv   the raw samples (SampleCsv: header row, numbers)
// <device> is the serial number reduced to [A-Za-z0-9_-] ("unknown" without one); <id> is
// the UTC time yyyyMMddTHHmmsszzz plus the kind, so a device's folder sorts by time.
// list() returns a device's runs newest first. Nothing is ever overwritten.
#include "calib/sample_csv.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonObject>
#include <QList>
#include <QString>

namespace imudesk::calib {

struct CalibrationRecord {
    QString kind;          // "magnetometer", "gyro_scale", "attitude_reset", "compass"
    QDateTime time;        // UTC
    QString deviceSerial;
    QString product;
    QString firmware;
    QJsonObject result;    // e.g. MagCalResult::toJson(); "verdict" and "reason" shown in lists
    int sampleCount = 0;
    QString folder;        // set by save() / list()

    QString verdict() const { return result.value(QStringLiteral("verdict")).toString(); }
    QJsonObject toJson() const;
    static bool fromJson(const QJsonObject &o, CalibrationRecord &out);
};

class CalibrationHistory {
    Q_DECLARE_TR_FUNCTIONS(CalibrationHistory)

public:
    static constexpr int kMaxListed = 10000;

    explicit CalibrationHistory(QString root);
    // QStandardPaths::AppDataLocation/calibrations.
    static QString defaultRoot();
    const QString &root() const { return m_root; }

    // Writes the record and its samples; fills record.folder. false with *error.
    bool save(CalibrationRecord &record, const SampleTable &samples, QString *error = nullptr) const;
    // The devices that have runs (folder names).
    QStringList devices() const;
    // A device's runs, newest first (serial as given to save()).
    QList<CalibrationRecord> list(const QString &deviceSerial) const;
    bool loadSamples(const CalibrationRecord &record, SampleTable &out, QString *error = nullptr) const;
    bool remove(const CalibrationRecord &record) const;

    static QString deviceFolderName(const QString &serial);

private:
    QString m_root;
};

} // namespace imudesk::calib
