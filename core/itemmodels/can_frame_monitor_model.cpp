#include "can_frame_monitor_model.h"

#include <QFile>
#include <QSaveFile>
#include <QTextStream>

#include <algorithm>

namespace imudesk::models {

using protocol::can::CanFrame;

CanFrameMonitorModel::CanFrameMonitorModel(QObject *parent) : QAbstractTableModel(parent) {}

int CanFrameMonitorModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_visible.size());
}

int CanFrameMonitorModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

uint64_t CanFrameMonitorModel::keyOf(const CanFrame &f, bool tx)
{
    return uint64_t(f.id) | (uint64_t(f.extended) << 32) | (uint64_t(tx) << 33);
}

QString CanFrameMonitorModel::typeText(const Row &r) const
{
    QString t = r.frame.extended ? tr("Ext") : tr("Std");
    if (r.frame.fd)
        t += tr(" FD");
    if (r.frame.remote)
        t += tr(" RTR");
    t += r.tx ? tr(" Tx") : tr(" Rx");
    return t;
}

QVariant CanFrameMonitorModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= int(m_visible.size()) || index.column() >= ColumnCount)
        return {};
    const Row &r = m_rows[size_t(m_visible[size_t(index.row())])];
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case ColId: return r.frame.idText() + QStringLiteral("h");
        case ColType: return typeText(r);
        case ColDlc: return int(r.frame.len);
        case ColData: return r.frame.dataText();
        case ColPeriod: return r.count > 1 ? QString::number(r.periodMs, 'f', 1) : QString();
        case ColCount: return QVariant::fromValue<qulonglong>(r.count);
        case ColMeaning: return r.meaning;
        default: return {};
        }
    case Qt::TextAlignmentRole:
        if (index.column() == ColDlc || index.column() == ColPeriod || index.column() == ColCount)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    case IdRole: return r.frame.id;
    case CountRole: return QVariant::fromValue<qulonglong>(r.count);
    case PeriodMsRole: return r.periodMs;
    case TransmittedRole: return r.tx;
    default: return {};
    }
}

QVariant CanFrameMonitorModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case ColId: return tr("CAN-ID");
    case ColType: return tr("Type");
    case ColDlc: return tr("Length");
    case ColData: return tr("Data");
    case ColPeriod: return tr("Cycle time (ms)");
    case ColCount: return tr("Count");
    case ColMeaning: return tr("Meaning");
    default: return {};
    }
}

bool CanFrameMonitorModel::matches(const Row &r) const
{
    if (m_filter.isEmpty())
        return true;
    return r.frame.idText().contains(m_filter, Qt::CaseInsensitive) || r.meaning.contains(m_filter, Qt::CaseInsensitive);
}

void CanFrameMonitorModel::addEvents(const device::CanFrameEvents &events)
{
    if (m_paused) {
        m_whilePaused += uint64_t(events.size());
        return;
    }
    int minChanged = INT_MAX, maxChanged = -1;
    std::vector<size_t> added;
    for (const auto &ev : events) {
        ++m_total;
        const uint64_t key = keyOf(ev.frame, ev.transmitted);
        auto it = m_index.find(key);
        size_t at;
        if (it == m_index.end()) {
            if (int(m_rows.size()) >= m_maxRows) {
                ++m_overLimit;
                continue;
            }
            at = m_rows.size();
            m_rows.push_back(Row{ev.frame, ev.transmitted, 0, 0, 0, {}});
            m_visibleOf.push_back(-1);
            m_index.emplace(key, at);
            added.push_back(at);
        } else {
            at = it->second;
        }
        Row &r = m_rows[at];
        if (r.count > 0 && ev.hostTimeNs > r.lastNs) {
            const double dt = double(ev.hostTimeNs - r.lastNs) / 1e6;
            r.periodMs = r.count == 1 ? dt : 0.8 * r.periodMs + 0.2 * dt;
        }
        r.lastNs = ev.hostTimeNs;
        ++r.count;
        r.frame = ev.frame;
        r.meaning = m_decoder.decode(ev.frame).meaning;
        const int vis = m_visibleOf[at];
        if (vis >= 0) {
            minChanged = std::min(minChanged, vis);
            maxChanged = std::max(maxChanged, vis);
        }
    }
    if (maxChanged >= 0)
        Q_EMIT dataChanged(index(minChanged, 0), index(maxChanged, ColumnCount - 1));
    for (size_t at : added) {
        if (!matches(m_rows[at]))
            continue;
        const int row = int(m_visible.size());
        beginInsertRows({}, row, row);
        m_visible.push_back(int(at));
        m_visibleOf[at] = row;
        endInsertRows();
    }
}

void CanFrameMonitorModel::clear()
{
    beginResetModel();
    m_rows.clear();
    m_index.clear();
    m_visible.clear();
    m_visibleOf.clear();
    m_total = m_whilePaused = m_overLimit = 0;
    m_decoder.resetCounters();
    endResetModel();
}

void CanFrameMonitorModel::rebuildVisible()
{
    m_visible.clear();
    for (size_t i = 0; i < m_rows.size(); ++i) {
        m_visibleOf[i] = -1;
        if (matches(m_rows[i])) {
            m_visibleOf[i] = int(m_visible.size());
            m_visible.push_back(int(i));
        }
    }
}

void CanFrameMonitorModel::setFilter(const QString &text)
{
    if (text == m_filter)
        return;
    beginResetModel();
    m_filter = text.trimmed();
    rebuildVisible();
    endResetModel();
}

namespace {
QString csvField(QString s)
{
    if (s.contains(QLatin1Char(',')) || s.contains(QLatin1Char('"')) || s.contains(QLatin1Char('\n')))
        s = QLatin1Char('"') + s.replace(QLatin1Char('"'), QStringLiteral("\"\"")) + QLatin1Char('"');
    return s;
}
} // namespace

bool CanFrameMonitorModel::exportCsv(QIODevice *out) const
{
    QTextStream ts(out);
    ts << "id,type,direction,dlc,data,period_ms,count,meaning\n";
    for (const Row &r : m_rows) {
        QString type = r.frame.extended ? QStringLiteral("ext") : QStringLiteral("std");
        if (r.frame.fd)
            type += QStringLiteral("+fd");
        if (r.frame.remote)
            type += QStringLiteral("+rtr");
        ts << r.frame.idText() << ',' << type << ',' << (r.tx ? "tx" : "rx") << ',' << r.frame.len << ','
           << r.frame.dataText() << ',' << QString::number(r.periodMs, 'f', 3) << ',' << r.count << ','
           << csvField(r.meaning) << '\n';
    }
    ts.flush();
    return ts.status() == QTextStream::Ok;
}

bool CanFrameMonitorModel::exportCsv(const QString &path, QString *error) const
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    if (!exportCsv(&f) || !f.commit()) {
        if (error)
            *error = tr("writing %1 failed: %2 (is the disk full?)").arg(path, f.errorString());
        return false;
    }
    return true;
}

} // namespace imudesk::models
