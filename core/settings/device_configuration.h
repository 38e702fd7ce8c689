#pragma once
// What one device holds: its identity and the canonical value of every setting it
// reported in LOG COMCONFIG (core/settings/setting_catalog.h for the value forms).
#include "model/device_identity.h"

#include <QString>
#include <QStringList>

#include <map>
#include <optional>
#include <string>

namespace imudesk::settings {

struct DeviceConfiguration {
    model::DeviceIdentity identity;
    std::map<QString, QString> values; // setting key -> canonical value
    QStringList unreadable;            // COMCONFIG lines no setting could understand ("KEY=VALUE")
    QStringList rawLines;              // the LOG COMCONFIG reply as it came (before OK)

    // From the KEY=VALUE lines of a LOG COMCONFIG reply. Settings the device's edition or
    // family does not have are ignored.
    static DeviceConfiguration fromComConfig(const model::DeviceIdentity &identity,
                                             const std::map<std::string, std::string> &keyValues);
    std::optional<QString> value(const QString &key) const;
    bool empty() const { return values.empty(); }
};

} // namespace imudesk::settings
