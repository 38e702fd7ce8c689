#include "register_table_model.h"

#include <algorithm>


namespace imudesk::models {

using protocol::modbus::RegisterBlock;
using protocol::modbus::RegisterDef;
using protocol::modbus::RegisterMap;

RegisterTableModel::RegisterTableModel(QObject *parent) : QAbstractTableModel(parent) {}

void RegisterTableModel::setMap(const RegisterMap &map)
{
    beginResetModel();
    m_map = &map;
    m_words.clear();
    endResetModel();
}

void RegisterTableModel::clearValues()
{
    m_words.clear();
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0, RawColumn), index(rowCount() - 1, ValueColumn));
}

const RegisterDef *RegisterTableModel::registerAt(int row) const
{
    if (!m_map || row < 0 || row >= int(m_map->registers().size()))
        return nullptr;
    return &m_map->registers()[size_t(row)];
}

void RegisterTableModel::setBlock(const RegisterBlock &block)
{
    if (!m_map || block.size() == 0)
        return;
    for (size_t i = 0; i < block.size(); ++i)
        m_words[uint16_t(block.start() + i)] = block.values()[i];
    int first = -1, last = -1;
    for (int row = 0; row < rowCount(); ++row) {
        const RegisterDef *d = registerAt(row);
        if (d->address < block.start() + block.size() && d->address + d->words > block.start()) {
            if (first < 0)
                first = row;
            last = row;
        }
    }
    if (first >= 0)
        Q_EMIT dataChanged(index(first, RawColumn), index(last, ValueColumn));
}

QList<RegisterTableModel::Range> RegisterTableModel::readRanges(int maxGap) const
{
    QList<Range> out;
    if (!m_map)
        return out;
    std::map<int, int> spans; // start -> end (exclusive), readable registers only
    for (const RegisterDef &d : m_map->registers())
        if (d.readable())
            spans[d.address] = std::max(spans[d.address], d.address + d.words);
    for (const auto &[start, end] : spans) {
        if (!out.isEmpty()) {
            Range &r = out.last();
            const int rEnd = r.start + r.count;
            if (start - rEnd <= maxGap && end - r.start <= 125) {
                r.count = std::max(rEnd, end) - r.start;
                continue;
            }
        }
        out.append(Range{start, end - start});
    }
    return out;
}

int RegisterTableModel::rowCount(const QModelIndex &parent) const
{
    return (parent.isValid() || !m_map) ? 0 : int(m_map->registers().size());
}

int RegisterTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant RegisterTableModel::data(const QModelIndex &index, int role) const
{
    const RegisterDef *d = index.isValid() ? registerAt(index.row()) : nullptr;
    if (!d)
        return {};
    std::vector<uint16_t> words;
    for (uint16_t i = 0; i < d->words; ++i) {
        const auto it = m_words.find(uint16_t(d->address + i));
        if (it == m_words.end())
            break;
        words.push_back(it->second);
    }
    const bool known = words.size() == d->words;
    const RegisterBlock block(d->address, words);
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (index.column()) {
        case AddressColumn:
            return d->words > 1 ? QStringLiteral("0x%1-0x%2").arg(d->address, 4, 16, QLatin1Char('0')).arg(d->address + d->words - 1, 4, 16, QLatin1Char('0'))
                                : QStringLiteral("0x%1").arg(d->address, 4, 16, QLatin1Char('0'));
        case NameColumn: return QLatin1String(d->name);
        case TypeColumn: return QLatin1String(RegisterMap::typeName(d->type));
        case AccessColumn:
            return d->access == protocol::modbus::ReadWrite ? QStringLiteral("R/W")
                : d->writable()                              ? QStringLiteral("W")
                                                             : QStringLiteral("R");
        case RawColumn: {
            if (role == Qt::EditRole)
                return known && d->words == 1 ? QVariant(int(words[0])) : QVariant(0);
            if (!known)
                return QStringLiteral("—");
            QStringList hex;
            for (uint16_t w : words)
                hex << QStringLiteral("%1").arg(w, 4, 16, QLatin1Char('0')).toUpper();
            return hex.join(QLatin1Char(' '));
        }
        case ValueColumn: {
            if (!known)
                return QStringLiteral("—");
            const auto text = block.text(*d);
            return text ? QString::fromStdString(*text) : QStringLiteral("—");
        }
        case UnitColumn: return QLatin1String(d->unit);
        case DescriptionColumn: return RegisterMap::describe(*d);
        default: return {};
        }
    }
    if (role == Qt::ToolTipRole)
        return RegisterMap::describe(*d);
    if (role == Qt::TextAlignmentRole && (index.column() == RawColumn || index.column() == ValueColumn))
        return int(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant RegisterTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case AddressColumn: return tr("Address");
    case NameColumn: return tr("Name");
    case TypeColumn: return tr("Type");
    case AccessColumn: return tr("Access");
    case RawColumn: return tr("Raw");
    case ValueColumn: return tr("Value");
    case UnitColumn: return tr("Unit");
    case DescriptionColumn: return tr("Description");
    default: return {};
    }
}

Qt::ItemFlags RegisterTableModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    const RegisterDef *d = index.isValid() ? registerAt(index.row()) : nullptr;
    if (d && index.column() == RawColumn && d->writable() && d->words == 1)
        f |= Qt::ItemIsEditable;
    return f;
}

bool RegisterTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    const RegisterDef *d = index.isValid() ? registerAt(index.row()) : nullptr;
    if (role != Qt::EditRole || !d || !(flags(index) & Qt::ItemIsEditable))
        return false;
    bool ok = false;
    const QString text = value.toString().trimmed();
    const int v = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? text.mid(2).toInt(&ok, 16) : text.toInt(&ok);
    if (!ok || v < 0 || v > 0xFFFF || !RegisterMap::accepts(*d, uint16_t(v))) {
        Q_EMIT writeRefused(tr("%1 is not a valid value for %2: %3").arg(text, QLatin1String(d->name), RegisterMap::describe(*d)));
        return false;
    }
    Q_EMIT writeRequested(d->address, v);
    return true; // the value shown changes when the device's register is read again
}

} // namespace imudesk::models
