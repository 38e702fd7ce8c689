#pragma once
// firmware::CanFrameLink on a QCanBusDevice (plugin, interface, bit rate as CanSession takes
// them). Create, open and use it in one thread (the update's worker thread): receive() and
// sleepMs() run a local event loop so the plugin's notifications arrive.
#include "io/can_frame_link.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <deque>
#include <memory>

QT_BEGIN_NAMESPACE
class QCanBusDevice;
QT_END_NAMESPACE

namespace imudesk::firmware {

class QtCanFrameLink : public CanFrameLink {
    Q_DECLARE_TR_FUNCTIONS(QtCanFrameLink)

public:
    static constexpr int kConnectTimeoutMs = 3000;
    static constexpr size_t kMaxQueued = 100000; // frames not yet read; older ones are dropped beyond

    // bitrate 0: leave the interface's bit rate as configured.
    QtCanFrameLink(QString plugin, QString interfaceName, int bitrate);
    ~QtCanFrameLink() override;

    bool open(QString *error) override;
    void close() override;
    bool isOpen() const override;
    bool send(const protocol::can::CanFrame &frame, QString *error) override;
    bool receive(std::vector<protocol::can::CanFrame> &out, int timeoutMs, QString *error) override;
    void clearInput() override;
    void sleepMs(int ms) override;
    int64_t nowUs() const override;

private:
    void drain();
    bool connectedOrError(QString *error) const;

    QString m_plugin, m_interface;
    int m_bitrate = 0;
    std::unique_ptr<QCanBusDevice> m_bus;
    std::deque<protocol::can::CanFrame> m_queue;
    QElapsedTimer m_clock;
};

} // namespace imudesk::firmware
