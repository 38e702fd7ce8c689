#include "workspace/window_settings.h"

#include "links/serial_family.h"

#include <QSettings>

#include <algorithm>

namespace imudesk::ui {

namespace {
QString key(const char *k)
{
    return QString::fromLatin1(k);
}
} // namespace

void WindowSettings::load(QSettings &settings)
{
    geometry = settings.value(key(kGeometryKey)).toByteArray();
    windowState = settings.value(key(kStateKey)).toByteArray();
    workspaceState = settings.value(key(kWorkspaceStateKey)).toByteArray();
    preset = settings.value(key(kPresetKey)).toString();
    port = settings.value(key(kPortKey)).toString();
    bool ok = false;
    const int b = settings.value(key(kBaudKey), 0).toInt(&ok);
    const auto &rates = device::serialDetectionBauds();
    baud = ok && std::find(rates.begin(), rates.end(), b) != rates.end() ? b : 0;
}

void WindowSettings::save(QSettings &settings) const
{
    settings.setValue(key(kGeometryKey), geometry);
    settings.setValue(key(kStateKey), windowState);
    settings.setValue(key(kWorkspaceStateKey), workspaceState);
    settings.setValue(key(kPresetKey), preset);
    settings.setValue(key(kPortKey), port);
    settings.setValue(key(kBaudKey), baud);
}

} // namespace imudesk::ui
