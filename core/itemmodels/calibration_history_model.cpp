#include "itemmodels/calibration_history_model.h"

#include "calib/mag_cal_result.h"

#include <algorithm>

namespace imudesk::models {

CalibrationHistoryModel::CalibrationHistoryModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void CalibrationHistoryModel::load(const calib::CalibrationHistory &history, const QString &deviceSerial)
{
    setRecords(history.list(deviceSerial));
}

void CalibrationHistoryModel::setRecords(QList<calib::CalibrationRecord> records)
{
    std::stable_sort(records.begin(), records.end(),
                     [](const calib::CalibrationRecord &a, const calib::CalibrationRecord &b) { return a.time > b.time; });
    beginResetModel();
    m_records = std::move(records);
    endResetModel();
}

int CalibrationHistoryModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_records.size());
}

int CalibrationHistoryModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString CalibrationHistoryModel::kindText(const QString &kind)
{
    if (kind == QLatin1String("magnetometer"))
        return tr("Magnetometer");
    if (kind == QLatin1String("gyro_scale"))
        return tr("Gyro scale factor");
    if (kind == QLatin1String("attitude_reset"))
        return tr("Attitude reset");
    if (kind == QLatin1String("compass"))
        return tr("Compass (HEC495)");
    return kind;
}

QString CalibrationHistoryModel::summaryText(const calib::CalibrationRecord &r)
{
    const QJsonObject o = r.result;
    if (o.contains(QStringLiteral("field_ut")))
        return tr("|B| %1 µT, fit error %2 %, coverage %3 %")
            .arg(o.value(QStringLiteral("field_ut")).toDouble(), 0, 'f', 1)
            .arg(o.value(QStringLiteral("fit_error_pct")).toDouble(), 0, 'f', 2)
            .arg(o.value(QStringLiteral("coverage_pct")).toDouble(), 0, 'f', 0);
    if (o.contains(QStringLiteral("scale_error_pct")))
        return tr("scale error %1 %").arg(o.value(QStringLiteral("scale_error_pct")).toDouble(), 0, 'f', 3);
    return o.value(QStringLiteral("reason")).toString();
}

QVariant CalibrationHistoryModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= int(m_records.size()))
        return {};
    const calib::CalibrationRecord &r = m_records.at(index.row());
    if (role == VerdictRole)
        return r.verdict();
    if (role == FolderRole)
        return r.folder;
    if (role == Qt::ToolTipRole)
        return r.result.value(QStringLiteral("reason")).toString();
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case TimeColumn: return r.time.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
    case KindColumn: return kindText(r.kind);
    case VerdictColumn: {
        calib::MagVerdict v;
        return calib::parseVerdict(r.verdict(), v) ? calib::MagCalResult::verdictText(v) : r.verdict();
    }
    case SummaryColumn: return summaryText(r);
    case FirmwareColumn: return r.firmware;
    default: return {};
    }
}

QVariant CalibrationHistoryModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case TimeColumn: return tr("Time");
    case KindColumn: return tr("Calibration");
    case VerdictColumn: return tr("Verdict");
    case SummaryColumn: return tr("Result");
    case FirmwareColumn: return tr("Firmware");
    default: return {};
    }
}

} // namespace imudesk::models
