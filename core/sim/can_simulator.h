#pragma once
// Serves a CanSimDevice on a Qt CAN bus device (normally the "virtualcan" plugin, which needs
// no kernel module): frames from the bus go to the device, its answers and periodic frames go
// out. Lives in the thread that creates it; a 1 ms timer drives the schedule. If the bus
// connection drops (virtualcan's TCP server went away with another process) it reconnects.
#include "can_sim_device.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>
#include <memory>

QT_BEGIN_NAMESPACE
class QCanBusDevice;
QT_END_NAMESPACE

namespace imudesk::sim {

class CanSimulator : public QObject {
    Q_OBJECT
public:
    static constexpr int kTickMs = 1;

    explicit CanSimulator(CanSimOptions options, QObject *parent = nullptr);
    ~CanSimulator() override;

    // Opens plugin/interface (e.g. "virtualcan", "can0" or "tcp://localhost:24500/can0").
    bool start(const QString &plugin, const QString &interfaceName, QString *error = nullptr);
    void stop();
    bool isRunning() const;

    CanSimDevice &device() { return m_device; }
    uint64_t framesSent() const { return m_sent; }
    uint64_t framesReceived() const { return m_received; }
    double elapsedSeconds() const;
    // Simulates switching the module off and on (saved settings become active).
    void powerCycle();
    // Called for every frame handed to the bus, with the host's steady clock (clock::hostNowNs)
    // at that moment: the truth a test measures the receiving side's times against.
    void setSentObserver(std::function<void(const protocol::can::CanFrame &, int64_t hostNs)> observer)
    {
        m_sentObserver = std::move(observer);
    }

Q_SIGNALS:
    void connectedChanged(bool connected);

private:
    void onFramesReceived();
    void onTick();
    void onStateChanged(int state);
    void send(const std::vector<protocol::can::CanFrame> &frames);
    void applyBitrate();

    CanSimDevice m_device;
    std::unique_ptr<QCanBusDevice> m_bus;
    QTimer m_tick;
    QTimer m_reconnect;
    QElapsedTimer m_clock;
    int m_bitrate = 0;
    uint64_t m_sent = 0;
    uint64_t m_received = 0;
    std::function<void(const protocol::can::CanFrame &, int64_t)> m_sentObserver;
    bool m_stopping = false;
};

// The "simulate --can PLUGIN:INTERFACE" command line entry (app/cli uses it). atExit sees the
// device once the simulator has stopped (e.g. to dump its flash).
int runCanSimulatorCommand(const QString &canSpec, const QString &protocol, const QString &deviceKind, int node,
                           Motion motion, uint64_t seed, const QString &firmware, bool canFd, QString *error,
                           const std::function<bool()> &stopRequested,
                           const std::function<void(CanSimDevice &)> &atExit = {});

} // namespace imudesk::sim
