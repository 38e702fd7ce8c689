#pragma once
// A configuration profile: the settings of one device saved as JSON, to be compared with
// and applied to others (provisioning a batch). Format:
//   {"format": "imudesk-profile", "version": 1,
//    "device": {"product": "HI14R3", "firmware": "1.7.1", "serial": "..."},
//    "settings": {"ATT.MODE": "1", "IMU.URFR": "24", "LOG.HI91": "0.01", ...}}
// Keys and values are those of SettingCatalog (canonical text). The loader refuses files
// over kMaxBytes, unknown keys, values of the wrong type or out of every edition's range.
#include "settings/configuration_controller.h"
#include "settings/device_configuration.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

#include <map>
#include <optional>
#include <vector>

namespace imudesk::settings {

class ConfigProfile {
    Q_DECLARE_TR_FUNCTIONS(ConfigProfile)

public:
    static constexpr qint64 kMaxBytes = 256 * 1024;
    static constexpr int kVersion = 1;

    struct Difference {
        QString key;
        QString profileValue;
        QString deviceValue;  // empty when the device did not report the setting
        bool applicable = true; // false: the device's model or firmware does not have it
        QString note;
    };

    QString product, firmware, serial; // where it was taken from (information only)
    std::map<QString, QString> settings;

    // The settings of a device that belong in a profile (LOG ENABLE/DISABLE is not saved).
    static ConfigProfile fromConfiguration(const DeviceConfiguration &config);
    QByteArray toJson() const;
    static std::optional<ConfigProfile> fromJson(const QByteArray &json, QString *error);
    bool save(const QString &path, QString *error) const;
    static std::optional<ConfigProfile> load(const QString &path, QString *error);

    // Every setting whose value differs from the device's, in catalog order.
    std::vector<Difference> diff(const DeviceConfiguration &device) const;
    // The changes that make the device match (differences the device can take).
    std::vector<ConfigurationController::Change> changesFor(const DeviceConfiguration &device) const;
};

} // namespace imudesk::settings
