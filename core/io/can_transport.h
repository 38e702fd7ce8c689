#pragma once
// A CAN interface through Qt's QCanBus plug-ins (socketcan, virtualcan, peakcan, ...) as a
// session transport: frames in and out as protocol::can records (can_record.h), so that the
// session engine treats a bus like any other byte link. The address is "plugin:interface"
// ("virtualcan:can0"), the rate the bit rate (0: leave the interface's setting). Lives in
// the session's worker thread: every CAN session shares one (canThread()), because the
// virtualcan plug-in keeps its bus server in the thread of the first device opened.
#include "io/transport.h"

#include <QString>
#include <QThread>

#include <memory>

QT_BEGIN_NAMESPACE
class QCanBusDevice;
QT_END_NAMESPACE

namespace imudesk::io {

// A CAN bus as the user names it, "plugin:interface": the first colon ends the plug-in's name,
// so that an interface may hold colons of its own ("virtualcan:tcp://127.0.0.1:24500/can0").
// Without a colon the whole text is the plug-in's name.
struct CanAddress {
    QString plugin;
    QString interfaceName;
    static CanAddress parse(const QString &address);
    // Both parts given (what --can and the bus fields require).
    bool complete() const { return !plugin.isEmpty() && !interfaceName.isEmpty(); }
};

// The thread every CAN session's engine lives in (started on first use, stopped when the
// application object is destroyed).
QThread *canThread();

class CanTransport : public Transport {
    Q_OBJECT
public:
    explicit CanTransport(QObject *parent = nullptr);
    ~CanTransport() override;

    // For the next open: CAN FD with this data-phase bit rate (0: the interface's).
    void setFd(bool fd, int dataBitrate)
    {
        m_fd = fd;
        m_dataBitrate = dataBitrate;
    }

    bool open(const QString &address, int bitrate, QString *error) override;
    void close() override;
    // Open: frames can go out. While the interface is still connecting (virtualcan's TCP link
    // to its bus server) they wait, kBacklogBytes of records at most, and leave in order once connected.
    bool isOpen() const override;
    static constexpr qsizetype kBacklogBytes = 256 * 1024;
    // A new bit rate needs the interface reopened: not done under a running session.
    bool setBaud(int bitrate) override { return bitrate == m_bitrate; }
    int baud() const override { return m_bitrate; }
    QString address() const override { return m_address; }
    // Whole records only; each becomes one frame. The answer is bytes.size() when all went out.
    qint64 write(const QByteArray &records) override;
    void clear() override {}
    bool reopen(int bitrate, QString *error) override { return open(m_address, bitrate, error); }

private:
    void onFramesReceived();
    void sendBacklog();

    std::unique_ptr<QCanBusDevice> m_bus;
    QString m_address;
    int m_bitrate = 0;
    bool m_fd = false;
    int m_dataBitrate = 0;
    QByteArray m_backlog; // records written while connecting
};

} // namespace imudesk::io
