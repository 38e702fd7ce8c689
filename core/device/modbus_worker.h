#pragma once
// The worker half of ModbusSession: owns the QModbusRtuSerialClient and runs in the
// session's thread. One request on the bus at a time (a queue in front of the client), so a
// poll never overtakes a write and a write's read-back follows it directly.
#include "device/modbus_types.h"
#include "device/sample_store.h"
#include "device/session_types.h"

#include <QElapsedTimer>
#include <QModbusDevice>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <atomic>
#include <deque>
#include <functional>

QT_BEGIN_NAMESPACE
class QModbusRtuSerialClient;
class QModbusReply;
QT_END_NAMESPACE

namespace imudesk::device {

class ModbusWorker : public QObject {
    Q_OBJECT
public:
    static constexpr int kBaudSwitchDelayMs = 120;  // after a baud write's reply, before the host follows
    static constexpr int kResetPauseMs = 300;       // after CTRL reset/factory, before polling again
    static constexpr int kTimeoutsBeforeLost = 5;   // consecutive poll timeouts -> Disconnected

    explicit ModbusWorker(SampleStore &store, QObject *parent = nullptr);
    ~ModbusWorker() override;

    // Set from any thread; the scan stops before its next probe.
    void requestScanCancel() { m_scanCancel = true; }

public Q_SLOTS:
    void open(const imudesk::device::ModbusOptions &options);
    void close();
    void setPollRate(double hz);
    void readRegisters(quint64 id, int start, int count);
    void writeRegister(quint64 id, int address, int value, bool verify);
    void scan(const imudesk::device::ModbusScanOptions &options);

Q_SIGNALS:
    void stateChanged(imudesk::device::SessionState state, const QString &detail);
    void identityChanged(const imudesk::model::DeviceIdentity &identity);
    void statsUpdated(const imudesk::device::SessionStats &stats);
    void errorOccurred(const QString &message);
    void registersRead(const imudesk::device::ModbusRegisterReply &reply);
    void writeFinished(const imudesk::device::ModbusRegisterReply &reply);
    void nodeIdChanged(int nodeId);
    void baudChanged(int baud);
    void pollRateChanged(double hz);
    void scanProgress(int done, int total);
    void scanFound(const imudesk::device::ModbusScanHit &hit);
    void scanFinished(const QList<imudesk::device::ModbusScanHit> &hits, bool cancelled);

private:
    struct Result {
        QModbusDevice::Error error = QModbusDevice::NoError;
        int exception = 0;
        QList<quint16> values;
        QString errorText;
        bool ok() const { return error == QModbusDevice::NoError; }
    };
    struct Op {
        bool write = false;
        int nodeId = 0;
        int start = 0;
        int count = 1;
        int value = 0;
        int timeoutMs = 300;
        bool poll = false;
        std::function<void(const Result &)> done;
    };

    void setState(SessionState s, const QString &detail = QString());
    bool connectClient(int baud, QString *error);
    void enqueue(Op op);
    void startNext();
    void onReplyFinished();
    void finishCurrent(const Result &r);
    void identify();
    void startPolling();
    void onPollTick();
    void onPollResult(const Result &r);
    void publishStats();
    QString failureText(const Op &op, const Result &r) const;
    model::ManualEdition edition() const;
    int pollCount() const;

    // scan
    void scanNext();
    void finishScan(bool cancelled);
    int probeTimeoutMs(int baud) const;
    static QString describeHitException(int code);

    SampleStore &m_store;
    QModbusRtuSerialClient *m_client = nullptr;
    ModbusOptions m_options;
    int m_nodeId = 0;
    int m_baud = 0;
    double m_requestedHz = 0;
    double m_pollHz = 0;
    model::DeviceIdentity m_identity;
    bool m_open = false;

    std::deque<Op> m_queue;
    bool m_busy = false;
    Op m_current;
    QPointer<QModbusReply> m_reply;
    quint64 m_generation = 0; // bumped at close: late callbacks of an older link are ignored

    QTimer m_pollTimer;
    QTimer m_statsTimer;
    QElapsedTimer m_clock;
    bool m_pollQueued = false;
    int m_consecutiveTimeouts = 0;
    bool m_lost = false;

    // counters
    uint64_t m_responses = 0, m_exceptions = 0, m_timeouts = 0, m_crcErrors = 0, m_polls = 0, m_pollTimeouts = 0;
    uint64_t m_bytesIn = 0, m_bytesOut = 0;
    uint64_t m_lastPolls = 0, m_lastBytes = 0;
    qint64 m_lastStatsMs = 0;
    double m_pollRateMeasured = 0, m_bytesPerSecond = 0;

    // scan state
    bool m_scanning = false;
    std::atomic<bool> m_scanCancel{false};
    ModbusScanOptions m_scan;
    QList<int> m_scanBauds;
    int m_scanBaudIndex = 0;
    int m_scanId = 0;
    int m_scanDone = 0;
    int m_scanTotal = 0;
    int m_scanRestoreBaud = 0;
    QList<ModbusScanHit> m_hits;
};

} // namespace imudesk::device
