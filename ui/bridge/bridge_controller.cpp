#include "bridge_controller.h"

#include <QLocale>

#include <set>

namespace imudesk::ui {

BridgeController::BridgeController(std::function<std::vector<BridgedLink>()> links, QObject *parent)
    : QObject(parent), m_links(std::move(links))
{
    m_sync.setInterval(1000);
    connect(&m_sync, &QTimer::timeout, this, &BridgeController::syncDevices);
    connect(&m_bridge, &bridge::LiveBridge::statsChanged, this, [this] { Q_EMIT statusChanged(statusText()); });
}

BridgeController::~BridgeController()
{
    m_bridge.stop();
}

bool BridgeController::start(const bridge::BridgeOptions &options, QString *error)
{
    if (!m_bridge.start(options, error))
        return false;
    syncDevices();
    m_sync.start();
    Q_EMIT runningChanged(true);
    Q_EMIT statusChanged(statusText());
    return true;
}

void BridgeController::stop()
{
    if (!m_bridge.isRunning())
        return;
    m_sync.stop();
    m_bridge.stop();
    for (const auto &[key, store] : m_devices)
        m_bridge.removeDevice(key);
    m_devices.clear();
    Q_EMIT runningChanged(false);
    Q_EMIT statusChanged(QString());
}

void BridgeController::syncDevices()
{
    if (!m_bridge.isRunning())
        return;
    std::set<const device::SampleStore *> present;
    for (const BridgedLink &shown : m_links()) {
        const device::DeviceLink &link = *shown.link;
        if (!link.isLive() || link.linkKind().isEmpty() || link.state() != device::SessionState::Connected)
            continue;
        std::shared_ptr<device::SampleStore> store = link.sharedStore();
        present.insert(store.get());
        if (m_devices.count(store.get()))
            continue;
        // Named by capture::deviceName (its serial, else family and address): never by the tab's
        // title, which names the port and differs per run.
        capture::CaptureHeader header;
        if (shown.identity)
            header.setIdentity(*shown.identity);
        header.set(capture::CaptureHeader::kLinkKind, link.linkKind().toStdString());
        link.describeLink(header);
        m_bridge.addDevice(store, header);
        m_devices.emplace(store.get(), std::move(store));
    }
    for (auto it = m_devices.begin(); it != m_devices.end();) {
        if (present.count(it->first)) {
            ++it;
            continue;
        }
        m_bridge.removeDevice(it->first);
        it = m_devices.erase(it);
    }
}

QString BridgeController::statusText() const
{
    if (!m_bridge.isRunning())
        return {};
    const bridge::BridgeStats s = m_bridge.stats();
    const QLocale locale;
    QStringList parts;
    if (m_bridge.options().websocket)
        parts << tr("Live bridge %1").arg(m_bridge.url()) << tr("clients: %1").arg(s.clients)
              << tr("sent: %1").arg(locale.toString(qulonglong(s.messagesSent)))
              << tr("dropped: %1").arg(locale.toString(qulonglong(s.messagesDropped)));
    else
        parts << tr("Live bridge");
    if (m_bridge.options().udp)
        parts << tr("UDP: %1").arg(locale.toString(qulonglong(s.datagramsSent)));
    return parts.join(QStringLiteral(" · "));
}

} // namespace imudesk::ui
