#pragma once
// What the main window remembers between runs. Only main.cpp and MainWindow's owner
// create the QSettings object; widgets get and return this struct.
#include <QByteArray>
#include <QString>

class QSettings;

namespace imudesk::ui {

struct WindowSettings {
    // Bump the version in the keys when a value changes meaning; old keys are then ignored.
    static constexpr int kVersion = 1;
    static constexpr const char *kGeometryKey = "ui/v1/mainWindow/geometry";
    static constexpr const char *kStateKey = "ui/v1/mainWindow/state";
    static constexpr const char *kWorkspaceStateKey = "ui/v1/workspace/state"; // docks of a device tab
    static constexpr const char *kPortKey = "ui/v1/connection/port"; // PortChoice::key()
    static constexpr const char *kBaudKey = "ui/v1/connection/baud"; // 0 = auto

    QByteArray geometry;    // QWidget::saveGeometry()
    QByteArray windowState; // QMainWindow::saveState(kVersion)
    QByteArray workspaceState; // DeviceWorkspace::saveLayout()
    QString port;
    int baud = 0;

    void load(QSettings &settings);
    void save(QSettings &settings) const;
};

} // namespace imudesk::ui
