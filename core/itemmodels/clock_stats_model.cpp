#include "clock_stats_model.h"

namespace imudesk::models {

using device::ClockStats;
using State = clock::ClockModel::State;

ClockStatsModel::ClockStatsModel(QObject *parent) : QAbstractTableModel(parent) {}

void ClockStatsModel::setClocks(const std::vector<device::ClockStats> &clocks)
{
    const bool sameRows = clocks.size() == m_clocks.size()
        && std::equal(clocks.begin(), clocks.end(), m_clocks.begin(),
                      [](const ClockStats &a, const ClockStats &b) { return a.source == b.source && a.method == b.method; });
    if (!sameRows) {
        beginResetModel();
        m_clocks = clocks;
        endResetModel();
        return;
    }
    m_clocks = clocks;
    if (!m_clocks.empty())
        Q_EMIT dataChanged(index(0, 0), index(int(m_clocks.size()) - 1, ColumnCount - 1));
}

int ClockStatsModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_clocks.size());
}

int ClockStatsModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString ClockStatsModel::methodText(ClockStats::Method m)
{
    switch (m) {
    case ClockStats::Method::Counter: return tr("device counter");
    case ClockStats::Method::Bracket: return tr("request/answer");
    case ClockStats::Method::Stamp: return tr("receive stamp");
    }
    return QString();
}

QString ClockStatsModel::stateText(const ClockStats &c)
{
    switch (c.state) {
    case State::Aligned: return tr("aligned");
    case State::Uncertain:
        return tr("uncertain: fitting, %1 s of the %2 s it needs").arg(c.spanS, 0, 'f', 1).arg(c.needSpanS, 0, 'f', 1);
    case State::FreeRunning:
        return c.method == ClockStats::Method::Stamp ? tr("free-running: the interface gives no receive stamps")
                                                     : tr("free-running: no device time yet");
    }
    return QString();
}

QVariant ClockStatsModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= int(m_clocks.size()))
        return {};
    const ClockStats &c = m_clocks[size_t(index.row())];
    const bool counter = c.method == ClockStats::Method::Counter;
    if (role == StateRole)
        return c.state == State::Aligned ? QStringLiteral("aligned")
            : c.state == State::Uncertain ? QStringLiteral("uncertain")
                                           : QStringLiteral("free-running");
    if (role == Qt::TextAlignmentRole && index.column() >= DriftColumn)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole) {
        switch (index.column()) {
        case MethodColumn:
            return counter ? tr("The device's own time, fitted against the host's clock from its least delayed samples")
                : c.method == ClockStats::Method::Bracket
                ? tr("No device time: the sample was taken between the request and its answer; the middle is used")
                : tr("No device time: the interface's receive stamp less the frame's time on the bus");
        case StateColumn: return stateText(c);
        case DriftColumn: return tr("How fast the device's clock runs against the host's, in parts per million");
        case JitterColumn: return tr("Scatter of the least delayed samples about the fitted line, in ms");
        case UncertaintyColumn: return tr("Half the request-to-answer time: the sampling instant lies within this, in ms");
        case ResetsColumn: return tr("Times the device's counter restarted or its time base changed (each starts the fit again)");
        default: return {};
        }
    }
    if (role != Qt::DisplayRole)
        return {};
    const QString none = QStringLiteral("–");
    switch (index.column()) {
    case StreamColumn: return QString::fromStdString(c.source);
    case MethodColumn: return methodText(c.method);
    case StateColumn: return stateText(c);
    case DriftColumn: return counter && c.state == State::Aligned ? QString::number(c.driftPpm, 'f', 2) : none;
    case JitterColumn: return counter && c.state != State::FreeRunning ? QString::number(c.jitterNs / 1e6, 'f', 3) : none;
    case UncertaintyColumn:
        return c.method == ClockStats::Method::Bracket ? QString::number(c.uncertaintyNs / 1e6, 'f', 1) : none;
    case ResetsColumn: return counter ? QString::number(c.resets) : none;
    default: return {};
    }
}

QVariant ClockStatsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case StreamColumn: return tr("Stream");
    case MethodColumn: return tr("Time from");
    case StateColumn: return tr("State");
    case DriftColumn: return tr("Drift (ppm)");
    case JitterColumn: return tr("Jitter (ms)");
    case UncertaintyColumn: return tr("± (ms)");
    case ResetsColumn: return tr("Resets");
    default: return {};
    }
}

} // namespace imudesk::models
