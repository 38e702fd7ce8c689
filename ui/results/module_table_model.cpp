#include "ui/results/module_table_model.h"

#include "ui/results/results_format.h"

#include <QFont>

namespace imudesk::ui {

ModuleTableModel::ModuleTableModel(QObject *parent) : QAbstractTableModel(parent) {}

void ModuleTableModel::setModules(std::vector<results::ModuleRecord> modules)
{
    beginResetModel();
    m_modules = std::move(modules);
    endResetModel();
}

const results::ModuleRecord *ModuleTableModel::module(int row) const
{
    return row >= 0 && row < int(m_modules.size()) ? &m_modules[size_t(row)] : nullptr;
}

int ModuleTableModel::rowOf(const QString &uuid) const
{
    for (size_t i = 0; i < m_modules.size(); ++i)
        if (m_modules[i].uuid == uuid)
            return int(i);
    return -1;
}

void ModuleTableModel::retranslate()
{
    Q_EMIT headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    if (!m_modules.empty())
        Q_EMIT dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1), {Qt::DisplayRole, Qt::ToolTipRole});
}

int ModuleTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_modules.size());
}

int ModuleTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString ModuleTableModel::firmwareText(const results::ModuleRecord &m)
{
    if (m.firmwareAfter.isEmpty() || m.firmwareAfter == m.firmwareBefore)
        return m.firmwareBefore;
    return QStringLiteral("%1 → %2").arg(m.firmwareBefore, m.firmwareAfter);
}

QString ModuleTableModel::fullText(const results::ModuleRecord &m, int column) const
{
    switch (column) {
    case Started: return ResultsFormat::time(m.started);
    case Serial: return m.serial;
    case Outcome: return ResultsFormat::outcome(m.outcome, m.marginal);
    case Plan: return m.run.planName;
    case Station: return m.run.stationId;
    case Slot: return m.slot;
    case Product: return m.product;
    case Firmware: return firmwareText(m);
    case Attempt: return QString::number(m.attempt);
    default: return {};
    }
}

QVariant ModuleTableModel::data(const QModelIndex &index, int role) const
{
    const results::ModuleRecord *m = index.isValid() ? module(index.row()) : nullptr;
    if (!m || index.column() < 0 || index.column() >= ColumnCount)
        return {};
    switch (role) {
    case Qt::DisplayRole: return ResultsFormat::shortText(fullText(*m, index.column()));
    case Qt::ToolTipRole: {
        const QString text = fullText(*m, index.column());
        return text.isEmpty() ? QVariant() : QVariant(ResultsFormat::toolTip(text));
    }
    case Qt::ForegroundRole:
        if (index.column() == Outcome)
            return ResultsFormat::outcomeColour(m->outcome, m->marginal);
        return {};
    case Qt::FontRole:
        if (index.column() == Outcome) {
            QFont bold;
            bold.setBold(true);
            return bold;
        }
        return {};
    case Qt::TextAlignmentRole:
        if (index.column() == Attempt)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    case SerialRole: return m->serial;
    case UuidRole: return m->uuid;
    default: return {};
    }
}

QVariant ModuleTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Started: return tr("Started");
    case Serial: return tr("Serial number");
    case Outcome: return tr("Outcome");
    case Plan: return tr("Plan");
    case Station: return tr("Station");
    case Slot: return tr("Slot");
    case Product: return tr("Product");
    case Firmware: return tr("Firmware");
    case Attempt: return tr("Attempt");
    default: return {};
    }
}

} // namespace imudesk::ui
