#pragma once
// HiPNUC modules on a serial port as a session-engine family (family_plugin.h): ASCII
// commands and their replies, binary HI91/HI92/HI81/HI83 frames and NMEA sentences on one
// stream (protocol::StreamDemux), the baud-rate detection, the safe baud change and the link
// recovery after a reset (hipnuc_family_baud.cpp), and the lost-frame counter, told by each
// command's typed output effect (protocol::hipnuc::OutputEffect) when a gap is the command's.
#include "clock/serial_frame_clocks.h"
#include "device/baud_scan.h"
#include "device/family_plugin.h"
#include "device/frame_gap_counter.h"
#include "model/sample.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/hipnuc/ascii_reply.h"
#include "decode/hipnuc_stream_decoder.h"

#include <QList>
#include <QTimer>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::device {

class HipnucSerialFamily : public FamilyPlugin, private decode::Sink {
    Q_OBJECT
public:
    // A module sends a frame without pauses, but a USB adapter's latency timer (16 ms on FTDI
    // parts) and a loaded host can split one in two deliveries tens of ms apart: only a pause
    // longer than this gives up an unfinished frame (30 ms lost frames under load).
    static constexpr int kLineIdleMs = 120;

    using Reply = protocol::hipnuc::AsciiReply;
    // Rates tried by auto-detection, in order.
    static const std::vector<int> &detectionBauds();
    static Request makeRequest(const protocol::hipnuc::Command &command, int timeoutMs,
                               std::function<void(const Reply &)> done = {});

    HipnucSerialFamily();

    // Engine thread.
    void setHostBaud(int baud);
    void changeBaud(int baud);
    void recoverLink(const QList<int> &bauds, int settleMs);

    QString linkKind() const override { return QStringLiteral("HiPNUC serial"); }
    bool reconnects() const override { return true; }
    int firstBaud(int requestedBaud) const override;
    void opened(int requestedBaud) override;
    void stopping() override;
    void reconnected() override;
    void restartStream() override;
    void resetCounters() override;
    void feed(const QByteArray &bytes, int64_t nowNs) override;
    bool midUnit() const override { return m_decoder.midUnit(); }
    void lineIdle(int64_t nowNs) override;
    void fillCounters(SessionStats &s) const override;
    void writing(const Request &r) override;
    void unanswered(const Request &r, RequestResult &result) override;
    void finished(const Request &r, const RequestResult &result) override;

Q_SIGNALS:
    void baudDetected(int baud);
    void identityQueryFinished(bool answered);
    void nmeaReceived(const QString &sentence);
    void textReceived(const QString &line);
    void baudChangeFinished(bool changed, int baud, const QString &detail);
    void linkRecovered(bool reachable, int baud, const QString &detail);

private:
    // What the family's decoder (decode/hipnuc_stream_decoder.h) gives: samples to the engine,
    // reply lines to the request on the line.
    void onSample(const model::Sample &sample, const decode::Record &record) override;
    void onText(decode::TextKind kind, const std::string &text, int64_t hostNs) override;
    void noteIdentity(const model::DeviceIdentity &id);
    void listenThenQueryIdentity();
    void queryIdentity(int attempt);
    // LOG COMCONFIG's COORD= (v1.7.1 4.6.7.10): the frame of the module's attitude, kept in the
    // identity. A COORD written since the last reset takes effect only after it, so a reply
    // read in between does not change the frame. A reply that names no COORD leaves ENU,
    // marked as assumed (DeviceIdentity::worldFrameAssumed).
    void queryWorldFrame(std::function<void()> then);
    void noteWorldFrame(const Reply &r);
    void noteWorldFrameAssumed(); // no reply: the frame kept is not confirmed by the module
    void noteCommandDone(const protocol::hipnuc::OutputEffect &effect);

    // Detection and recovery (hipnuc_family_baud.cpp)
    using LinkDone = std::function<void(bool reachable, int baud)>;
    BaudScan::Plan detectionPlan();
    void detectQuery(bool retry, BaudScan::Answer answer);
    // LOG VERSION at each rate in turn, then the whole detection; done(reachable, baud).
    void probeBauds(std::vector<int> bauds, LinkDone done);
    void probeVersion(int attempt, BaudScan::Answer answer);
    // A usable LOG VERSION answer: kept in m_found for the scan's found step.
    bool takeIdentity(const Reply &r);
    void finishLink(bool reachable, int baud);

    decode::HipnucStreamDecoder m_decoder; // the stream, its clocks and counters (also a replay's)
    std::vector<model::Sample> m_batch;
    std::optional<protocol::hipnuc::ReplyCollector> m_collector; // the request on the line
    FrameGapCounter m_gaps;
    std::map<std::string, size_t> m_frameBytes; // last frame size per type (link load of a rate)

    QTimer m_listenTimer{this}; // before the identity query on a given rate
    BaudScan m_scan{this};
    std::optional<model::DeviceIdentity> m_found; // by the scan's probe at the rate it tries
    uint64_t m_framesAtDetectStart = 0;
    LinkDone m_linkDone; // the baud change or recovery under way

    std::string m_deviceSerial; // from LOG VERSION: tells whether the same module came back
    bool m_checkSameDevice = false;
    bool m_coordChangePending = false; // CONFIG IMU COORD sent, the module not reset since
};

} // namespace imudesk::device
