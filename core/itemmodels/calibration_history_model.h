#pragma once
// A device's calibration runs (calib::CalibrationHistory), newest first, one row each:
// time, kind, verdict, the key figures, firmware. QtCore only: colours come from the view
// (VerdictRole gives "pass"/"warn"/"fail"/"refused").
#include "calib/calibration_history.h"

#include <QAbstractTableModel>

namespace imudesk::models {

class CalibrationHistoryModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column : int { TimeColumn, KindColumn, VerdictColumn, SummaryColumn, FirmwareColumn, ColumnCount };
    enum Role : int {
        VerdictRole = Qt::UserRole + 1, // "pass", "warn", "fail", "refused" (or empty)
        FolderRole,                     // the run's folder
    };

    explicit CalibrationHistoryModel(QObject *parent = nullptr);

    // Reads the device's runs from the history (replaces the rows).
    void load(const calib::CalibrationHistory &history, const QString &deviceSerial);
    void setRecords(QList<calib::CalibrationRecord> records);
    const calib::CalibrationRecord &record(int row) const { return m_records.at(row); }

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    int columnCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    static QString kindText(const QString &kind);
    // "|B| 49.8 uT, fit error 0.62 %, coverage 95 %" or "scale error 0.503 %".
    static QString summaryText(const calib::CalibrationRecord &r);

private:
    QList<calib::CalibrationRecord> m_records;
};

} // namespace imudesk::models
