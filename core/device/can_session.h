#pragma once
// A device on a CAN bus (HiPNUC J1939, HiPNUC CANopen, HEC495 CAN): the typed front-end of a
// Session (session.h) whose transport is io::CanTransport and whose family plug-in is
// CanFamily (can_family.h: decoding, node discovery, the steps of a job). The engine runs in
// the process-wide CAN thread (io::canThread()); this object's API is queued and safe to call
// from the owner's thread. Configuration calls return a request id; the outcome arrives in
// requestFinished, confirmed by the device's reply or by reading the value back.
#include "can_job.h"
#include "can_session_types.h"
#include "device/session.h"
#include "protocol/can/can_setting_catalog.h"

#include <QStringList>

#include <atomic>

namespace imudesk::device {

class CanSession : public Session {
    Q_OBJECT
public:
    // CANopen output on/off (NMT) is confirmed by watching the target's TPDOs: after a stop
    // none may come in kNmtConfirmMs (after kNmtSettleMs for frames already sent); after a
    // start one must.
    static constexpr int kNmtSettleMs = 100;
    static constexpr int kNmtConfirmMs = 1500;

    // transport: a QCanBus interface when null.
    explicit CanSession(QObject *parent = nullptr, std::unique_ptr<io::Transport> transport = nullptr);
    ~CanSession() override;

    // What Qt offers: plugin names, and a plugin's interfaces ("can0", ...).
    static QStringList plugins();
    static QStringList interfaces(const QString &plugin, QString *error = nullptr);

    void open(const CanSessionOptions &options);
    QString linkKind() const override;
    void describeLink(capture::CaptureHeader &header) const override;
    // Frames, not bytes: the CAN monitor shows them (no raw bytes).
    Capabilities capabilities() const override { return {}; }

    const CanSessionOptions &options() const { return m_options; }
    protocol::can::CanProtocol protocol() const; // the configured one, else the detected one
    int targetNode() const { return m_target.load(); }

    // Raw access. J1939 to node 255 (the broadcast address): every node answers within the
    // request timeout, each answer in the result's answers.
    quint64 readRegister(uint16_t addr);                  // J1939
    quint64 writeRegister(uint16_t addr, uint32_t value); // J1939, confirmed by the echo
    quint64 sdoRead(uint16_t index, uint8_t sub);         // CANopen
    quint64 sdoWrite(uint16_t index, uint8_t sub, uint32_t value, int size);
    quint64 hec495Write(uint16_t index, uint8_t value);

    // A setting of the device's catalogue (protocol/can/can_setting_catalog.h), by its request:
    // readSetting reads the module's value (the result's value is the raw code); writeSetting
    // writes the raw code and reads it back, failing with both values when they differ. A
    // setting the manual gives no read for (HEC495) is confirmed by the module's write reply
    // only (the result's message says so); reading one is refused with that reason.
    quint64 readSetting(const protocol::can::CanSetting &setting);
    quint64 writeSetting(const protocol::can::CanSetting &setting, uint32_t raw);
    // The catalogue of the session's protocol (configured or detected), with the node-ID object
    // of its firmware.
    std::vector<protocol::can::CanSetting> settingsCatalogue() const;

    // Configuration (all protocols where the device has it).
    quint64 setOutputPeriod(uint32_t pgnOrChannel, int ms); // J1939: data PGN; CANopen: TPDO channel 0..5
    quint64 setHec495Rate(int code);
    quint64 setSyncMode(int channel, bool sync);
    quint64 setHeartbeat(int ms);                          // HEC495: the nearest 100 ms * (N + 1), 100..25600 ms
    quint64 setNodeId(int newId);
    // The bit rates the module's own setting takes (setBitrate), fastest first.
    static QList<int> moduleBitrates(protocol::can::CanProtocol protocol, bool hec495Extended = false);
    quint64 setBitrate(int bitrate);
    quint64 attitudeReset(int mode);
    quint64 setOutputEnabled(bool on);
    // NMT start / stop to node 0: CANopen, and the HEC495's "all nodes" PDO start/stop (not saved).
    quint64 setAllNodesOutput(bool on);
    // Inclinometer axis direction (axis 0 = X, 1 = Y): J1939 0x9E/0x9F, CANopen 0x209E/0x209F; read back.
    quint64 setInclinometerSign(int axis, bool reversed);
    // HEC495: PDO mode 0x1080 (0 float, 1 fixed point, 3 float 0x180/0x280 only; extended variant
    // 0 = message one, 1 = messages one and two) and work mode 0x6245 (0x02 default, 0x0A rate at 500 Hz).
    quint64 setHec495PdoMode(int mode);
    quint64 setHec495WorkMode(int mode);
    quint64 save();
    quint64 reset();
    quint64 factoryReset();
    quint64 trigger(uint32_t pgn);                         // J1939 one-shot output

    void sendSync();
    void setSyncPeriod(int ms);                            // 0 = off
    void sendNmt(uint8_t command, uint8_t node);
    void sendFrame(const protocol::can::CanFrame &f);
    void scanNodes(int from = 1, int to = 127);
    void cancelScan();

Q_SIGNALS:
    void requestFinished(const imudesk::device::CanRequestResult &result);
    void framesSeen(const imudesk::device::CanFrameEvents &events);
    void nodeDiscovered(const imudesk::device::CanNodeInfo &info);
    void protocolDetected(int protocol);
    void targetNodeChanged(int node);
    void scanProgress(int done, int total);
    void scanFinished(const QList<int> &nodes, bool cancelled);

private:
    quint64 submitJob(CanJob job);
    quint64 refuseJob(const QString &why);
    uint8_t node() const;
    CanJobStep j1939Write(uint16_t addr, uint32_t value, const QString &what) const;
    CanJobStep j1939Read(uint16_t addr, const QString &what) const;
    CanJobStep sdoWriteStep(uint16_t index, uint8_t sub, uint32_t value, int size, const QString &what) const;
    CanJobStep sdoReadStep(uint16_t index, uint8_t sub, const QString &what) const;
    CanJobStep hecStep(uint16_t index, uint8_t value, const QString &what) const;
    // CANopen: reads the firmware version the module reports (0x1018:3, optional: a module
    // without it aborts) and hands it to `then` (nullopt: none reported) before the next step.
    using FirmwareAdapt = std::function<void(std::optional<uint32_t> revision, CanJob &job, size_t at)>;
    CanJobStep firmwareProbe(FirmwareAdapt then) const;
    // A firmwareProbe that points the job's later requests to a node-ID object at that
    // firmware's object (0x209C from 1.7, 0x20A0 on 1.6.6); a module that reports none keeps
    // the configured one (hipnucNodeIdObject).
    CanJobStep nodeIdObjectProbe() const;
    // A job of `action` (a write, an NMT command) confirmed by the target's data frames
    // starting (on) or stopping (off).
    quint64 outputJob(const QString &title, const CanJobStep &action, bool on);
    quint64 commandJob(uint32_t value, const QString &title, int followNode);

    CanSessionOptions m_options;
    std::atomic<int> m_target{-1};
    std::atomic<int> m_detected{0};
};

} // namespace imudesk::device
