#pragma once
// A session's clocks (device::ClockStats, issue 36 point 2), one row per stream: how its samples
// get their common time (the device's counter through a clock model, a request's bracket, the
// interface's receive stamp), the state (aligned, uncertain with why, free-running) and the
// figures: drift (ppm), residual jitter, bracket half-width, counter resets. QtCore only:
// StateRole gives "aligned" / "uncertain" / "free-running" for the view's colours.
#include "device/session_types.h"

#include <QAbstractTableModel>

#include <vector>

namespace imudesk::models {

class ClockStatsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column : int { StreamColumn, MethodColumn, StateColumn, DriftColumn, JitterColumn, UncertaintyColumn,
                        ResetsColumn, ColumnCount };
    enum Role : int { StateRole = Qt::UserRole + 1 };

    explicit ClockStatsModel(QObject *parent = nullptr);

    // The clocks of the latest statistics (rows kept where the streams stay the same).
    void setClocks(const std::vector<device::ClockStats> &clocks);
    const std::vector<device::ClockStats> &clocks() const { return m_clocks; }

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    int columnCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    static QString methodText(device::ClockStats::Method m);
    // "aligned", "uncertain: fitting, 1.2 s of 2.0 s", "free-running: no interface stamps" ...
    static QString stateText(const device::ClockStats &c);

private:
    std::vector<device::ClockStats> m_clocks;
};

} // namespace imudesk::models
