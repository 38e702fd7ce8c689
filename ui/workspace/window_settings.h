#pragma once
// What the main window remembers between runs. Only main.cpp and MainWindow's owner
// create the QSettings object; widgets get and return this struct.
#include <QByteArray>
#include <QString>

class QSettings;

namespace imudesk::ui {

struct WindowSettings {
    // Bump the version in the keys when a value changes meaning; old keys are then ignored.
    // v2: the attitude view in a dock of its own, layout presets; a v1 layout is not restored.
    static constexpr int kVersion = 2;
    static constexpr const char *kGeometryKey = "ui/v2/mainWindow/geometry";
    static constexpr const char *kStateKey = "ui/v2/mainWindow/state";
    static constexpr const char *kWorkspaceStateKey = "ui/v2/workspace/state"; // docks of a device tab
    static constexpr const char *kPresetKey = "ui/v2/workspace/preset"; // DeviceWorkspace::presetKey()
    static constexpr const char *kPortKey = "ui/v1/connection/port"; // PortChoice::key()
    static constexpr const char *kBaudKey = "ui/v1/connection/baud"; // 0 = auto

    QByteArray geometry;    // QWidget::saveGeometry()
    QByteArray windowState; // QMainWindow::saveState(kVersion)
    QByteArray workspaceState; // DeviceWorkspace::saveLayout()
    QString preset;            // DeviceWorkspace::presetKey(); empty = Monitor
    QString port;
    int baud = 0;

    void load(QSettings &settings);
    void save(QSettings &settings) const;
};

} // namespace imudesk::ui
