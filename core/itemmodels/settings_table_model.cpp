#include "settings_table_model.h"

#include "settings/setting_catalog.h"

namespace imudesk::models {

using settings::SettingCatalog;

namespace {
const settings::SettingDefinition &def(int row)
{
    return SettingCatalog::settings()[size_t(row)];
}
} // namespace

SettingsTableModel::SettingsTableModel(QObject *parent) : QAbstractTableModel(parent) {}

int SettingsTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(SettingCatalog::settings().size());
}

int SettingsTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

bool SettingsTableModel::available(int row) const
{
    return m_config.identity.usable() && SettingCatalog::availability(def(row), m_config.identity).available;
}

int SettingsTableModel::rowOfKey(const QString &key) const
{
    const auto *d = SettingCatalog::find(key);
    if (!d)
        return -1;
    return int(d - SettingCatalog::settings().data());
}

void SettingsTableModel::setConfiguration(const settings::DeviceConfiguration &config)
{
    beginResetModel();
    m_config = config;
    for (auto it = m_pending.begin(); it != m_pending.end();) {
        const auto v = m_config.value(it->first);
        const int row = rowOfKey(it->first);
        if ((v && *v == it->second) || row < 0 || !available(row))
            it = m_pending.erase(it);
        else
            ++it;
    }
    endResetModel();
    Q_EMIT pendingChanged();
}

bool SettingsTableModel::setPending(const QString &key, const QString &value)
{
    const int row = rowOfKey(key);
    if (row < 0) {
        m_lastError = tr("unknown setting '%1'").arg(key);
        return false;
    }
    return setData(index(row, NewColumn), value, Qt::EditRole);
}

std::vector<settings::ConfigurationController::Change> SettingsTableModel::pendingChanges() const
{
    std::vector<settings::ConfigurationController::Change> out;
    for (const auto &d : SettingCatalog::settings()) {
        const auto it = m_pending.find(QLatin1String(d.key));
        if (it != m_pending.end())
            out.push_back({it->first, it->second});
    }
    return out;
}

void SettingsTableModel::clearPending()
{
    if (m_pending.empty())
        return;
    m_pending.clear();
    Q_EMIT dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    Q_EMIT pendingChanged();
}

void SettingsTableModel::retranslate()
{
    Q_EMIT headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    Q_EMIT dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

QVariant SettingsTableModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const auto &d = def(index.row());
    const QString key = QLatin1String(d.key);
    const auto device = m_config.value(key);
    const auto pending = m_pending.find(key);
    const bool isPending = pending != m_pending.end();
    switch (role) {
    case KeyRole: return key;
    case AvailableRole: return available(index.row());
    case PendingRole: return isPending;
    case CanonicalRole:
        if (index.column() == DeviceColumn)
            return device.value_or(QString());
        if (index.column() == NewColumn)
            return isPending ? pending->second : device.value_or(QString());
        return {};
    case ChoicesRole:
    case ChoiceLabelsRole: {
        QStringList out;
        for (const auto &c : SettingCatalog::choices(d, m_config.identity))
            out << (role == ChoicesRole ? c.value : c.label);
        return out;
    }
    case Qt::ToolTipRole: {
        QString tip = SettingCatalog::description(d);
        if (m_config.identity.usable()) {
            const auto a = SettingCatalog::availability(d, m_config.identity);
            if (!a.available)
                tip = a.reason + QLatin1Char('\n') + tip;
        }
        // What the optional columns hold, for a table that shows only name and values.
        tip += QLatin1Char('\n') + tr("Key: %1").arg(key);
        tip += QLatin1Char('\n') + tr("Takes effect: %1").arg(SettingCatalog::persistenceText(d.persistence));
        if (const QString readBack = SettingCatalog::readBackText(d); !readBack.isEmpty())
            tip += QLatin1Char('\n') + tr("Read back by: %1").arg(readBack);
        return tip;
    }
    case Qt::EditRole:
        if (index.column() == NewColumn)
            return isPending ? pending->second : device.value_or(QString());
        return {};
    case Qt::DisplayRole:
        switch (index.column()) {
        case NameColumn: return SettingCatalog::label(d);
        case KeyColumn: return key;
        case DeviceColumn: return device ? SettingCatalog::valueText(d, *device) : QString();
        case NewColumn: return isPending ? SettingCatalog::valueText(d, pending->second) : QString();
        case EffectColumn: return SettingCatalog::persistenceText(d.persistence);
        case ReadBackColumn: return SettingCatalog::readBackText(d);
        default: return {};
        }
    default: return {};
    }
}

bool SettingsTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::EditRole || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid)
        || index.column() != NewColumn)
        return false;
    const auto &d = def(index.row());
    const QString key = QLatin1String(d.key);
    if (!available(index.row())) {
        m_lastError = m_config.identity.usable() ? SettingCatalog::availability(d, m_config.identity).reason
                                                 : tr("read the device first");
        return false;
    }
    const QString text = value.toString();
    if (text.trimmed().isEmpty()) {
        m_pending.erase(key);
    } else {
        QString error;
        const auto v = SettingCatalog::normalize(d, text, &m_config.identity, &error);
        if (!v) {
            m_lastError = error;
            return false;
        }
        const auto device = m_config.value(key);
        if (device && *device == *v)
            m_pending.erase(key);
        else
            m_pending[key] = *v;
    }
    m_lastError.clear();
    Q_EMIT dataChanged(this->index(index.row(), 0), this->index(index.row(), ColumnCount - 1));
    Q_EMIT pendingChanged();
    return true;
}

Qt::ItemFlags SettingsTableModel::flags(const QModelIndex &index) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return Qt::NoItemFlags;
    if (!available(index.row()))
        return Qt::NoItemFlags; // greyed out: the model or firmware does not have it
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == NewColumn)
        f |= Qt::ItemIsEditable;
    return f;
}

QVariant SettingsTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case NameColumn: return tr("Setting");
    case KeyColumn: return tr("Key");
    case DeviceColumn: return tr("On the device");
    case NewColumn: return tr("New value");
    case EffectColumn: return tr("Takes effect");
    case ReadBackColumn: return tr("Read back by");
    default: return {};
    }
}

} // namespace imudesk::models
