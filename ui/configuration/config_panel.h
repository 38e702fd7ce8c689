#pragma once
// Device configuration panel bound to SettingsTableModel and a ConfigurationController
// over one DeviceSession: read all, edit (settings the model or firmware lacks are greyed
// out), apply (the pending commands are listed first and can be copied as the equivalent
// imudesk-cli line; each reply is shown after), save to flash, reboot, factory reset (a
// confirmation says what is lost), the attitude reset actions with their conditions, the
// v1.6.6 CONFIG YAW, the URFR mounting picker and the link load of the new output rates.
//
// Folder ui/configuration/: device settings. This ConfigPanel with its SettingValueDelegate,
// the URFR MountingPicker and its MountingTile pictures, the ProfileDialog and the
// Hec495SettingsPanel. It mirrors core/settings: ConfigurationController runs the flows over a
// DeviceSession, SettingCatalog describes each setting, MountingChoice picks the URFR code,
// ConfigProfile holds a profile and ProfileBatch applies it to several devices. The settings
// table is models::SettingsTableModel in a QTableView, edited through SettingValueDelegate; the
// HEC495 panel talks to its Hec495Session directly, without an item model.
#include "settings/configuration_controller.h"

#include "itemmodels/settings_table_model.h"

#include <QWidget>

#include <array>

#include <functional>
#include <map>
#include <memory>

class QLabel;
class QPlainTextEdit;
class QPushButton;
class QTableView;
class QComboBox;
class QDoubleSpinBox;

namespace imudesk::models {
class SettingsTableModel;
}

namespace imudesk::ui {

class ConfigPanel : public QWidget {
    Q_OBJECT
public:
    // (title, text) -> true to go ahead; the default asks with a QMessageBox.
    using ConfirmFn = std::function<bool(const QString &title, const QString &text)>;

    explicit ConfigPanel(device::DeviceSession &session, QWidget *parent = nullptr);
    ~ConfigPanel() override;

    // The port name used in the copied imudesk-cli line.
    void setPortName(const QString &port);
    void setConfirm(ConfirmFn confirm) { m_confirm = std::move(confirm); }

    settings::ConfigurationController &controller() { return *m_controller; }
    models::SettingsTableModel &model() { return *m_model; }
    QTableView *table() const { return m_table; }
    // "> CONFIG ..." lines of the pending changes, and the imudesk-cli line.
    QString pendingText() const;
    QString cliLine() const;
    QString replyLog() const;
    QString linkText() const;
    QPushButton *button(const QString &key) const; // "read", "apply", "save", "reboot", "freset", "mounting", "copy",
                                                   // "ATT.RST.1".."ATT.RST.5", "YAW"
    // The key, when a change takes effect and what reads it back: columns the user can show
    // from the header's context menu (hidden by default; their text is in each row's tooltip).
    static constexpr std::array<int, 3> kOptionalColumns{models::SettingsTableModel::KeyColumn,
                                                         models::SettingsTableModel::EffectColumn,
                                                         models::SettingsTableModel::ReadBackColumn};
    static constexpr const char *kShownColumnsKey = "ui/v1/configuration/shownColumns";
    void setColumnShown(int column, bool shown);

public Q_SLOTS:
    void readAll();
    void applyPending();
    void saveToFlash();
    void reboot();
    void factoryReset();
    void chooseMounting();
    void copyCliLine();
    void runAction(const QString &key);

protected:
    void changeEvent(QEvent *event) override;
    // Opening the panel on a connected device that has not been read yet reads it: the table
    // shows what the device holds without a press on Read all.
    void showEvent(QShowEvent *event) override;

private:
    void retranslateUi();
    void updateState();
    void updatePending();
    void log(const QString &line, bool error = false);
    // A line the module's read-back left open ("could not be read back"), in amber: not an
    // error like a refused or differing value (red), not a success either.
    void logUnsure(const QString &line);

    device::DeviceSession &m_session;
    std::unique_ptr<settings::ConfigurationController> m_controller;
    models::SettingsTableModel *m_model = nullptr;
    QString m_port;
    ConfirmFn m_confirm;

    QLabel *m_identity = nullptr;
    QTableView *m_table = nullptr;
    QPlainTextEdit *m_pending = nullptr;
    QPlainTextEdit *m_replies = nullptr;
    QLabel *m_link = nullptr;
    QLabel *m_cli = nullptr;
    QComboBox *m_yawMode = nullptr;
    QDoubleSpinBox *m_yawDeg = nullptr;
    std::map<QString, QPushButton *> m_buttons;
};

} // namespace imudesk::ui
