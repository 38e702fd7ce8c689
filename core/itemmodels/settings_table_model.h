#pragma once
// Every documented setting as a table row: name, key, the value the device holds, the
// value the user wants (editable), when it takes effect and how it is read back. Rows the
// connected model or firmware does not have are shown but not enabled (the reason is the
// tooltip). QtCore only: colours and editors come from the view's delegates.
#include "settings/configuration_controller.h"
#include "settings/device_configuration.h"

#include <QAbstractTableModel>

#include <map>
#include <vector>

namespace imudesk::models {

class SettingsTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column : int { NameColumn, KeyColumn, DeviceColumn, NewColumn, EffectColumn, ReadBackColumn, ColumnCount };
    enum Role : int {
        KeyRole = Qt::UserRole + 1, // QString setting key
        AvailableRole,              // bool
        CanonicalRole,              // QString canonical value (Device / New columns)
        ChoicesRole,                // QStringList of canonical values a combo offers (empty: free text)
        ChoiceLabelsRole,           // QStringList, the same order
        PendingRole,                // bool: the row has a new value that differs from the device
    };

    explicit SettingsTableModel(QObject *parent = nullptr);

    // The device's values (after a read); pending values equal to them are dropped.
    void setConfiguration(const settings::DeviceConfiguration &config);
    const settings::DeviceConfiguration &configuration() const { return m_config; }
    // Sets a new value by key; false and lastError() when refused.
    bool setPending(const QString &key, const QString &value);
    std::vector<settings::ConfigurationController::Change> pendingChanges() const;
    void clearPending();
    QString lastError() const { return m_lastError; }
    int rowOfKey(const QString &key) const;
    void retranslate();

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    int columnCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

Q_SIGNALS:
    void pendingChanged();

private:
    bool available(int row) const;
    settings::DeviceConfiguration m_config;
    std::map<QString, QString> m_pending; // key -> canonical
    QString m_lastError;
};

} // namespace imudesk::models
