#include "config_profile.h"

#include "settings/setting_catalog.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

namespace imudesk::settings {

namespace {
constexpr int kMaxSettings = 256;
}

ConfigProfile ConfigProfile::fromConfiguration(const DeviceConfiguration &config)
{
    ConfigProfile p;
    p.product = QString::fromStdString(config.identity.productName);
    p.firmware = config.identity.firmware ? QString::fromStdString(config.identity.firmware->toString()) : QString();
    p.serial = QString::fromStdString(config.identity.serial);
    for (const auto &[key, value] : config.values) {
        const SettingDefinition *d = SettingCatalog::find(key);
        if (d && d->inProfile)
            p.settings[key] = value;
    }
    return p;
}

QByteArray ConfigProfile::toJson() const
{
    QJsonObject device;
    device[QStringLiteral("product")] = product;
    device[QStringLiteral("firmware")] = firmware;
    device[QStringLiteral("serial")] = serial;
    QJsonObject values;
    for (const auto &[key, value] : settings)
        values[key] = value;
    QJsonObject root;
    root[QStringLiteral("format")] = QStringLiteral("imudesk-profile");
    root[QStringLiteral("version")] = kVersion;
    root[QStringLiteral("device")] = device;
    root[QStringLiteral("settings")] = values;
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::optional<ConfigProfile> ConfigProfile::fromJson(const QByteArray &json, QString *error)
{
    auto refuse = [error](const QString &why) -> std::optional<ConfigProfile> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (json.size() > kMaxBytes)
        return refuse(tr("the profile is larger than %1 KiB: not an ImuDesk profile").arg(kMaxBytes / 1024));
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (pe.error != QJsonParseError::NoError)
        return refuse(tr("the profile is not valid JSON (%1 at byte %2)").arg(pe.errorString()).arg(pe.offset));
    if (!doc.isObject())
        return refuse(tr("the profile must be a JSON object"));
    const QJsonObject root = doc.object();
    if (root.value(QStringLiteral("format")).toString() != QLatin1String("imudesk-profile"))
        return refuse(tr("not an ImuDesk profile (\"format\" must be \"imudesk-profile\")"));
    const QJsonValue version = root.value(QStringLiteral("version"));
    if (!version.isDouble() || version.toDouble() != kVersion)
        return refuse(tr("profile version %1 is not supported (this ImuDesk reads version %2)")
                          .arg(version.toVariant().toString())
                          .arg(kVersion));
    ConfigProfile p;
    const QJsonValue device = root.value(QStringLiteral("device"));
    if (!device.isUndefined()) {
        if (!device.isObject())
            return refuse(tr("\"device\" must be an object"));
        const QJsonObject d = device.toObject();
        p.product = d.value(QStringLiteral("product")).toString().left(64);
        p.firmware = d.value(QStringLiteral("firmware")).toString().left(32);
        p.serial = d.value(QStringLiteral("serial")).toString().left(64);
    }
    const QJsonValue settings = root.value(QStringLiteral("settings"));
    if (!settings.isObject())
        return refuse(tr("\"settings\" must be an object of \"KEY\": \"VALUE\""));
    const QJsonObject s = settings.toObject();
    if (s.size() > kMaxSettings)
        return refuse(tr("too many settings (%1)").arg(s.size()));
    for (auto it = s.begin(); it != s.end(); ++it) {
        const SettingDefinition *d = SettingCatalog::find(it.key());
        if (!d || !d->inProfile)
            return refuse(tr("unknown setting '%1' in the profile").arg(it.key()));
        QString text;
        if (it.value().isString())
            text = it.value().toString();
        else if (it.value().isDouble())
            text = QString::number(it.value().toDouble(), 'g', 12);
        else
            return refuse(tr("the value of %1 must be a string").arg(it.key()));
        QString why;
        const auto v = SettingCatalog::normalize(*d, text, nullptr, &why);
        if (!v)
            return refuse(why);
        p.settings[QLatin1String(d->key)] = *v;
    }
    return p;
}

bool ConfigProfile::save(const QString &path, QString *error) const
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(toJson()) < 0 || !f.commit()) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

std::optional<ConfigProfile> ConfigProfile::load(const QString &path, QString *error)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("cannot read %1: %2").arg(path, f.errorString());
        return std::nullopt;
    }
    if (f.size() > kMaxBytes) {
        if (error)
            *error = tr("%1 is larger than %2 KiB: not an ImuDesk profile").arg(path).arg(kMaxBytes / 1024);
        return std::nullopt;
    }
    QString why;
    auto p = fromJson(f.read(kMaxBytes + 1), &why);
    if (!p && error)
        *error = tr("%1: %2").arg(path, why);
    return p;
}

std::vector<ConfigProfile::Difference> ConfigProfile::diff(const DeviceConfiguration &device) const
{
    std::vector<Difference> out;
    for (const auto &d : SettingCatalog::settings()) {
        const QString key = QLatin1String(d.key);
        const auto want = settings.find(key);
        if (want == settings.end())
            continue;
        const auto have = device.value(key);
        if (have && *have == want->second)
            continue;
        Difference diff{key, want->second, have.value_or(QString()), true, {}};
        const auto a = SettingCatalog::availability(d, device.identity);
        if (!a.available) {
            diff.applicable = false;
            diff.note = a.reason;
        } else {
            QString error;
            if (SettingCatalog::commands(d, want->second, device.identity, &error).empty()) {
                diff.applicable = false;
                diff.note = error;
            }
        }
        out.push_back(diff);
    }
    return out;
}

std::vector<ConfigurationController::Change> ConfigProfile::changesFor(const DeviceConfiguration &device) const
{
    std::vector<ConfigurationController::Change> out;
    for (const Difference &d : diff(device))
        if (d.applicable)
            out.push_back({d.key, d.profileValue});
    return out;
}

} // namespace imudesk::settings
