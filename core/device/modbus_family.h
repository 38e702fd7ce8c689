#pragma once
// A device on an RS-485 bus spoken to in Modbus RTU, as a session-engine family
// (family_plugin.h): HiPNUC v1.7.1 chapter 6 / v1.6.6 chapter 4, and the HEC495's
// "Modbus 通讯协议". The engine's serial transport carries the bytes; this plug-in frames the
// requests (protocol::modbus::RtuAdu: address, PDU, CRC-16), matches each reply to the request
// on the line by node, function and length, and runs what is Modbus-specific on top:
//   * identification (HiPNUC identity block 0x70..0x83; HEC495: one read of the angles),
//   * polling of the sensor block at a rate the line can carry (ModbusSession::maxPollRate),
//     one Sample per reply,
//   * writes checked against the register map and verified by reading back; MD_ID and
//     UART1_BAUD writes make the host follow the device; CTRL reset pauses polling,
//   * the node/baud scan.
// A request goes out only after the line was quiet for 3.5 characters (the RTU frame gap).
// Replies that fail their CRC are counted and dropped; the engine's timeout sends again.
#include "clock/clock_model.h"
#include "device/family_plugin.h"
#include "device/modbus_types.h"
#include "model/sample.h"

#include <QElapsedTimer>
#include <QList>
#include <QTimer>

#include <map>

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace imudesk::device {

class ModbusFamily : public FamilyPlugin {
    Q_OBJECT
public:
    static constexpr int kBaudSwitchDelayMs = 120; // after a baud write's reply, before the host follows
    static constexpr int kResetPauseMs = 300;      // after CTRL reset/factory, before polling again
    static constexpr int kTimeoutsBeforeLost = 5;  // consecutive poll timeouts -> Disconnected
    static constexpr int kLineIdleMs = 50;         // bytes of an unfinished reply dropped after this quiet

    // One transaction (Request::command).
    struct Op {
        bool write = false;
        int nodeId = 0;
        int start = 0;
        int count = 1;
        int value = 0;
        int timeoutMs = 300; // per attempt
    };
    // The typed answer (RequestResult::reply).
    struct Reply {
        QList<quint16> values;
        int exception = 0;
    };

    ModbusFamily();

    // Engine thread. Before the engine opens the link.
    void configure(const ModbusOptions &options);
    // Any thread: the scan stops before its next probe.
    void requestScanCancel() { m_scanCancel = true; }
    void setPollRate(double hz);
    void readRegisters(quint64 id, int start, int count);
    void writeRegister(quint64 id, int address, int value, bool verify);
    void scan(const ModbusScanOptions &options);

    QString linkKind() const override;
    int firstBaud(int requestedBaud) const override;
    void opened(int requestedBaud) override;
    void stopping() override;
    void restartStream() override { m_rx.clear(); }
    void resetCounters() override;
    void feed(const QByteArray &bytes, int64_t nowNs) override;
    bool midUnit() const override { return !m_rx.isEmpty(); }
    void lineIdle(int64_t nowNs) override;
    void fillCounters(SessionStats &s) const override;
    QString prepare(Request &r) override;
    int holdWriteMs(const Request &r) const override;
    void writing(const Request &r) override;
    void unanswered(const Request &r, RequestResult &result) override;

Q_SIGNALS:
    void registersRead(const imudesk::device::ModbusRegisterReply &reply);
    void writeFinished(const imudesk::device::ModbusRegisterReply &reply);
    void nodeIdChanged(int nodeId);
    void baudChanged(int baud);
    void pollRateChanged(double hz);
    void scanProgress(int done, int total);
    void scanFound(const imudesk::device::ModbusScanHit &hit);
    void scanFinished(const QList<imudesk::device::ModbusScanHit> &hits, bool cancelled);

private:
    using Done = std::function<void(const RequestResult &)>;
    Request makeRequest(const Op &op, int attempts, Done done) const;
    void parseReplies();
    QString failureText(const Op &op, const RequestResult &r) const;
    model::ManualEdition edition() const;
    int pollCount() const;
    int pollStart() const;
    int frameGapMs() const;
    void identify();
    void startPolling();
    void onPollTick();
    void onPollResult(const RequestResult &r);
    void followBaud(int baud);
    void scanNext();
    void noteLateAnswer(int nodeId);
    void finishScan(bool cancelled, bool linkStaysOpen);
    int probeTimeoutMs(int baud) const;

    ModbusOptions m_options;
    std::string m_frameType = "MODBUS"; // the samples' source, the counters' frame type
    int m_nodeId = 0;
    double m_requestedHz = 0;
    double m_pollHz = 0;
    model::DeviceIdentity m_identity;
    QElapsedTimer m_clock;       // since open: the samples' device time (the registers carry none)
    QElapsedTimer m_lastTraffic; // the last byte in or out (the RTU frame gap)

    QByteArray m_rx;   // bytes of the reply being received
    QByteArray m_echo; // the request on the line (an RS-485 adapter may hear it back)
    std::vector<model::Sample> m_batch;

    QTimer m_pollTimer{this};
    QTimer m_baudSwitch{this}; // runs between a baud write's reply and the host following
    QTimer m_resume{this};     // polling paused after CTRL reset
    int m_pendingBaud = 0;
    bool m_pollQueued = false;
    int m_consecutiveTimeouts = 0; // kTimeoutsBeforeLost or more: reported Disconnected

    uint64_t m_responses = 0, m_exceptions = 0, m_crcErrors = 0, m_polls = 0, m_pollTimeouts = 0;
    clock::BracketTally m_brackets; // the polls' request->answer intervals
    uint64_t m_bytesIn = 0, m_bytesSkipped = 0;

    bool m_scanning = false;
    std::atomic<bool> m_scanCancel{false};
    ModbusScanOptions m_scan;
    QList<ModbusScanOptions::Probe> m_scanPlan;
    qsizetype m_scanAt = 0;
    QList<ModbusScanOptions::Probe> m_scanRecheck; // ids whose answer came late: asked again, slowly
    QList<int> m_scanAsked;                         // ids probed at the current baud (a late answer's)
    int m_scanHitBaud = 0;                          // oneRate: the baud a device answered at
    int m_scanCurrentId = -1;
    std::map<int, int> m_scanDamaged;               // id -> damaged replies while it was probed
    int m_scanDone = 0;
    int m_scanTotal = 0;
    int m_scanRestoreBaud = 0;
    QList<ModbusScanHit> m_hits;
};

} // namespace imudesk::device

Q_DECLARE_METATYPE(imudesk::device::ModbusFamily::Reply)
