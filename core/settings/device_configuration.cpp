#include "device_configuration.h"

#include "settings/setting_catalog.h"

namespace imudesk::settings {

DeviceConfiguration DeviceConfiguration::fromComConfig(const model::DeviceIdentity &identity,
                                                       const std::map<std::string, std::string> &keyValues)
{
    DeviceConfiguration c;
    c.identity = identity;
    for (const auto &[key, raw] : keyValues) {
        const SettingDefinition *def = nullptr;
        for (const auto &d : SettingCatalog::settings())
            if (key == d.comConfigKey && SettingCatalog::availability(d, identity).available) {
                def = &d;
                break;
            }
        const auto v = def ? SettingCatalog::fromComConfig(*def, raw) : std::nullopt;
        if (v)
            c.values[QLatin1String(def->key)] = *v;
        else
            c.unreadable << QString::fromStdString(key + "=" + raw);
    }
    return c;
}

std::optional<QString> DeviceConfiguration::value(const QString &key) const
{
    const auto it = values.find(key);
    if (it == values.end())
        return std::nullopt;
    return it->second;
}

} // namespace imudesk::settings
