#pragma once
// Configuration profiles: save the connected device's configuration to a JSON file, load
// one and see the differences with the device (a table: setting, profile, device, note),
// apply them with read-back verification, or apply the profile to several ports in turn
// with a report per device (port, serial number, product, result).
#include "settings/config_profile.h"
#include "settings/profile_batch.h"

#include <QDialog>

#include <memory>
#include <optional>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace imudesk::device {
class DeviceSession;
}

namespace imudesk::ui {

class ProfileDialog : public QDialog {
    Q_OBJECT
public:
    explicit ProfileDialog(device::DeviceSession &session, QWidget *parent = nullptr);
    ~ProfileDialog() override;

    // Reads the device (the table compares against what it holds).
    void readDevice();
    bool saveProfile(const QString &path, QString *error = nullptr);
    bool loadProfile(const QString &path, QString *error = nullptr);
    void applyToDevice();
    // Applies the loaded profile to these ports in turn (not the connected one), with SAVECONFIG.
    void applyToPorts(const QStringList &ports, bool save = true);

    settings::ConfigurationController &controller() { return *m_controller; }
    QTableWidget *diffTable() const { return m_diff; }
    QTableWidget *batchTable() const { return m_batchTable; }
    QString statusText() const;

Q_SIGNALS:
    void batchFinished();

private:
    void refreshDiff();
    void onSaveClicked();
    void onLoadClicked();

    std::unique_ptr<settings::ConfigurationController> m_controller;
    std::optional<settings::ConfigProfile> m_profile;
    std::unique_ptr<settings::ProfileBatch> m_batch;
    QLabel *m_status = nullptr;
    QTableWidget *m_diff = nullptr;
    QTableWidget *m_batchTable = nullptr;
    QLineEdit *m_ports = nullptr;
    QPushButton *m_apply = nullptr;
    QPushButton *m_applyPorts = nullptr;
};

} // namespace imudesk::ui
