#pragma once
// Applies one profile to several devices in turn (provisioning a batch): for each port it
// connects (auto-detecting the baud unless one is given), reads the device, applies the
// differences with read-back verification, saves them when asked, and reports the
// device's serial number and the result before going on to the next port.
#include "settings/config_profile.h"

#include <QObject>
#include <QStringList>

#include <memory>
#include <vector>

namespace imudesk::device {
class DeviceSession;
}

namespace imudesk::settings {

class ProfileBatch : public QObject {
    Q_OBJECT
public:
    struct DeviceReport {
        QString port;
        QString serial;
        QString product;
        bool ok = false;
        int changed = 0;            // settings applied and verified
        QStringList problems;       // what failed or could not be applied
        // Not ok only because the module's read-back did not confirm some settings (none was
        // refused or held at another value).
        bool onlyUnconfirmed = false;
    };

    ProfileBatch(ConfigProfile profile, QStringList ports, QObject *parent = nullptr);
    ~ProfileBatch() override;
    void setBaud(int baud) { m_baud = baud; }       // 0: auto-detect
    void setSave(bool save) { m_save = save; }      // SAVECONFIG after a verified apply
    void start();
    const std::vector<DeviceReport> &reports() const { return m_reports; }
    bool running() const { return m_running; }

Q_SIGNALS:
    void deviceStarted(const QString &port);
    void deviceFinished(const imudesk::settings::ProfileBatch::DeviceReport &report);
    void finished();

private:
    void next();
    void onConnected();
    void onRead(bool ok, const QString &error);
    void onApplied(const ConfigurationController::ApplyReport &report);
    void finishDevice();

    ConfigProfile m_profile;
    QStringList m_ports;
    int m_baud = 0;
    bool m_save = false;
    bool m_running = false;
    bool m_deviceDone = false;
    int m_index = -1;
    DeviceReport m_current;
    std::unique_ptr<device::DeviceSession> m_session;
    std::unique_ptr<ConfigurationController> m_controller;
    std::vector<DeviceReport> m_reports;
};

} // namespace imudesk::settings

Q_DECLARE_METATYPE(imudesk::settings::ProfileBatch::DeviceReport)
