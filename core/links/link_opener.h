#pragma once
// The one way a link is opened, for the window and the CLI alike: a link request (a serial port
// at a baud or Auto, of a known family or not; a Modbus RTU device; a CAN bus; a capture file)
// becomes an opened device::DeviceLink of the right family.
//
// A serial port whose family is not given is opened once: a session whose family plug-in is
// the detection (SerialFamilyScan) scans the rates on it, and the port, still open, goes to the
// found family's session at the rate found. The serial families are plug-ins
// (serial_family.h); nothing here names one. Nothing blocks: ready() or failed() follows from
// the event loop.
#include "device/can_session_types.h"
#include "device/device_link.h"
#include "device/modbus_types.h"
#include "links/serial_family.h"
#include "io/transport.h"
#include "record/replay_group.h"
#include "sim/hipnuc_simulator.h"
#include "sim/motion_model.h"

#include <QObject>
#include <QString>

#include <any>
#include <functional>
#include <memory>

namespace imudesk::sim {
class PtySimulator;
}

namespace imudesk::device {

class Session;

struct LinkRequest {
    enum class Kind { Serial, Modbus, Can, Capture };
    Kind kind = Kind::Serial;
    QString address;                              // serial port, or the capture file
    int baud = 0;                                 // serial: 0 = Auto
    QString family;                               // serial: a SerialFamilyKind's id; empty = detect it
    int deviceAddress = 0;                        // serial: a polled device's bus address
    bool autoReconnect = true;                    // serial: wait for an unplugged device to return
    ModbusOptions modbus;
    CanSessionOptions can;
    // A simulated device first, as the link's far end (a serial family's device or a Modbus
    // device on a pseudo-terminal, a CAN device on the same bus), moving as `motion`.
    bool simulate = false;
    sim::Motion motion = sim::Motion::Static;
    // A simulated serial device's own options, as its family takes them (HiPNUC:
    // sim::SimOptions, with a motion of their own); empty: the family's defaults.
    std::any simulator;
    // What the link needs (its simulator): handed on with the link, released after it.
    std::shared_ptr<void> keepAlive;
    // A capture of a multi-device session: its place on the session's timeline and the group
    // of replays it plays with (record/replay_group.h); null: a capture of its own.
    record::ReplayTimeline replay;
    std::shared_ptr<record::ReplayGroup> replayGroup;
    // A serial link's transport (tests: an in-process simulator); null: the serial port.
    std::function<std::unique_ptr<io::Transport>()> transport;

    static LinkRequest serial(const QString &port, int baud = 0, const QString &family = {});
    static LinkRequest modbusDevice(const ModbusOptions &options);
    static LinkRequest canBus(const CanSessionOptions &options);
    static LinkRequest capture(const QString &path);
    // A serial family's simulated device on a pseudo-terminal (options: as the family takes
    // them, empty for its defaults), connected at baud (0: as the family finds it).
    static LinkRequest simulatedSerial(const QString &family, sim::Motion motion, std::any options = {}, int baud = 0);
    // Conveniences for the built-in families: a simulated HEC495 streaming at 50 Hz; a
    // simulated HiPNUC module connected at baud (0: detected).
    static LinkRequest simulatedHec495(sim::Motion motion);
    static LinkRequest simulatedHipnuc(const sim::SimOptions &options, int baud);
};

class LinkOpener : public QObject {
    Q_OBJECT
public:
    explicit LinkOpener(QObject *parent = nullptr);
    ~LinkOpener() override;

    // Starts opening (a request under way is dropped). ready() or failed() follows.
    void open(LinkRequest request);
    // Stops a detection under way (no signal follows) and closes its port.
    void cancel();
    bool running() const { return m_running; }

    // What ready() announces: the link of the right family, not yet started (OpenedLink).
    using Opened = OpenedLink;
    Opened take();
    // A request that needs no detection (anything but a serial port of unknown family), at
    // once: its simulator started, its link made. On failure no link, and `error` says why.
    static Opened openNow(LinkRequest &request, QString *error);
    // The request that was opened (for a serial Auto request: family and baud as found).
    const LinkRequest &request() const { return m_request; }
    // After failed(): the bytes a serial detection heard without finding a family (0: silence).
    quint64 bytesHeard() const { return m_bytesHeard; }

Q_SIGNALS:
    // Detection progress ("trying 115200 baud").
    void detecting(const QString &detail);
    void ready();
    // Nothing usable answered, or the port could not be opened: what happened and what to do.
    void failed(const QString &message);

private:
    void onFound(const QString &family, int baud, int address);
    void finish(Opened opened);

    LinkRequest m_request;
    std::unique_ptr<Session> m_probe;
    Opened m_opened;
    bool m_running = false;
    quint64 m_bytesHeard = 0;
};

// Starts a simulated serial device and points r at it (address, keepAlive; never waited for
// when unplugged: a pty's number is reused). failure: the message, %1 the reason.
bool startOnPty(LinkRequest &r, std::shared_ptr<sim::PtySimulator> simulator, const QString &failure, QString *error);

} // namespace imudesk::device
