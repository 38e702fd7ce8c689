#pragma once
// Tools > Live bridge, the part without widgets: the bridge (core/bridge/live_bridge.h) fed with
// every tab's connected device, kept in step as tabs connect, disconnect and close (checked
// once a second and when the window says tabs changed), and the text of the window's status
// bar. A replayed capture is not bridged: its times are the recording's, not now.
#include "bridge/live_bridge.h"
#include "device/device_link.h"
#include "model/device_identity.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace imudesk::ui {

// A device the window shows: its link and what it said of itself (the workspace keeps the
// identity; the link's own signal has passed by the time the bridge starts).
struct BridgedLink {
    const device::DeviceLink *link = nullptr;
    std::optional<model::DeviceIdentity> identity;
};

class BridgeController : public QObject {
    Q_OBJECT
public:
    // links: every device the window shows now (the controller keeps the connected, live ones).
    explicit BridgeController(std::function<std::vector<BridgedLink>()> links, QObject *parent = nullptr);
    ~BridgeController() override;

    bridge::LiveBridge &bridge() { return m_bridge; }
    bool start(const bridge::BridgeOptions &options, QString *error);
    void stop();
    // Adds the tabs' connected devices, removes the ones gone.
    void syncDevices();
    // "Live bridge ws://127.0.0.1:8765 · 2 clients · 12 034 sent · 0 dropped"; empty when stopped.
    QString statusText() const;
    int deviceCount() const { return int(m_devices.size()); }

Q_SIGNALS:
    void statusChanged(const QString &text);
    void runningChanged(bool running);

private:
    std::function<std::vector<BridgedLink>()> m_links;
    bridge::LiveBridge m_bridge;
    QTimer m_sync;
    // The stores bridged (kept alive by the bridge while it reads them), by store.
    std::map<const device::SampleStore *, std::shared_ptr<device::SampleStore>> m_devices;
};

} // namespace imudesk::ui
